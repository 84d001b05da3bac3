// qacc info SCENE: objects, primitives, quadric types, clip-plane counts, bounds.
#include <cstdio>
#include <map>
#include <memory>

#include "modeling/geometry/primitive_bounds.h"
#include "modeling/geometry/quadric_type.h"
#include "modeling/loader/scene_loader.h"
#include "tools/cli/commands.h"
#include "tools/cli/limit_options.h"

namespace qacc {

void addInfoCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto limits = std::make_shared<Limits>();
  CLI::App* cmd = app.add_subcommand("info", "Describe a scene: primitives, quadric types, clip planes, bounds");
  cmd->add_option("scene", *path, "Scene file")->required();
  addLimitOptions(cmd, *limits);
  cmd->callback([path, limits] {
    const Scene s = loadScene(*path, *limits);
    std::printf("scene %s (%s)\n", s.name.c_str(), path->c_str());
    std::printf("image %dx%d, %s camera, %zu lights, %zu materials\n", s.width, s.height,
                s.camera.type == Camera::Type::Perspective ? "perspective" : "orthographic", s.lights.size(),
                s.materials.size());
    std::map<std::string, int> objTypes;
    for (const auto& o : s.objects) objTypes[o.type]++;
    std::printf("objects: %zu\n", s.objects.size());
    for (const auto& [t, n] : objTypes) std::printf("  %-24s %d\n", t.c_str(), n);
    for (std::size_t i = 0; i < s.objects.size(); ++i)
      if (!s.objects[i].note.empty())
        std::printf("  object %zu (%s): %s\n", i, s.objects[i].type.c_str(), s.objects[i].note.c_str());
    std::map<std::string, int> qTypes;
    std::map<std::size_t, int> clipCounts;
    int solid = 0, unbounded = 0;
    Eigen::AlignedBox3d bounds;
    bounds.setEmpty();
    for (const auto& p : s.primitives) {
      qTypes[quadricTypeName(quadricType(p.quadric))]++;
      clipCounts[p.clip.size()]++;
      solid += p.solid ? 1 : 0;
      const PrimitiveBounds b = primitiveBounds(p);
      if (b.empty) continue;
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
    if (unbounded) std::printf("unbounded primitives: %d\n", unbounded);
  });
}

}  // namespace qacc
