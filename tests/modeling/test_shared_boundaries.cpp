// Crack-free shared boundaries (shared_boundaries.h): on the shipped scenes made of pieces
// that share clip planes — macropatches, B-spline cells, degree-reduction pieces — the
// tessellation uses the same vertices on both sides of every shared plane, so every edge
// on a shared plane is used by exactly two triangles (the mesh's only open edges are on
// planes no other piece of the object shares), no edge by more than two, to a pixel error
// and at a fixed triangle count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/tessellation.h"
#include "tests/sanitized_build.h"

using namespace qacc;
using Eigen::Vector3d;

namespace {

Scene loadShipped(const std::string& name) {
  Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + name);
  // Degree-reduction objects draw their exact surface as facets: take their pieces instead.
  for (auto& o : s.objects) o.exact_surface = -1;
  s.exact_surfaces.clear();
  return s;
}

bool onPlane(const HalfSpace& h, const Vector3d& x) {
  return std::abs(h.eval(x)) <= 1e-9 * (h.p.head<3>().norm() * x.norm() + std::abs(h.p[3]));
}

// Per primitive, its clip planes whose exact opposite is a clip plane of another piece of
// the same object.
std::vector<std::vector<int>> sharedPlanes(const Scene& s) {
  std::map<std::pair<int, std::array<double, 4>>, std::set<std::size_t>> owners;
  for (std::size_t i = 0; i < s.primitives.size(); ++i)
    for (const auto& h : s.primitives[i].clip)
      owners[{s.primitives[i].object, {h.p[0], h.p[1], h.p[2], h.p[3]}}].insert(i);
  std::vector<std::vector<int>> out(s.primitives.size());
  for (std::size_t i = 0; i < s.primitives.size(); ++i)
    for (std::size_t k = 0; k < s.primitives[i].clip.size(); ++k) {
      const Eigen::Vector4d q = -s.primitives[i].clip[k].p;
      auto it = owners.find({s.primitives[i].object, {q[0], q[1], q[2], q[3]}});
      if (it != owners.end() && !(it->second.size() == 1 && *it->second.begin() == i)) out[i].push_back(int(k));
    }
  return out;
}

struct Cracks {
  std::size_t open_on_shared = 0, open = 0, overused = 0, degenerate = 0, shared_planes = 0;
  std::size_t interior_open = 0;  // open edges on none of their piece's unshared clip planes
};

Cracks cracks(const Scene& s, const TriangleMesh3& mesh) {
  const auto shared = sharedPlanes(s);
  Cracks c;
  for (const auto& v : shared) c.shared_planes += v.size();
  const EdgeUse use = edgeUse(mesh);
  c.open = use.open.size();
  c.overused = use.overused;
  c.degenerate = use.degenerate;
  for (const OpenEdge& e : use.open) {
    const std::size_t i = std::size_t(mesh.primitive[e.triangle]);
    const auto& clip = s.primitives[i].clip;
    bool onShared = false, onOuter = false;
    for (std::size_t k = 0; k < clip.size(); ++k) {
      if (!onPlane(clip[k], e.a) || !onPlane(clip[k], e.b)) continue;
      const bool isShared = std::find(shared[i].begin(), shared[i].end(), int(k)) != shared[i].end();
      onShared = onShared || isShared;
      onOuter = onOuter || !isShared;
    }
    c.open_on_shared += onShared;
    c.interior_open += !onOuter;
  }
  return c;
}

struct SceneCase {
  const char* file;
  bool shares;  // has pieces on both sides of a clip plane (macropatch_bezier's cells do not)
  bool closed;  // a closed surface: no open edge at all
  bool heavy;   // a minute or more under the sanitizers: left to the Release suite
  // Closed at a fixed count (64 triangles a piece) too; when not, that count is printed only.
  bool fixed_count_closed = true;
};

// GoogleTest (and ctest's test list) name a case by its file, not by its bytes.
void PrintTo(const SceneCase& c, std::ostream* os) { *os << c.file; }

std::string caseName(const ::testing::TestParamInfo<SceneCase>& info) {
  std::string n = info.param.file;
  return n.substr(0, n.find('.'));
}

class SharedBoundaryScene : public ::testing::TestWithParam<SceneCase> {};

}  // namespace

// One tessellation per tolerance (2 and 0.5 px) for every check: every edge on a shared plane
// is used by exactly two triangles; every interior edge (all but those of the object's outer
// boundary, on clip planes no other piece shares) too; no edge by more, no degenerate
// triangle; a closed surface has no open edge at all; and the pixel error, measured on the
// final triangles (the rebuilt strips included), is within the tolerance. At a fixed count
// (64 triangles per piece) the shared planes are closed as well.
TEST_P(SharedBoundaryScene, EveryInteriorEdgeIsUsedTwiceWithinTheTolerance) {
  const SceneCase& sc = GetParam();
  if (kSanitizedBuild && sc.heavy) GTEST_SKIP() << sc.file << ": left to the Release suite (tests/sanitized_build.h)";
  const Scene s = loadShipped(sc.file);
  // Under the sanitizers the coarser tolerance only: the same strips, refinement and rebuilds,
  // on fewer triangles (tests/sanitized_build.h).
  const std::vector<double> tolerances = kSanitizedBuild ? std::vector<double>{2.0} : std::vector<double>{2.0, 0.5};
  for (double eps : tolerances) {
    TessellationOptions o;
    o.pixel_error = eps;
    TessellationReport rep;
    const TriangleMesh3 mesh = tessellateScene(s, o, &rep);
    const Cracks c = cracks(s, mesh);
    std::printf("%s eps %g: %zu triangles, max pixel error %.3f, %zu open edges\n", sc.file, eps, mesh.size(),
                rep.max_pixel_error, c.open);
    EXPECT_LE(rep.max_pixel_error, eps) << "eps " << eps << ", " << mesh.size() << " triangles";
    if (sc.shares) {
      EXPECT_GT(c.shared_planes, 0u);
    } else {
      EXPECT_EQ(c.shared_planes, 0u);
    }
    EXPECT_EQ(c.open_on_shared, 0u) << "eps " << eps << ": " << c.open << " open edges, " << mesh.size() << " triangles";
    EXPECT_EQ(c.interior_open, 0u) << "eps " << eps << ": " << c.open << " open edges";
    EXPECT_EQ(c.overused, 0u) << "eps " << eps;
    EXPECT_EQ(c.degenerate, 0u) << "eps " << eps;
    if (sc.closed) { EXPECT_TRUE(isWatertight(mesh)) << "eps " << eps << ": " << c.open << " open edges"; }
  }
  TessellationOptions o;
  o.triangles = 64;
  const TriangleMesh3 mesh = tessellateScene(s, o);
  const Cracks c = cracks(s, mesh);
  std::printf("%s level 64: %zu triangles, %zu open edges on shared planes, %zu used more than twice\n", sc.file,
              mesh.size(), c.open_on_shared, c.overused);
  if (!sc.fixed_count_closed) return;
  EXPECT_EQ(c.open_on_shared, 0u) << "level 64: " << c.open << " open edges";
  EXPECT_EQ(c.overused, 0u) << "level 64";
}

INSTANTIATE_TEST_SUITE_P(SharedBoundaries, SharedBoundaryScene,
                         ::testing::Values(SceneCase{"macropatch_g0.json", true, true, false},
                                           SceneCase{"macropatch_g1.json", true, true, true},
                                           SceneCase{"macropatch_bezier.json", false, false, false},
                                           SceneCase{"bspline_g0.json", true, false, false},
                                           SceneCase{"bspline_g1.json", true, false, true},
                                           SceneCase{"bspline_volume_g0.json", true, true, false},
                                           SceneCase{"quartic.json", true, true, true},
                                           SceneCase{"torus.json", true, true, true}),
                         caseName);

// bspline_volume_g1 (41 839 pieces; 75 s a tolerance in Release, so out of the suite: run it
// with --gtest_also_run_disabled_tests). Watertight at 2 and 0.5 px; not yet at a fixed count
// (17 open edges at a corner of pieces 1e-5 across: docs/COMPARE.md "Shared boundaries").
INSTANTIATE_TEST_SUITE_P(DISABLED_Volume, SharedBoundaryScene,
                         ::testing::Values(SceneCase{"bspline_volume_g1.json", true, true, true, false}), caseName);
