// Image quality per primitive count for the octahedron control net: the quadric macropatch
// models (4 and 18 quadrics per net) and the nets' quadratic Bézier triangles tessellated
// into n² triangles per net, all against the Bézier triangles tessellated finely (the
// surface the macropatches imitate), rendered by the exact reference renderer.
// Prints the table reported in docs/MODELERS_I.md.
#include <gtest/gtest.h>

#include <cstdio>

#include "modeling/loader/scene_loader.h"
#include "raster/metrics/coverage_error.h"
#include "raster/metrics/psnr.h"
#include "raster/reference/reference_renderer.h"
#include "raster/metrics/silhouette_distance.h"

using namespace qacc;

namespace {

Scene octahedronScene(const std::string& object) {
  return parseScene(R"({"format": "qacc-scene/1", "image": {"width": 256, "height": 256},
    "camera": {"type": "perspective", "eye": [3.2, -4.2, 2.6], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y_deg": 30},
    "lights": [{"type": "directional", "direction": [-0.5, 1, -0.8], "color": [1, 1, 1]},
               {"type": "ambient", "color": [0.12, 0.12, 0.12]}],
    "objects": [{"type": "macropatch", "surface": "octahedron", )" + object + "}]}",
                    "inline.json", ".");
}

struct Row {
  std::string name;
  std::size_t prims = 0;
  double psnr = 0, hausdorff = 0;
  long long coverage = 0;
};

Row measure(const std::string& name, const std::string& object, const FrameBuffer& truth) {
  const Scene s = octahedronScene(object);
  const FrameBuffer fb = renderReference(s, 0);
  Row r;
  r.name = name;
  r.prims = s.primitives.size();
  r.psnr = psnr(truth, fb);
  r.hausdorff = silhouetteDistance(truth, fb).hausdorff;
  const CoverageError ce = coverageError(truth, fb);
  r.coverage = (long long)(ce.pinholes + ce.spurious + ce.wrong_object);
  return r;
}

}  // namespace

TEST(MacropatchQuality, QuadricsAndTrianglesAgainstTheBezierSurface) {
  const FrameBuffer truth = renderReference(octahedronScene(R"("model": "bezier", "tessellation": 32)"), 0);
  std::vector<Row> rows;
  rows.push_back(measure("G0 (4/net)", R"("model": "G0")", truth));
  rows.push_back(measure("G1, G0 between (18/net)", R"("model": "G1", "between": "G0")", truth));
  rows.push_back(measure("G1, G1 between (18/net)", R"("model": "G1", "between": "G1")", truth));
  for (int n : {1, 2, 3, 4, 6, 8})
    rows.push_back(measure("bezier n=" + std::to_string(n) + " (" + std::to_string(n * n) + " tri/net)",
                           R"("model": "bezier", "tessellation": )" + std::to_string(n), truth));
  std::printf("%-28s %6s %8s %10s %10s\n", "model", "prims", "PSNR dB", "Hausdorff", "coverage");
  for (const auto& r : rows)
    std::printf("%-28s %6zu %8.2f %10.2f %10lld\n", r.name.c_str(), r.prims, r.psnr, r.hausdorff, r.coverage);
  // The 18-quadric model fitted to the Bézier triangles beats the 4-quadric one.
  EXPECT_GT(rows[1].psnr, rows[0].psnr);
  EXPECT_LE(rows[1].coverage, rows[0].coverage);
  // Finer tessellations converge to the reference.
  EXPECT_GT(rows.back().psnr, rows[3].psnr);
  EXPECT_EQ(rows[0].prims, 32u);
  EXPECT_EQ(rows[1].prims, 144u);
}
