// Span solver (design §3.2 step 3): per scanline of a primitive's screen box, the span(s)
// where the contour conic Δ(u, v) >= 0 — at most two, a hyperbola's row can have two
// pieces — widened by one pixel against the quantisation of Δ; the pixel pipelines then
// decide coverage exactly from the interpolated Δ. Caps of solids (a <= 0) and facets can
// show where Δ < 0: their rows are whole (PrimitiveSetup::fullRows).
#pragma once
#include "hw_model/datapath/primitive_setup.h"

namespace qacc {

struct Span {
  int x0 = 0, x1 = 0;  // [x0, x1) in screen pixels
};

// Spans of row y (screen) restricted to [xlo, xhi); returns their number (0..2).
int solveSpans(const PrimitiveSetup& s, int y, int xlo, int xhi, Span out[2]);

}  // namespace qacc
