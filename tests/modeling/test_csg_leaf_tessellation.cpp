// The tessellation of csg leaves (docs/CSG.md, "Triangles"): OpenCSG counts, per pixel, the
// faces of each leaf in front of a surface (Goldfeather's parity), so every solid leaf of a
// csg object must tessellate to a closed mesh — its surface and a cap on every plane that
// bounds it: its own clip planes, a planar leaf's (a slab, a half-space) as well as a curved
// one's, and, for a leaf the view frustum bounds (a half-space, a paraboloid), the frustum's.
// Checked on every leaf of the shipped csg scenes: every edge used by exactly two triangles.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "modeling/loader/scene_loader.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/tessellation/tessellation.h"

using namespace qacc;

namespace {

// An open edge that only closes a rounding sliver: one of its ends lies within a rounding
// distance of a different end of another open edge (two copies of one point computed from
// two edges, where a surface passes exactly through an edge of its clip box); no pixel
// centre can fall in such a crack.
bool roundingSliver(const OpenEdge& e, const std::vector<OpenEdge>& open) {
  for (const Eigen::Vector3d& p : {e.a, e.b})
    for (const OpenEdge& o : open)
      for (const Eigen::Vector3d& q : {o.a, o.b})
        if (p != q && (p - q).norm() <= 1e-12 * (1 + p.norm())) return true;
  return false;
}

// Every csg leaf of the scene, its triangles in the scene's tessellation at `options`:
// closed (every edge used by two triangles), or, with `slivers`, open only along rounding
// slivers.
void expectClosedLeaves(const std::string& name, const TessellationOptions& options, bool slivers = false) {
  const Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/csg/" + name);
  ASSERT_FALSE(s.csg_trees.empty()) << name;
  const TriangleMesh3 all = tessellateScene(s, options);
  for (const CsgTree& tree : s.csg_trees)
    for (int leaf : tree.leafPrimitives()) {
      TriangleMesh3 m;
      m.positions = all.positions;
      for (std::size_t t = 0; t < all.triangles.size(); ++t)
        if (all.primitive[t] == leaf) m.triangles.push_back(all.triangles[t]);
      const EdgeUse use = edgeUse(m);
      const Primitive& p = s.primitives[std::size_t(leaf)];
      const std::string what = name + " leaf " + std::to_string(leaf) + " (" + quadricTypeName(quadricType(p.quadric)) +
                               ", " + std::to_string(p.clip.size()) + " clip planes, " +
                               std::to_string(m.triangles.size()) + " triangles)";
      EXPECT_GT(m.triangles.size(), 0u) << what;
      std::size_t open = 0;
      for (const OpenEdge& e : use.open) open += !(slivers && roundingSliver(e, use.open));
      EXPECT_EQ(open, 0u) << what << ": " << use.open.size() << " open edges";
      EXPECT_EQ(use.overused, 0u) << what;
      EXPECT_EQ(use.degenerate, 0u) << what;
    }
}

}  // namespace

TEST(CsgLeafTessellation, EveryLeafOfTheShippedScenesIsClosedAtATriangleBudget) {
  TessellationOptions o;
  o.triangles = 128;
  for (const char* name : {"csg_mechanical.json", "csg_quadrics.json"}) expectClosedLeaves(name, o);
}

TEST(CsgLeafTessellation, EveryLeafOfTheShippedScenesIsClosedToAPixelError) {
  TessellationOptions o;
  o.pixel_error = 1;
  // csg_quadrics' saddle passes exactly through an edge of its clip box, where two copies of
  // the corner differ by 4e-18: a sliver no pixel centre falls in.
  for (const char* name : {"csg_mechanical.json", "csg_quadrics.json"}) expectClosedLeaves(name, o, true);
}
