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
  // Lights of a scene: --max-lights. Every engine shades every covered pixel once per light
  // (a 320x240 sphere under 1 000 point lights: 1.2 s of CPU in `hw`; under 100 000 the
  // reference was stopped after 100 s).
  std::size_t max_lights = 64;
  // Materials of a scene: --max-materials (300 000 took 300 MB; a 1 GiB scene file holds
  // tens of millions).
  std::size_t max_materials = 65'536;
  // The work of the primitives' clip polyhedra, summed over the scene: --max-clip-work.
  // Finding the exact extent of a clipped piece enumerates the vertices of its clip
  // polyhedron within the view volume (its n planes and the view volume's 6) by testing
  // every triple of planes against every plane: clipWork(n) tests, which grows as n^4 (400
  // planes on one sphere: 4.5e9 tests, 14 s of setup on the project's machine; 33 000 was
  // stopped after 300 s: about 2e17 tests). The default keeps a scene's setup within a few seconds.
  std::size_t max_clip_work = 1'000'000'000;
  // C(n + 6, 3) (n + 6) - 120: the plane tests of a primitive with n clip planes beyond
  // those of the view volume alone (0 for a primitive without clip planes); saturates at
  // SIZE_MAX.
  static std::size_t clipWork(std::size_t planes);
  // a + b, saturating at SIZE_MAX.
  static std::size_t addSaturated(std::size_t a, std::size_t b);

  // "WHAT needs N UNIT, above the limit of M (raise it with --OPTION)": the one refusal message.
  static std::string exceeded(const std::string& what, std::size_t needed, const char* unit, std::size_t limit,
                              const char* option);
};

}  // namespace qacc
