// qacc info SCENE: objects, primitives, quadric types, clip-plane counts, bounds.
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>

#include "hw_model/config/hw_config.h"
#include "hw_model/report/cost_model.h"
#include "hw_model/report/scene_needs.h"
#include "modeling/csg/csg_normal_form.h"
#include "modeling/geometry/primitive_bounds.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/loader/scene_loader.h"
#include "raster/pixel/csg_tile_work.h"
#include "raster/pixel/window_primitive.h"
#include "raster/reference/csg_hit.h"
#include "tools/cli/commands.h"
#include "tools/cli/limit_options.h"
#include "tools/cli/view_cull_option.h"

namespace qacc {

namespace {

// Per csg object: its tree, its normal form (Goldfeather) and the work per 32x32 tile of a
// product-at-a-time method with and without pruning by screen boxes.
void printCsgInfo(const Scene& s) {
  const Eigen::Matrix4d M = s.camera.worldToWindow(s.width, s.height), Minv = M.inverse();
  std::vector<WindowPrimitive> win(s.primitives.size());
  std::vector<ScreenBox> boxes(s.primitives.size());
  for (const CsgTree& t : s.csg_trees)
    for (int p : t.leafPrimitives()) {
      win[std::size_t(p)] = toWindow(s.primitives[std::size_t(p)], p, M, Minv, s.width, s.height);
      boxes[std::size_t(p)] = win[std::size_t(p)].box;
    }
  std::printf("csg objects: %zu\n", s.csg_trees.size());
  for (const CsgTree& t : s.csg_trees) {
    const CsgNormalForm f = normalForm(t);
    std::printf("  object %d: %zu leaves, depth %d; normal form: %s%zu products, at most %zu literals, %zu passes\n",
                t.object, t.leafPrimitives().size(), t.depth(), f.complete ? "" : "over ", f.products.size(),
                f.maxLiterals(), f.passes());
    if (!f.complete) continue;
    const ScreenBox box = CsgPixelTree(t, win, s.width, s.height).box();
    const CsgTileWork all = csgTileWork(f, boxes, box, s.width, s.height, false);
    const CsgTileWork pruned = csgTileWork(f, boxes, box, s.width, s.height, true);
    std::printf("    per tile: %llu tiles; without pruning %llu product draws, %llu passes; "
                "with box pruning %llu product draws, %llu passes (%.1f%% of the passes)\n",
                (unsigned long long)all.tiles, (unsigned long long)all.products, (unsigned long long)all.passes,
                (unsigned long long)pruned.products, (unsigned long long)pruned.passes,
                all.passes ? 100.0 * double(pruned.passes) / double(all.passes) : 0.0);
  }
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto perPrimitive = std::make_shared<bool>(false);
  auto limits = std::make_shared<Limits>();
  auto viewCull = std::make_shared<bool>(true);
  CLI::App* cmd = app.add_subcommand("info", "Describe a scene: primitives, quadric types, clip planes, bounds");
  cmd->add_option("scene", *path, "Scene file")->required();
  cmd->add_flag("--primitives", *perPrimitive,
                "Also list every primitive: object, quadric type, planes, solid, world bounds of its clipped piece");
  addLimitOptions(cmd, *limits);
  addViewCullOption(cmd, *viewCull);
  cmd->callback([path, perPrimitive, limits, viewCull] {
    const auto loadStart = std::chrono::steady_clock::now();
    const Scene s = loadScene(*path, *limits, ViewCulling{*viewCull, 0, 0});
    const double loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
    std::printf("scene %s (%s)\n", s.name.c_str(), path->c_str());
    std::printf("image %dx%d, %s camera, %zu lights, %zu materials\n", s.width, s.height,
                s.camera.type == Camera::Type::Perspective ? "perspective" : "orthographic", s.lights.size(),
                s.materials.size());
    std::map<std::string, int> objTypes;
    for (const auto& o : s.objects) objTypes[o.type]++;
    std::printf("objects: %zu\n", s.objects.size());
    std::printf("loaded in %.3f s (read, parse, build, view culling; %s)\n", loadSeconds,
                "wall clock, on this machine as loaded now");
    for (const auto& [t, n] : objTypes) std::printf("  %-24s %d\n", t.c_str(), n);
    for (std::size_t i = 0; i < s.objects.size(); ++i)
      if (!s.objects[i].note.empty())
        std::printf("  object %zu (%s): %s\n", i, s.objects[i].type.c_str(), s.objects[i].note.c_str());
    std::map<std::string, int> qTypes;
    std::map<std::size_t, int> clipCounts;
    int solid = 0, unbounded = 0, empty = 0;
    Eigen::AlignedBox3d bounds;
    bounds.setEmpty();
    if (*perPrimitive) std::printf("primitive  object  type                          planes  solid  bounds\n");
    for (std::size_t i = 0; i < s.primitives.size(); ++i) {
      const Primitive& p = s.primitives[i];
      qTypes[quadricTypeName(quadricType(p.quadric))]++;
      clipCounts[p.clip.size()]++;
      solid += p.solid ? 1 : 0;
      PrimitiveBounds b = primitiveBounds(p);
      if (b.bounded && !b.empty) b.box.translate(s.origin);  // world coordinates (scene_origin.h)
      if (*perPrimitive) {
        std::printf("%9zu  %6d  %-28s  %6zu  %5s  ", i, p.object, quadricTypeName(quadricType(p.quadric)),
                    p.clip.size(), p.solid ? "yes" : "no");
        if (b.empty) std::printf("empty\n");
        else if (!b.bounded) std::printf("unbounded\n");
        else
          std::printf("[%.4g, %.4g, %.4g] - [%.4g, %.4g, %.4g]\n", b.box.min().x(), b.box.min().y(), b.box.min().z(),
                      b.box.max().x(), b.box.max().y(), b.box.max().z());
      }
      if (b.empty) {
        ++empty;
        continue;
      }
      if (b.bounded) bounds.extend(b.box);
      else ++unbounded;
    }
    std::printf("primitives: %zu (%d solid, %zu exact surfaces)\n", s.primitives.size(), solid,
                s.exact_surfaces.size());
    std::printf("quadric types:\n");
    for (const auto& [t, n] : qTypes) std::printf("  %-28s %d\n", t.c_str(), n);
    std::printf("clip planes per primitive:\n");
    for (const auto& [k, n] : clipCounts) std::printf("  %2zu planes: %d primitives\n", k, n);
    if (!bounds.isEmpty())
      std::printf("bounds: [%.4g, %.4g, %.4g] - [%.4g, %.4g, %.4g]%s\n", bounds.min().x(), bounds.min().y(),
                  bounds.min().z(), bounds.max().x(), bounds.max().y(), bounds.max().z(),
                  unbounded ? " (bounded primitives only)" : "");
    if (!s.origin.isZero())
      std::printf("scene frame: origin at [%.17g, %.17g, %.17g] (coordinates held relative to it, far from the world origin)\n",
                  s.origin.x(), s.origin.y(), s.origin.z());
    if (unbounded) std::printf("unbounded primitives: %d (their clipped piece is unbounded)\n", unbounded);
    if (empty) std::printf("empty primitives: %d (their clipped piece is empty)\n", empty);
    {
      // The accelerator's units this scene uses, priced by the cost model (default configuration).
      const HwConfig cfg;
      const SceneNeeds needs = SceneNeeds::of(s);
      std::printf("accelerator units used: %s; cost model (default configuration): %.0f kGE full, %.0f kGE needed\n",
                  needs.describe().c_str(), CostModel::of(cfg).totalGe() / 1e3, CostModel::of(cfg, &needs).totalGe() / 1e3);
    }
    if (!s.csg_trees.empty()) printCsgInfo(s);
  });
}

}  // namespace qacc
