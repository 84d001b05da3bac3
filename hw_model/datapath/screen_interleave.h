// Screen interleaving: pixel (x, y) belongs to unit (x + y) mod n of n — the pixel pipeline
// that draws it (timing/traversal_unit.h) and the Z-buffer bank that holds it
// (zbuffer_memory.h), so that neighbours along a row or a column go to different units.
#pragma once

namespace qacc {

// x, y >= 0 (screen pixels), n >= 1. For a power-of-two n the mask gives the same unit as the
// modulo without the host's divide (one per issued pixel and per Z request otherwise).
inline int interleavedUnit(int x, int y, int n) { return (n & (n - 1)) == 0 ? (x + y) & (n - 1) : (x + y) % n; }

}  // namespace qacc
