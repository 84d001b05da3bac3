#include "modeling/bspline_object.h"

#include <map>

#include "modeling/polynomial3.h"
#include "modeling/simplex_spline.h"

namespace qacc {

namespace {

Eigen::Vector2d vec2(const JsonNode& n) {
  const auto v = n.numbers(2);
  return Eigen::Vector2d(v[0], v[1]);
}

}  // namespace

std::vector<Primitive> buildBspline(const JsonNode& o, ObjectContext& ctx) {
  const int degree = o.get("degree") ? int(o.at("degree").integer(1, 3)) : 2;
  std::vector<Eigen::Vector2d> verts;
  std::vector<std::array<int, 3>> tris;
  if (auto g = o.get("grid")) {
    if (o.has("vertices") || o.has("triangles")) o.fail("give either grid or vertices + triangles");
    const Eigen::Vector2d lo = vec2(g->at("min")), hi = vec2(g->at("max"));
    const int n = int(g->at("n").integer(1, 64));
    g->finish();
    if (!(lo.x() < hi.x() && lo.y() < hi.y())) g->fail("grid min must be below max");
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        verts.emplace_back(lo.x() + (hi.x() - lo.x()) * i / n, lo.y() + (hi.y() - lo.y()) * j / n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
        tris.push_back({a, b, d});
        tris.push_back({a, d, c});
      }
  } else {
    const JsonNode vn = o.at("vertices");
    for (const auto& e : vn.elements()) verts.push_back(vec2(e));
    const JsonNode tn = o.at("triangles");
    for (const auto& e : tn.elements()) {
      if (!e.isArray() || e.size() != 3) e.fail("a triangle is 3 vertex indices");
      std::array<int, 3> t;
      for (std::size_t k = 0; k < 3; ++k) t[k] = int(e[k].integer(0, (long long)verts.size() - 1));
      tris.push_back(t);
    }
    if (tris.empty()) tn.fail("at least one triangle");
  }

  std::vector<std::vector<Eigen::Vector2d>> knots;
  const std::string continuity = o.string("continuity", "G1");
  if (continuity != "G0" && continuity != "G1") o.at("continuity").fail("continuity must be \"G0\" or \"G1\"");
  const double radius = o.positive("knot_radius", 0.2);
  if (auto k = o.get("knots")) {
    if (k->size() != verts.size()) k->fail("one knot cloud per vertex");
    for (const auto& cloud : k->elements()) {
      if (cloud.size() != std::size_t(degree)) cloud.fail("a knot cloud has `degree` points");
      std::vector<Eigen::Vector2d> c;
      for (const auto& p : cloud.elements()) c.push_back(vec2(p));
      knots.push_back(c);
    }
  } else {
    knots = knotClouds(verts, tris, degree, continuity == "G1", radius);
  }
  SimplexSpline2 spline(degree, verts, tris, knots);

  std::map<std::string, double> params;
  if (auto p = o.get("params")) {
    if (!p->isObject()) p->fail("params must be an object of named numbers");
    for (auto it = p->json().begin(); it != p->json().end(); ++it) params[it.key()] = p->at(it.key()).number();
  }
  if (auto h = o.get("height")) {
    if (o.has("coefficients")) o.fail("give either height or coefficients");
    Polynomial3 f;
    try {
      f = Polynomial3::parse(h->string(), params);
    } catch (const PolynomialParseError& e) {
      h->fail(e.what());
    }
    for (const auto& t : f.terms())
      if (t.k != 0) h->fail("the height is a function of x and y only");
    spline.setCoefficients(spline.grevilleCoefficients(f));
  } else {
    const JsonNode cn = o.at("coefficients");
    if (cn.size() != tris.size()) cn.fail("one coefficient list per triangle");
    const std::size_t m = SimplexSpline2::multiIndices(degree).size();
    std::vector<std::vector<double>> c;
    for (const auto& e : cn.elements()) c.push_back(e.numbers(m));
    spline.setCoefficients(c);
  }

  Eigen::AlignedBox2d box;
  for (const auto& v : verts) box.extend(v);
  if (auto d = o.get("domain")) {
    if (!d->isArray() || d->size() != 2) d->fail("domain must be [[xmin, ymin], [xmax, ymax]]");
    const Eigen::Vector2d lo = vec2((*d)[0]), hi = vec2((*d)[1]);
    if (!(lo.x() < hi.x() && lo.y() < hi.y())) d->fail("domain min must be below max");
    spline.setDomain(Eigen::AlignedBox2d(lo, hi));
  } else if (continuity == "G1" || o.has("knots")) {
    double longest = 0;
    for (const auto& t : tris)
      for (int e = 0; e < 3; ++e)
        longest = std::max(longest, (verts[std::size_t(t[std::size_t(e)])] - verts[std::size_t(t[std::size_t(e + 1) % 3])]).norm());
    const Eigen::Vector2d inset(longest, longest);
    if (!((box.sizes().array() > 2 * longest).all())) o.fail("the triangulation is too small for a G1 domain; give \"domain\"");
    spline.setDomain(Eigen::AlignedBox2d(box.min() + inset, box.max() - inset));
  }
  return spline.toPrimitives(ctx.material, 0);
}

}  // namespace qacc
