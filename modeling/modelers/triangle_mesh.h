// Triangle meshes: inline vertex/index lists or Wavefront OBJ files, turned into facet
// primitives (planes clipped by their 3 edge half-spaces, makeTriangle).
// OBJ support: "v x y z [w]" and "f" lines with 3 or more corners (polygons are fan-
// triangulated), corner forms i, i/t, i//n, i/t/n, negative (relative) indices; other
// statements (vt, vn, o, g, s, usemtl, mtllib, l, p...) are ignored; "#" starts a comment.
#pragma once
#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "modeling/loader/object_registry.h"
#include "modeling/loader/view_cull_count.h"

namespace qacc {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // 0-based vertex indices
};

// Reads an OBJ file. Throws std::runtime_error "PATH:LINE: problem" on bad content and
// "PATH: problem" when the file cannot be read.
TriangleMesh readObj(const std::string& path, std::size_t max_bytes = Limits{}.max_input_bytes);
// Parses OBJ text; `name` is used in messages.
TriangleMesh parseObj(const std::string& text, const std::string& name);

// One facet primitive per non-degenerate triangle (zero-area triangles draw nothing and
// are skipped; `skipped`, if given, receives their number). With a `view` (view culling,
// ObjectContext::view), a triangle whose three corners lie outside one of its planes is not
// built (counted in `count`).
std::vector<Primitive> meshPrimitives(const TriangleMesh& mesh, std::size_t* skipped = nullptr,
                                      const ViewVolume* view = nullptr, ViewCullCount* count = nullptr);

// Scene builder for "triangle_mesh": {"vertices": [[x,y,z]...], "triangles": [[i,j,k]...]}
// or {"file": "mesh.obj"}.
std::vector<Primitive> buildTriangleMesh(const JsonNode& o, ObjectContext& ctx);

}  // namespace qacc
