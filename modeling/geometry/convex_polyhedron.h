// Convex polyhedra cut by planes: the cells of simplex B-spline volumes (simplex_spline3.h).
//
// A polyhedron is its vertices, each with the (sorted) ids of the planes through it, and its
// faces (plane id + which side is kept). Planes live in a table owned by the caller (unit
// normals, so that values are distances). Two vertices are joined by an edge exactly when
// they share two planes, so cutting by a plane needs only the vertices: those strictly on a
// side go to that side, those within eps of the plane to both (the plane added to their
// list), and every edge between a strictly negative and a strictly positive vertex gives a
// new vertex on the plane. A face whose plane keeps fewer than three vertices is dropped,
// so the face list holds no redundant half-space. Cost: O(vertices²) per cut, independent
// of how many planes cut before.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace qacc {

class ConvexPolyhedron {
 public:
  struct Vertex {
    Eigen::Vector3d x;
    std::vector<int> planes;  // ids of the planes through x, sorted
  };
  struct Face {
    int plane;
    bool flip;  // kept side: p·x <= 0 (flip = false) or p·x >= 0 (flip = true)
  };

  ConvexPolyhedron() = default;
  // The tetrahedron x0..x3; plane[a] is the face opposite x[a], flip[a] says which side is kept.
  static ConvexPolyhedron tetrahedron(const std::array<Eigen::Vector3d, 4>& x, const std::array<int, 4>& plane,
                                      const std::array<bool, 4>& flip);

  bool empty() const { return verts_.empty(); }
  const std::vector<Vertex>& vertices() const { return verts_; }
  const std::vector<Face>& faces() const { return faces_; }
  Eigen::AlignedBox3d box() const;
  Eigen::Vector3d centroid() const;  // of the vertices: an interior point

  // Which sides of the plane (unit normal) hold vertices farther than eps from it.
  void sides(const Eigen::Vector4d& unit, double eps, bool& neg, bool& pos) const;
  // Cuts by plane `id` (table `unit`): `neg` keeps p·x <= 0, `pos` p·x >= 0. False (and the
  // outputs untouched) unless vertices lie farther than eps on both sides.
  bool split(int id, const std::vector<Eigen::Vector4d>& unit, double eps, ConvexPolyhedron& neg,
             ConvexPolyhedron& pos) const;
  // The part on the kept side of plane `id` (flip as in Face); empty if none beyond eps.
  ConvexPolyhedron clipped(int id, bool flip, const std::vector<Eigen::Vector4d>& unit, double eps) const;
  // Does the triangle (a, b, c) cross the interior (by more than eps)?
  bool crossedBy(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 const std::vector<Eigen::Vector4d>& unit, double eps) const;
  // Tetrahedra covering the polyhedron: its centroid joined to a fan of every face.
  std::vector<std::array<Eigen::Vector3d, 4>> fan(const std::vector<Eigen::Vector4d>& unit) const;

 private:
  std::vector<Vertex> verts_;
  std::vector<Face> faces_;
  void keepFaces(const std::vector<Face>& candidates);
};

}  // namespace qacc
