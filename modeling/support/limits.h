// Limits: the work a scene may ask for, checked before anything is built, so that accepted
// input always ends within bounded time and memory (docs/SCENES.md, "Limits"). Each limit has
// a command-line option that raises it; a scene over a limit is refused with a message that
// names the limit and the option, never a bad_alloc or an endless run.
#pragma once
#include <cstddef>
#include <string>

namespace qacc {

struct Limits {
  // Bytes read from any one input file (scene, PDB, OBJ, configuration): --max-input-mb.
  std::size_t max_input_bytes = std::size_t(1) << 30;
  // Quadric primitives of a scene, after every object is built: --max-primitives.
  std::size_t max_primitives = 10'000'000;
  // Cells a modeler may create before it culls them (the Kuhn tetrahedra of `algebraic` at
  // its final level; in `bspline`, the leaves of the compiled basis, then a volume's regions):
  // --max-cells.
  std::size_t max_cells = 2'000'000;
  // Triangles of a tessellation (facets engine, compare): --max-triangles. 4 M keeps the
  // costliest accepted tessellation (pieces marched, as in the B-spline volume: about 20 us
  // of CPU per triangle with the draw) within a minute on two cores and about 2.2 GB.
  std::size_t max_triangles = 4'000'000;

  // "WHAT needs N UNIT, above the limit of M (raise it with --OPTION)": the one refusal message.
  static std::string exceeded(const std::string& what, std::size_t needed, const char* unit, std::size_t limit,
                              const char* option);
};

}  // namespace qacc
