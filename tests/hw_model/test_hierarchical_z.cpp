// The hierarchical Z unit (HwConfig::hierarchical_z): its tile memory is conservative, ties
// are rejected only where the Z test fails, the depth floor bounds every depth the datapath
// computes, images are byte-identical with the unit on and off in both engines, hw and
// hw-cycle agree with it on, and it rejects work on the molecule scene.
#include <gtest/gtest.h>

#include <random>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/hierarchical_z_memory.h"
#include "hw_model/datapath/pixel_datapath.h"
#include "hw_model/datapath/setup_arithmetic.h"
#include "hw_model/datapath/span_solver.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/report/cost_model.h"
#include "hw_model/report/hierarchical_z_counters.h"
#include "modeling/geometry/natural_quadrics.h"
#include "modeling/loader/scene_loader.h"
#include "tests/hw_model/frame_expectations.h"

using namespace qacc;

namespace {

HwConfig withHiz(int tile = 8) {
  HwConfig c;
  c.hierarchical_z = true;
  c.hiz_tile_size = tile;
  return c;
}

// A random scene of overlapping pieces of every kind the datapath draws: surfaces, clipped
// surfaces, solids with caps, cones, triangles (facets), seen from a random perspective view.
Scene randomScene(unsigned seed, int w, int h) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  auto v3 = [&] { return Eigen::Vector3d(U(rng), U(rng), U(rng)); };
  Scene s;
  s.name = "random-" + std::to_string(seed);
  s.width = w;
  s.height = h;
  s.camera.eye = Eigen::Vector3d(U(rng), U(rng), 4.5 + U(rng));
  s.camera.target = 0.2 * v3();
  s.lights = Scene::defaultLights(s.camera);
  s.materials.emplace_back();
  const int n = 24 + int(seed % 16);
  for (int i = 0; i < n; ++i) {
    Primitive p;
    switch (i % 6) {
      case 0: {  // every other one clipped to a half sphere
        const Eigen::Vector3d c = 1.2 * v3();
        p = makeSphere(c, 0.15 + 0.35 * std::abs(U(rng)));
        if ((i / 6) % 2 == 1) p.clip.push_back(HalfSpace::fromPointNormal(c, v3().normalized()));
        break;
      }
      case 1: p = makeEllipsoid(1.2 * v3(), Eigen::Vector3d(0.2, 0.3, 0.5) + 0.2 * v3().cwiseAbs()); break;
      case 2: {
        const Eigen::Vector3d a = 1.2 * v3();
        p = makeCylinder(a, a + 0.8 * v3(), 0.1 + 0.2 * std::abs(U(rng)));
        break;
      }
      case 3: {
        const Eigen::Vector3d a = 1.2 * v3();
        p = makeCone(a, a + 0.8 * v3(), 0.2 + 0.2 * std::abs(U(rng)));
        break;
      }
      case 4: p = makeTriangle(1.5 * v3(), 1.5 * v3(), 1.5 * v3()); break;
      default: {  // a solid sphere cut by a random plane: a cap
        const Eigen::Vector3d c = 1.2 * v3();
        p = makeSphere(c, 0.2 + 0.3 * std::abs(U(rng)));
        p.solid = true;
        p.clip.push_back(HalfSpace::fromPointNormal(c + 0.1 * v3(), v3().normalized()));
        break;
      }
    }
    p.object = i;
    p.material = 0;
    s.primitives.push_back(p);
    s.objects.push_back({"random", std::size_t(i), 1, 0, -1, {}});
  }
  return s;
}

// Every stored value of a tile is at most the memory's bound (brute force).
void expectConservative(const HierarchicalZMemory& m, const ZBufferMemory& zb, int tile, const HwConfig& cfg) {
  const int T = cfg.hiz_tile_size;
  std::uint32_t maxStored = 0;
  for (int y = 0; y < zb.height; ++y)
    for (int x = 0; x < zb.width; ++x)
      if (m.tileOf(x, y) == tile) maxStored = std::max(maxStored, zb.px[zb.index(x, y)].z);
  // rejects(t, v) says "every stored value of t is <= v": it must never say so for a value below the maximum.
  if (maxStored > 0) {
    EXPECT_FALSE(m.rejects(tile, maxStored - 1)) << "tile " << tile << " (" << T << "): bound below a stored value";
  }
}

}  // namespace

TEST(HierarchicalZ, CountersOfARejectedBlockAndOfAPrimitive) {
  // Both clocks count through these (TraversalUnit, the item clock).
  HierarchicalZCounters c;
  c.blockRejected(8, 2, 1);  // 4 issue cycles, 1 of lookup: 3 saved
  c.blockRejected(3, 4, 1);  // 1 issue cycle, no saving
  c.blockRejected(5, 1, 2);  // 5 issue cycles, 2 of lookup
  EXPECT_EQ(c.blocks_rejected, 3u);
  EXPECT_EQ(c.pixels_rejected, 16u);
  EXPECT_EQ(c.issue_cycles_saved, 6u);
  c.primitiveDone(false, false);  // never looked up: not counted
  c.primitiveDone(true, true);
  c.primitiveDone(true, false);
  EXPECT_EQ(c.primitives_tested, 2u);
  EXPECT_EQ(c.primitives_rejected, 1u);
}

TEST(HierarchicalZ, ConfigurationKeysAreStrict) {
  const std::string f = R"({"format": "qacc-hw-config/1", )";
  const HwConfig on = parseHwConfig(f + R"("hierarchical_z": true, "hiz_tile_size": 8, "hiz_depth_bits": 10})", "x.json");
  EXPECT_TRUE(on.hierarchical_z);
  EXPECT_EQ(on.hiz_tile_size, 8);
  EXPECT_EQ(on.hiz_depth_bits, 10);
  EXPECT_FALSE(HwConfig().hierarchical_z);  // off by default, as on the boards of the 1990s
  EXPECT_THROW(parseHwConfig(f + R"("hierarchical_z": 1})", "x.json"), std::invalid_argument);
  EXPECT_THROW(parseHwConfig(f + R"("hiz_tile_size": 12})", "x.json"), std::invalid_argument);
  EXPECT_THROW(parseHwConfig(f + R"("hiz_tile_size": 64})", "x.json"), std::invalid_argument);
  EXPECT_THROW(parseHwConfig(f + R"("hiz_depth_bits": 2})", "x.json"), std::invalid_argument);
  // Every key round-trips through the saved configuration.
  const HwConfig back = parseHwConfig(hwConfigToJson(on), "y.json");
  EXPECT_TRUE(back.hierarchical_z);
  EXPECT_EQ(back.hiz_tile_size, 8);
  for (const char* n : {"default", "minimal", "wide"})
    EXPECT_FALSE(loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/" + n + ".json").hierarchical_z) << n;
  const HwConfig shipped = loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/default_hiz.json");
  EXPECT_TRUE(shipped.hierarchical_z);
  EXPECT_EQ(shipped.hiz_tile_size, 8);
  EXPECT_EQ(shipped.name, "default_hiz");
}

TEST(HierarchicalZ, TileBoundIsConservativeUnderRandomWrites) {
  for (int tileSize : {4, 8, 16}) {
    for (int bits : {24, 12, 6}) {
      HwConfig cfg;
      cfg.hiz_tile_size = tileSize;
      cfg.hiz_depth_bits = bits;
      const int W = 37, H = 21;  // partial tiles at the right and bottom edges
      ZBufferMemory zb(W, H);
      HierarchicalZMemory m(cfg, 0, 0, W, H);
      std::mt19937 rng(unsigned(tileSize * 100 + bits));
      std::uniform_int_distribution<int> X(0, W - 1), Y(0, H - 1);
      std::uniform_int_distribution<std::uint32_t> Z(0, (1u << cfg.zbuffer_bits) - 1);
      int rejecting = 0;
      for (int i = 0; i < 20000; ++i) {
        const int x = X(rng), y = Y(rng);
        const std::uint32_t z = Z(rng);
        if (zb.testAndWrite(zb.index(x, y), z, i, 0, -1)) m.write(x, y, z);
        if (i % 97 == 0)
          for (int t = 0; t < ((W + tileSize - 1) / tileSize) * ((H + tileSize - 1) / tileSize); ++t) {
            expectConservative(m, zb, t, cfg);
            rejecting += m.rejects(t, (1u << cfg.zbuffer_bits) - 1);
          }
      }
      EXPECT_GT(rejecting, 0) << "tiles " << tileSize << ", bits " << bits << ": no bound was ever known";
    }
  }
}

TEST(HierarchicalZ, ABoundNeedsTheWholeTileAndTiesFailTheZTest) {
  HwConfig cfg;
  cfg.hiz_tile_size = 4;
  cfg.hiz_depth_bits = cfg.zbuffer_bits;  // exact maxima: the tie case is visible
  HierarchicalZMemory m(cfg, 0, 0, 8, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_FALSE(m.rejects(0, 0xFFFFFFu)) << "a tile not fully written keeps the far value";
      m.write(x, y, 1000 + std::uint32_t(x + y));  // the largest, 1006, at (3, 3)
    }
  EXPECT_TRUE(m.rejects(0, 1006));   // equal to the stored maximum: z < stored is false, the Z test fails
  EXPECT_FALSE(m.rejects(0, 1005));  // nearer than the pixel holding 1006: it would pass there
  EXPECT_FALSE(m.rejects(1, 0xFFFFFFu));  // the other tile knows nothing
  // A second layer: every pixel written nearer again lowers the bound; until then it stays.
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_TRUE(m.rejects(0, 1006));
      m.write(x, y, 500);
    }
  EXPECT_TRUE(m.rejects(0, 500));
  EXPECT_FALSE(m.rejects(0, 499));
  // In coarse units the bound rounds up: with 8 of 24 bits, 500 >> 16 = 0 stands for up to 2^16 - 1.
  HwConfig coarse = cfg;
  coarse.hiz_depth_bits = 8;
  HierarchicalZMemory c(coarse, 0, 0, 4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) c.write(x, y, 500);
  EXPECT_FALSE(c.rejects(0, 500));
  EXPECT_TRUE(c.rejects(0, (1u << 16) - 1));
}

// The depth floor bounds every depth the datapath computes for its primitive: evaluated
// without the floor (the same setup with zFloor = 0), no visible depth of any pixel of the
// primitive's box is below it. On random scenes of every primitive kind, and on the shipped
// scenes that use the unit in the benchmark.
TEST(HierarchicalZ, DepthFloorNeverExceedsADepthTheDatapathComputes) {
  std::vector<Scene> scenes;
  for (unsigned seed = 1; seed <= 12; ++seed) scenes.push_back(randomScene(seed, 96, 72));
  for (const char* n : {"molecule", "sphereflake", "gallery", "cylinders"}) {
    Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + n + ".json");
    s.width = 128;
    s.height = 96;
    scenes.push_back(std::move(s));
  }
  const HwConfig cfg;
  std::uint64_t hits = 0, withFloor = 0;
  for (const Scene& scene : scenes) {
    const Eigen::Matrix4d M = scene.camera.worldToWindow(scene.width, scene.height), Minv = M.inverse();
    for (int i = 0; i < int(scene.primitives.size()); ++i) {
      OverflowCounter so;
      const PrimitiveSetup s = setupPrimitive(scene, i, M, Minv, cfg, so);
      if (!s.visible) continue;
      withFloor += s.zFloor > 0;
      PrimitiveSetup unfloored = s;
      unfloored.zFloor = 0;
      PixelDatapath pp(unfloored, cfg);
      OverflowCounters ovf;
      for (int y = s.y0; y < s.y1; ++y) {  // every pixel the traversal issues
        Span sp[2];
        const int n = solveSpans(s, y, s.x0, s.x1, sp);
        for (int k = 0; k < n; ++k) {
          pp.startSpan(sp[k].x0 - s.x0, y - s.y0);
          for (int x = sp[k].x0; x < sp[k].x1; ++x) {
            const PixelOutcome o = pp.evaluate(ovf);
            pp.stepRight();
            if (!o.hit) continue;
            ++hits;
            ASSERT_GE(o.z, s.zFloor) << scene.name << " primitive " << i << " pixel " << x << "," << y;
          }
        }
      }
    }
  }
  EXPECT_GT(hits, 10000u);
  EXPECT_GT(withFloor, 100u);  // the floors are not all the trivial 0
}

TEST(HierarchicalZ, ImagesIdenticalOnAndOffInBothEnginesAndItRejectsOnMoleculeAndSphereflake) {
  struct Case {
    std::string name;
    Scene scene;
    std::vector<int> tiles;
  };
  std::vector<Case> cases;
  // The molecule at its own size (1920x1080): at a quarter of it few 8x8 tiles are ever
  // fully covered between its balls and sticks, and the unit rejects nothing.
  cases.push_back({"molecule", loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/molecule.json"), {8}});
  Scene flake = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/sphereflake.json");
  flake.width = 640;
  flake.height = 360;
  cases.push_back({"sphereflake", std::move(flake), {4, 8, 16}});
  for (unsigned seed = 20; seed < 28; ++seed)
    cases.push_back({"random " + std::to_string(seed), randomScene(seed, 160, 120), {4, 8, 16}});
  const HwConfig off;
  std::uint64_t randomRejected = 0;
  for (const Case& c : cases) {
    const HwRender hwOff = renderHw(c.scene, off, 2);
    const HwRender cyOff = renderHwCycle(c.scene, off, 2);
    expectIdentical(hwOff.fb, cyOff.fb, c.name + ": hw vs hw-cycle, off");
    EXPECT_FALSE(cyOff.stats.hiz.enabled);
    for (int tile : c.tiles) {
      const HwConfig on = withHiz(tile);
      const std::string what = c.name + ", tiles " + std::to_string(tile);
      const HwRender hwOn = renderHw(c.scene, on, 2);
      const HwRender cyOn = renderHwCycle(c.scene, on, 2);
      expectIdentical(hwOff.fb, hwOn.fb, what + ": hw off vs on");
      expectIdentical(hwOn.fb, cyOn.fb, what + ": hw vs hw-cycle, on");
      EXPECT_EQ(hwOn.stats.overflow.depth_floor_clamps, 0u) << what;
      EXPECT_TRUE(hwOn.stats.hiz.enabled && cyOn.stats.hiz.enabled);
      // A rejected pixel is one the Z test would have rejected: the written pixels are the same.
      EXPECT_EQ(hwOn.stats.pixels.written, hwOff.stats.pixels.written) << what;
      EXPECT_EQ(hwOn.stats.pixels.tested + hwOn.stats.hiz.pixels_rejected, hwOff.stats.pixels.tested) << what;
      EXPECT_EQ(cyOn.stats.pixels.tested + cyOn.stats.hiz.pixels_rejected, hwOff.stats.pixels.tested) << what;
      if (c.name.rfind("random", 0) == 0) randomRejected += hwOn.stats.hiz.pixels_rejected;
      if (c.name.rfind("random", 0) != 0) {  // molecule and sphereflake
        EXPECT_GT(hwOn.stats.hiz.pixels_rejected, 0u) << what;
        EXPECT_GT(cyOn.stats.hiz.pixels_rejected, 0u) << what;
        EXPECT_GT(cyOn.stats.hiz.blocks_rejected, 0u) << what;
        // At its own size the molecule is pixel-bound and the rejected pixels save cycles
        // (at 640x360 sphereflake is setup-bound: the floor's setup operations cost more).
        if (c.name == "molecule") {
          EXPECT_LT(cyOn.stats.cycles, cyOff.stats.cycles) << what << ": the rejected work saves cycles";
        }
      }
    }
  }
  EXPECT_GT(randomRejected, 0u);  // the random scenes exercise rejection too
}

TEST(HierarchicalZ, PricedWhenEnabled) {
  const HwConfig off;
  const CostModel a = CostModel::of(off), b = CostModel::of(withHiz(16)), c = CostModel::of(withHiz(8));
  EXPECT_EQ(a.hizBitsPerTile, 0);
  EXPECT_GT(b.totalGe(), a.totalGe());
  EXPECT_DOUBLE_EQ(b.totalGe() - a.totalGe(), b.hizGe);
  // zmax0 and zmax1 in 12 bits, the far flag, a 9-bit count (0..256) and the parity.
  EXPECT_EQ(b.hizBitsPerTile, 2 * 12 + 1 + 9 + 1);
  EXPECT_EQ(c.hizBitsPerTile, 2 * 12 + 1 + 7 + 1);
  HwConfig narrowZ = withHiz(16);
  narrowZ.zbuffer_bits = 10;  // the maxima are never wider than the stored depth
  EXPECT_EQ(HierarchicalZMemory::depthBits(narrowZ), 10);
}
