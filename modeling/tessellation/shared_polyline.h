// The one polyline of a shared boundary (shared_boundaries.h): where two pieces of one object
// meet on their common clip plane h (one piece has h, the other exactly h.opposite()), the
// curve {q = 0} ∩ h restricted to both pieces' faces (their other clip planes) is sampled
// once, so that both pieces' meshes end on the same vertices, bit for bit.
//  - The ends are where the curve leaves the common face: on each line where h meets another
//    clip plane of either piece, the roots of q along that line that lie inside every other
//    plane of both pieces (within rounding) and where the curve crosses a plane of the face
//    rather than touching it (a G1 cell's surface is tangent to faces of its tetrahedron).
//    One end or none, or two planes among the face's that cut h along one line from
//    opposite sides (opposite planes, or two planes through one line of h: pieces that meet
//    along that line only): the faces share no arc. More than two (a conic can cross a
//    face four times): each end not yet in an arc is traced into the face (below) to the
//    end it reaches (the way in probed at 1e-3 of the ends' span, or a quarter of the way to
//    the nearest other end not yet in an arc when that is nearer, not below 1e-6 of its
//    distance from the origin, at least a unit: above the face test's slack); an end with no
//    way into the face (the curve only passes through a corner of it) is in no arc.
//  - Between two ends the curve is sampled by halving: the midpoint of a chord is moved onto
//    the curve within h (Newton steps along the gradient's component in the plane) and the
//    chord split there while its sagitta exceeds the tolerance (world units, or pixels in a
//    view), up to kMaxSharedPolylineDepth halvings. Where a midpoint does not reach the curve
//    inside the face (an arc that turns back, more than half an ellipse), the curve is traced
//    instead: from a, the way that enters the face, steps along the tangent as long as the
//    curvature allows within the tolerance, each moved back onto the curve, until b is
//    within a step.
// The arithmetic runs once per pair of pieces, on the quadric and plane of the pair's
// canonical piece (the caller's choice), so the result is the same whichever piece asks.
#pragma once
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "modeling/geometry/half_space.h"
#include "modeling/geometry/quadric.h"
#include "modeling/scene/screen_view.h"

namespace qacc::tess {

constexpr int kMaxSharedPolylineDepth = 10;

// The arcs of the curve {q = 0} ∩ h within `face` (the other clip planes of both pieces), as
// their ends, two per arc: none when the curve misses the common face or touches it at one
// point.
std::vector<Eigen::Vector3d> sharedCurveEnds(const Quadric& q, const HalfSpace& h,
                                             const std::vector<HalfSpace>& face);

// How finely: sagitta at most `world` (world units), and with a view at most `pixels` in it.
struct PolylineTolerance {
  double world = 0;
  const ScreenView* view = nullptr;
  double pixels = 0;
  int samples = 6;  // a triangle's error is measured at this barycentric grid (measureChordError)
};

// The curve from `a` to `b` (both on it, ends of one arc) sampled to the tolerance, a and b
// included as given; std::nullopt when neither halving nor tracing stays on the curve in
// `face`.
std::optional<std::vector<Eigen::Vector3d>> sampleSharedCurve(const Quadric& q, const HalfSpace& h,
                                                              const std::vector<HalfSpace>& face,
                                                              const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                              const PolylineTolerance& tol);

}  // namespace qacc::tess
