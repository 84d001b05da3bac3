#include "modeling/algebraic/algebraic_object.h"

#include <map>
#include <memory>
#include <sstream>

#include "modeling/algebraic/algebraic_surface.h"
#include "modeling/algebraic/degree_reduction.h"
#include "modeling/algebraic/polynomial3.h"

namespace qacc {

namespace {

Eigen::AlignedBox3d readBox(const JsonNode& n) {
  if (!n.isArray() || n.size() != 2) n.fail("box must be [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
  const Eigen::Vector3d lo = n[0].vec3(), hi = n[1].vec3();
  for (int a = 0; a < 3; ++a)
    if (!(lo[a] < hi[a])) n.fail("box minimum must be below its maximum on every axis");
  return Eigen::AlignedBox3d(lo, hi);
}

}  // namespace

AlgebraicSpec readAlgebraicSpec(const JsonNode& o) {
  AlgebraicSpec spec;
  std::map<std::string, double> params;
  if (auto p = o.get("params")) {
    if (!p->isObject()) p->fail("params must be an object of named numbers");
    for (auto it = p->json().begin(); it != p->json().end(); ++it) {
      const std::string& key = it.key();
      if (key == "x" || key == "y" || key == "z") p->fail("params cannot redefine the variable '" + key + "'");
      params[key] = p->at(key).number();
    }
  }
  const JsonNode polyNode = o.at("poly");
  try {
    spec.f = Polynomial3::parse(polyNode.string(), params);
  } catch (const PolynomialParseError& e) {
    polyNode.fail(e.what());
  }
  if (spec.f.degree() < 1) polyNode.fail("the polynomial is constant: it has no surface");
  if (spec.f.degree() > 16) polyNode.fail("degree " + std::to_string(spec.f.degree()) + " is above the supported 16");
  spec.box = readBox(o.at("box"));
  // Beyond 1e15 the pieces' barycentric matrices (rows x y z 1) lose their rank in double
  // precision and no quadric piece can be formed.
  const double extent = std::max(spec.box.min().cwiseAbs().maxCoeff(), spec.box.max().cwiseAbs().maxCoeff());
  if (extent > 1e15) {
    std::ostringstream m;
    m << "box coordinates reach " << extent << ", beyond the supported 1e15 (double precision cannot form the pieces)";
    o.at("box").fail(m.str());
  }

  DegreeReductionOptions& opt = spec.options;
  if (auto l = o.get("level")) opt.level = int(l->integer(1, 256));
  if (auto r = o.get("refine_error")) opt.refine_error = r->positive();
  if (auto m = o.get("max_level")) opt.max_level = int(m->integer(1, 256));
  opt.smooth = o.boolean("smooth", false);
  opt.merge = o.boolean("merge", false);
  opt.cull = o.boolean("cull", true);
  const std::string reference = o.string("reference", "exact");
  if (reference != "exact" && reference != "pieces")
    o.at("reference").fail("reference must be \"exact\" or \"pieces\"");
  spec.exact_reference = reference == "exact";
  return spec;
}

std::vector<Primitive> buildAlgebraic(const JsonNode& o, ObjectContext& ctx) {
  AlgebraicSpec spec = readAlgebraicSpec(o);
  spec.options.material = ctx.material;
  spec.options.view = ctx.view;
  // The Kuhn mesh of the final level (refinement doubles the level up to max_level) has
  // 6 level^3 tetrahedra, each a degree-n Bernstein form: refuse before building it.
  int finalLevel = spec.options.level;
  if (spec.options.refine_error > 0)
    while (finalLevel * 2 <= spec.options.max_level) finalLevel *= 2;
  const std::size_t tets = 6 * std::size_t(finalLevel) * std::size_t(finalLevel) * std::size_t(finalLevel);
  if (tets > ctx.limits.max_cells)
    o.get(finalLevel != spec.options.level ? "max_level" : "level")
        .value_or(o)
        .fail(Limits::exceeded("level " + std::to_string(finalLevel), tets, "Kuhn tetrahedra", ctx.limits.max_cells,
                               "max-cells"));
  DegreeReductionResult r = reduceAlgebraic(spec.f, spec.box, spec.options);
  ctx.note = "level " + std::to_string(r.level) + ": " + std::to_string(r.cells) + " cells, " +
             std::to_string(r.built_cells) + " built, " + std::to_string(r.view_culled_cells) + " outside the view, " +
             std::to_string(r.kept_cells) + " pieces";
  if (spec.exact_reference) {
    ctx.scene.exact_surfaces.push_back(std::make_shared<AlgebraicSurface>(spec.f, spec.box));
    ctx.model_cells = std::size_t(r.cells);  // the facets' budget: every cell, whatever the view kept
  }
  return std::move(r.primitives);
}

namespace {
// The scene object type this modeler provides (loader/object_registry.h).
[[maybe_unused]] const bool kRegistered = registerObjectTypes({
    {"algebraic", buildAlgebraic},
});

}  // namespace

}  // namespace qacc
