#include "tools/cli/limit_options.h"


namespace qacc {

void addLimitOptions(CLI::App* cmd, Limits& limits) {
  const Limits defaults;
  cmd->add_option_function<std::size_t>(
         "--max-input-mb", [&limits](const std::size_t& v) { limits.max_input_bytes = v << 20; },
         "Largest input file read, MiB (default " + std::to_string(defaults.max_input_bytes >> 20) + ")")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 24));
  cmd->add_option("--max-primitives", limits.max_primitives,
                  "Most quadric primitives in a scene (default " + std::to_string(defaults.max_primitives) + ")")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  cmd->add_option("--max-cells", limits.max_cells,
                  "Most cells a modeler may create: algebraic tetrahedra, bspline work units (default " +
                      std::to_string(defaults.max_cells) + ")")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  cmd->add_option("--max-triangles", limits.max_triangles,
                  "Most triangles of a tessellation: facets engine, compare (default " +
                      std::to_string(defaults.max_triangles) + ")")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  cmd->add_option("--max-lights", limits.max_lights,
                  "Most lights in a scene (default " + std::to_string(defaults.max_lights) + ")")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  cmd->add_option("--max-materials", limits.max_materials,
                  "Most materials in a scene (default " + std::to_string(defaults.max_materials) + ")")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  cmd->add_option("--max-clip-work", limits.max_clip_work,
                  "Most plane tests of the primitives' clip polyhedra, C(n + 6, 3) (n + 6) - 120 for n clip "
                  "planes, summed over the scene (default " +
                      std::to_string(defaults.max_clip_work) + ")")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 62));
}

}  // namespace qacc
