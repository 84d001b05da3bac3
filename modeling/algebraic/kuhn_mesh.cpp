#include "modeling/algebraic/kuhn_mesh.h"

#include <stdexcept>

namespace qacc {

double TetMesh::volume(std::size_t t) const {
  const auto& v = tets[t];
  const Eigen::Vector3d& a = vertices[std::size_t(v[0])];
  return (vertices[std::size_t(v[1])] - a).dot((vertices[std::size_t(v[2])] - a).cross(vertices[std::size_t(v[3])] - a)) / 6.0;
}

namespace {

double gridCoordinate(double a, double b, int i, int n) { return i == n ? b : a + (b - a) * i / n; }

}  // namespace

Eigen::Vector3d kuhnGridPoint(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& n, int i, int j, int k) {
  return Eigen::Vector3d(gridCoordinate(box.min().x(), box.max().x(), i, n.x()),
                         gridCoordinate(box.min().y(), box.max().y(), j, n.y()),
                         gridCoordinate(box.min().z(), box.max().z(), k, n.z()));
}

KuhnCubeTets kuhnCubeTets(int i, int j, int k) {
  // The 6 permutations of the axes: each is one monotone path min corner → max corner.
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  KuhnCubeTets out;
  for (std::size_t t = 0; t < 6; ++t) {
    Eigen::Vector3i c(i, j, k);
    out[t][0] = c;
    for (std::size_t s = 0; s < 3; ++s) {
      ++c[perms[t][s]];
      out[t][s + 1] = c;
    }
  }
  return out;
}

TetMesh kuhnMesh(const Eigen::AlignedBox3d& box, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("kuhnMesh: at least one cube per axis");
  if (box.isEmpty() || !(box.sizes().array() > 0.0).all()) throw std::invalid_argument("kuhnMesh: empty box");
  TetMesh m;
  m.nx = nx;
  m.ny = ny;
  m.nz = nz;
  const Eigen::Vector3i n(nx, ny, nz);
  m.vertices.reserve(std::size_t((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.vertices.push_back(kuhnGridPoint(box, n, i, j, k));
  m.tets.reserve(std::size_t(6 * nx * ny * nz));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int cube = (k * ny + j) * nx + i;
        for (const auto& tet : kuhnCubeTets(i, j, k)) {
          std::array<int, 4> t;
          for (std::size_t s = 0; s < 4; ++s) t[s] = m.gridVertex(tet[s].x(), tet[s].y(), tet[s].z());
          m.tets.push_back(t);
          m.cube.push_back(cube);
        }
      }
  return m;
}

std::array<std::array<Eigen::Vector3d, 4>, 8> refineBey(const std::array<Eigen::Vector3d, 4>& x) {
  auto mid = [&](int i, int j) { return Eigen::Vector3d(0.5 * (x[std::size_t(i)] + x[std::size_t(j)])); };
  const Eigen::Vector3d x01 = mid(0, 1), x02 = mid(0, 2), x03 = mid(0, 3), x12 = mid(1, 2), x13 = mid(1, 3),
                        x23 = mid(2, 3);
  return {{{x[0], x01, x02, x03},
           {x01, x[1], x12, x13},
           {x02, x12, x[2], x23},
           {x03, x13, x23, x[3]},
           {x01, x02, x03, x13},
           {x01, x02, x12, x13},
           {x02, x03, x13, x23},
           {x02, x12, x13, x23}}};
}

}  // namespace qacc
