#include "modeling/splines/bspline_object.h"

#include <chrono>
#include <cstdio>
#include <map>

#include "modeling/algebraic/kuhn_mesh.h"
#include "modeling/algebraic/polynomial3.h"
#include "modeling/splines/simplex_spline2.h"
#include "modeling/splines/simplex_spline3.h"

namespace qacc {

namespace {

template <int D>
using Point = Eigen::Matrix<double, D, 1>;

template <int D>
Point<D> point(const JsonNode& n) {
  const auto v = n.numbers(D);
  Point<D> p;
  for (int a = 0; a < D; ++a) p[a] = v[std::size_t(a)];
  return p;
}

template <int D>
struct Mesh {
  std::vector<Point<D>> vertices;
  std::vector<std::array<int, D + 1>> simplices;
};

// "grid" (triangulated squares, or the Kuhn tetrahedralisation of a box) or explicit
// "vertices" + "triangles" / "tetrahedra".
template <int D>
Mesh<D> readMesh(const JsonNode& o) {
  const char* listKey = D == 2 ? "triangles" : "tetrahedra";
  const char* otherKey = D == 2 ? "tetrahedra" : "triangles";
  if (o.has(otherKey)) o.at(otherKey).fail(std::string(otherKey) + " are for dimension " + (D == 2 ? "3" : "2"));
  Mesh<D> m;
  if (auto g = o.get("grid")) {
    if (o.has("vertices") || o.has(listKey)) o.fail(std::string("give either grid or vertices + ") + listKey);
    const Point<D> lo = point<D>(g->at("min")), hi = point<D>(g->at("max"));
    // n cells per axis; volumes also take [nx, ny, nz].
    const JsonNode nn = g->at("n");
    std::array<int, D> n;
    if (D == 3 && nn.isArray()) {
      if (nn.size() != 3) nn.fail("n is a count or [nx, ny, nz]");
      for (std::size_t a = 0; a < 3; ++a) n[a] = int(nn[a].integer(1, 32));
    } else {
      n.fill(int(nn.integer(1, D == 2 ? 64 : 32)));
    }
    g->finish();
    if (!(lo.array() < hi.array()).all()) g->fail("grid min must be below max");
    if constexpr (D == 2) {
      const int k = n[0];
      for (int j = 0; j <= k; ++j)
        for (int i = 0; i <= k; ++i)
          m.vertices.emplace_back(lo.x() + (hi.x() - lo.x()) * i / k, lo.y() + (hi.y() - lo.y()) * j / k);
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          const int a = j * (k + 1) + i, b = a + 1, c = a + k + 1, d = c + 1;
          m.simplices.push_back({a, b, d});
          m.simplices.push_back({a, d, c});
        }
    } else {
      const TetMesh k = kuhnMesh(Eigen::AlignedBox3d(lo, hi), n[0], n[1], n[2]);
      m.vertices = k.vertices;
      m.simplices = k.tets;
    }
    return m;
  }
  const JsonNode vn = o.at("vertices");
  for (const auto& e : vn.elements()) m.vertices.push_back(point<D>(e));
  const JsonNode sn = o.at(listKey);
  for (const auto& e : sn.elements()) {
    if (!e.isArray() || e.size() != D + 1)
      e.fail(std::string(D == 2 ? "a triangle is 3" : "a tetrahedron is 4") + " vertex indices");
    std::array<int, D + 1> s;
    for (std::size_t k = 0; k <= D; ++k) s[k] = int(e[k].integer(0, (long long)m.vertices.size() - 1));
    m.simplices.push_back(s);
  }
  if (m.simplices.empty()) sn.fail(std::string("at least one ") + (D == 2 ? "triangle" : "tetrahedron"));
  return m;
}

// Explicit "knots" or the clouds of "continuity" / "knot_radius".
template <int D>
std::vector<std::vector<Point<D>>> readKnots(const JsonNode& o, const Mesh<D>& m, int degree, bool g1) {
  const double radius = o.positive("knot_radius", 0.2);
  if (auto k = o.get("knots")) {
    if (k->size() != m.vertices.size()) k->fail("one knot cloud per vertex");
    std::vector<std::vector<Point<D>>> knots;
    for (const auto& cloud : k->elements()) {
      if (cloud.size() != std::size_t(degree)) cloud.fail("a knot cloud has `degree` points");
      std::vector<Point<D>> c;
      for (const auto& p : cloud.elements()) c.push_back(point<D>(p));
      knots.push_back(c);
    }
    return knots;
  }
  return simplexKnotClouds<D>(m.vertices, m.simplices, degree, g1, radius);
}

std::map<std::string, double> readParams(const JsonNode& o) {
  std::map<std::string, double> params;
  if (auto p = o.get("params")) {
    if (!p->isObject()) p->fail("params must be an object of named numbers");
    for (auto it = p->json().begin(); it != p->json().end(); ++it) params[it.key()] = p->at(it.key()).number();
  }
  return params;
}

// The height (x, y) or field (x, y, z) polynomial, named constants from "params".
Polynomial3 readFunction(const JsonNode& f, const std::map<std::string, double>& params, int dimension) {
  Polynomial3 poly;
  try {
    poly = Polynomial3::parse(f.string(), params);
  } catch (const PolynomialParseError& e) {
    f.fail(e.what());
  }
  if (dimension == 2)
    for (const auto& t : poly.terms())
      if (t.k != 0) f.fail("the height is a function of x and y only");
  return poly;
}

template <int D>
Eigen::AlignedBox<double, D> readDomain(const JsonNode& d) {
  if (!d.isArray() || d.size() != 2)
    d.fail(D == 2 ? "domain must be [[xmin, ymin], [xmax, ymax]]" : "domain must be [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
  const Point<D> lo = point<D>(d[0]), hi = point<D>(d[1]);
  if (!(lo.array() < hi.array()).all()) d.fail("domain min must be below max");
  return Eigen::AlignedBox<double, D>(lo, hi);
}

template <int D>
using Spline = std::conditional_t<D == 2, SimplexSpline2, SimplexSpline3>;

// The compiled basis is priced before it is compiled (SimplexSplineBase::basisLeafBound):
// over --max-cells, the mesh is refused.
template <int D>
void checkBasisPrice(const JsonNode& o, std::size_t simplices, int degree, const Limits& limits) {
  const std::size_t leaves = Spline<D>::basisLeafBound(simplices, degree);
  if (leaves <= limits.max_cells) return;
  const std::size_t functions = Spline<D>::multiIndices(degree).size();
  std::size_t perFunction = 1;
  for (int level = 0; level < degree; ++level) perFunction *= D + 1;
  const std::string what = std::string("the B-spline basis (") + std::to_string(simplices) +
                           (D == 2 ? " triangles" : " tetrahedra") + " x " + std::to_string(functions) +
                           " basis functions x " + std::to_string(perFunction) + " recursion leaves)";
  o.get("grid").value_or(o.get(D == 2 ? "triangles" : "tetrahedra").value_or(o))
      .fail(Limits::exceeded(what, leaves, "leaves", limits.max_cells, "max-cells"));
}

template <int D>
Spline<D> readSpline(const JsonNode& o, const Limits& limits) {
  // The cells become quadrics: a spline of higher degree has no exact quadric per cell.
  const int degree = o.get("degree") ? int(o.at("degree").integer(1, 2)) : 2;
  const Mesh<D> mesh = readMesh<D>(o);
  checkBasisPrice<D>(o, mesh.simplices.size(), degree, limits);
  const std::string continuity = o.string("continuity", "G1");
  if (continuity != "G0" && continuity != "G1") o.at("continuity").fail("continuity must be \"G0\" or \"G1\"");
  Spline<D> spline(degree, mesh.vertices, mesh.simplices, readKnots<D>(o, mesh, degree, continuity == "G1"));

  const auto params = readParams(o);
  const char* functionKey = D == 2 ? "height" : "field";
  const char* otherKey = D == 2 ? "field" : "height";
  if (o.has(otherKey)) o.at(otherKey).fail(std::string(otherKey) + " is for dimension " + (D == 2 ? "3" : "2"));
  if (auto f = o.get(functionKey)) {
    if (o.has("coefficients")) o.fail(std::string("give either ") + functionKey + " or coefficients");
    const Polynomial3 h = readFunction(*f, params, D);
    const std::string sampling = o.string("sampling", "greville");
    if (sampling == "greville") {
      spline.setCoefficients(spline.grevilleCoefficients(h));
    } else if (sampling == "taylor") {
      spline.setCoefficients(spline.taylorCoefficients(h));
    } else {
      o.at("sampling").fail("sampling must be \"greville\" or \"taylor\"");
    }
  } else {
    if (o.has("sampling")) o.at("sampling").fail(std::string("sampling applies to ") + functionKey);
    const JsonNode cn = o.at("coefficients");
    if (cn.size() != mesh.simplices.size()) cn.fail(D == 2 ? "one coefficient list per triangle" : "one coefficient list per tetrahedron");
    const std::size_t m = Spline<D>::multiIndices(degree).size();
    std::vector<std::vector<double>> c;
    for (const auto& e : cn.elements()) c.push_back(e.numbers(m));
    spline.setCoefficients(c);
  }

  Eigen::AlignedBox<double, D> box;
  for (const auto& v : mesh.vertices) box.extend(v);
  if (auto d = o.get("domain")) {
    spline.setDomain(readDomain<D>(*d));
  } else if constexpr (D == 2) {
    if (continuity == "G1" || o.has("knots")) {
      double longest = 0;
      for (const auto& t : mesh.simplices)
        for (int e = 0; e < 3; ++e)
          longest = std::max(longest, (mesh.vertices[std::size_t(t[std::size_t(e)])] -
                                       mesh.vertices[std::size_t(t[std::size_t(e + 1) % 3])]).norm());
      const Eigen::Vector2d inset(longest, longest);
      if (!((box.sizes().array() > 2 * longest).all())) o.fail("the triangulation is too small for a G1 domain; give \"domain\"");
      spline.setDomain(Eigen::AlignedBox2d(box.min() + inset, box.max() - inset));
    }
  } else {
    // Inset by the knot reach: beyond it the basis is a partition of unity.
    const double reach = spline.knotReach();
    if (!((box.sizes().array() > 2 * reach).all())) o.fail("the mesh is too small for its knot clouds; give \"domain\"");
    spline.setDomain(Eigen::AlignedBox3d(box.min().array() + reach, box.max().array() - reach));
  }
  return spline;
}

template <int D>
std::vector<Primitive> build(const JsonNode& o, ObjectContext& ctx) {
  const Spline<D> spline = readSpline<D>(o, ctx.limits);
  if constexpr (D == 2) {
    ViewCullCount seen(ctx.view != nullptr);
    std::vector<Primitive> prims = spline.toPrimitives(ctx.material, 0, ctx.view, &seen);
    ctx.note = seen.note();
    return prims;
  } else {
    const auto start = std::chrono::steady_clock::now();
    SimplexSpline3::CellStats st;
    const bool cull = o.boolean("cull", true);
    std::vector<Primitive> prims;
    try {
      prims = spline.toPrimitives(ctx.material, 0, &st, cull, ctx.view, ctx.limits.max_cells);
    } catch (const SimplexSpline3::RegionLimitExceeded& e) {
      // The regions, estimated from a sample or counted while cutting (simplex_spline3.h).
      const std::string what =
          e.sampled ? "the cell decomposition (estimated from " + std::to_string(e.sampled) + " of " +
                          std::to_string(e.tets) + " tetrahedra)"
                    : "the cell decomposition (counted while cutting, stopped at the limit)";
      o.get("grid").value_or(o.get("tetrahedra").value_or(o))
          .fail(Limits::exceeded(what, e.regions, e.sampled ? "regions" : "regions or more", ctx.limits.max_cells,
                                 "max-cells"));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char note[320];
    std::snprintf(note, sizeof note,
                  "%zu tetrahedra (%zu culled whole), %zu knot-triangle planes, %zu regions made, %zu regions culled, "
                  "%zu tetrahedra and regions outside the view, %zu cells made, %zu emitted, %.2f s",
                  st.tets, st.tets_culled, st.planes, st.regions, st.regions_culled, st.view_culled, st.cells,
                  st.crossed, seconds);
    ctx.note = note;
    return prims;
  }
}

}  // namespace

SimplexSpline3 readBsplineVolume(const JsonNode& o, const Limits& limits) {
  if (!o.get("dimension") || o.at("dimension").integer(2, 3) != 3) o.fail("not a bspline volume (\"dimension\": 3)");
  return readSpline<3>(o, limits);
}

std::vector<Primitive> buildBspline(const JsonNode& o, ObjectContext& ctx) {
  const int dimension = o.get("dimension") ? int(o.at("dimension").integer(2, 3)) : 2;
  return dimension == 2 ? build<2>(o, ctx) : build<3>(o, ctx);
}

namespace {
// The scene object type this modeler provides (loader/object_registry.h).
[[maybe_unused]] const bool kRegistered = registerObjectTypes({
    {"bspline", buildBspline},
});

}  // namespace

}  // namespace qacc
