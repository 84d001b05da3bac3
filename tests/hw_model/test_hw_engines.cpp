// Accelerator engines: hw == hw-cycle bit for bit, thread-count independence, the cycle
// count of a lone primitive, back-pressure, and accuracy against the reference.
#include <cstdio>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <random>

#include "hw_model/report/accuracy_report.h"
#include "hw_model/engines/cycle_engine.h"
#include "hw_model/engines/functional_engine.h"
#include "hw_model/datapath/setup_arithmetic.h"
#include "hw_model/timing/host_interface_unit.h"
#include "hw_model/timing/pixel_pipeline_unit.h"
#include "hw_model/timing/setup_unit.h"
#include "modeling/geometry/natural_quadrics.h"
#include "modeling/loader/scene_loader.h"
#include "tests/hw_model/frame_expectations.h"
#include "tests/hw_model/random_timing.h"
#include "raster/reference/reference_renderer.h"
#include "tests/sanitized_build.h"

using namespace qacc;
namespace fs = std::filesystem;

namespace {

Scene loneSphereScene(int w, int h) {
  Scene s;
  s.name = "lone-sphere";
  s.width = w;
  s.height = h;
  s.camera.eye = {0, 0, 6};
  s.camera.target = {0, 0, 0};
  s.lights = Scene::defaultLights(s.camera);
  s.materials.emplace_back();
  s.primitives.push_back(makeSphere({0, 0, 0}, 1.0));
  s.objects.push_back({"sphere", 0, 1, 0, -1, {}});
  return s;
}

// Every count of a run (cycles, units, pixels, overflows, ...) without its host times, thread
// count and clock (HwStats::countsJson).
nlohmann::json counts(const HwStats& st) { return nlohmann::json::parse(st.countsJson()); }

std::uint64_t totalStalls(const HwStats& st) {
  std::uint64_t n = 0;
  for (const auto& u : st.units) n += u.stall;
  return n;
}

}  // namespace

TEST(HwEngines, BitIdenticalOnAllScenesAndThreadCounts) {
  const fs::path dir = fs::path(QACC_SOURCE_DIR) / "scenes";
  int count = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".json" || leftOutOfSanitizedSweeps(e.path().stem().string())) continue;
    Scene scene = loadScene(e.path().string());
    // reduced size keeps the suite fast; the arithmetic is the same at any size
    scene.width = 160;
    scene.height = 120;
    HwConfig cfg;
    const HwRender a = renderHw(scene, cfg, 1);
    const HwRender b = renderHw(scene, cfg, 2);
    const HwRender c = renderHwCycle(scene, cfg, 2);
    const HwRender c1 = renderHwCycle(scene, cfg, 1);
    expectIdentical(a.fb, b.fb, e.path().filename().string() + " hw 1 vs 2 threads");
    expectIdentical(a.fb, c.fb, e.path().filename().string() + " hw vs hw-cycle");
    // hw-cycle on one thread fills the pixel trace before its timing loop, on two while it
    // runs (the loop waiting for a primitive not yet filled): the same run either way.
    expectIdentical(c1.fb, c.fb, e.path().filename().string() + " hw-cycle 1 vs 2 threads");
    EXPECT_EQ(counts(c1.stats), counts(c.stats)) << e.path().filename().string() << " hw-cycle 1 vs 2 threads";
    EXPECT_EQ(c1.stats.fast_forwarded, c.stats.fast_forwarded) << e.path().filename().string();
    EXPECT_EQ(a.stats.pixels.tested, c.stats.pixels.tested);
    EXPECT_EQ(a.stats.pixels.covered, c.stats.pixels.covered);
    EXPECT_EQ(a.stats.pixels.written, c.stats.pixels.written);
    EXPECT_GT(c.stats.cycles, 0u);
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(HwEngines, TheClockCountsWhatTickingEveryCycleCounts) {
  // hw-cycle's clock ticks only some cycles: it repeats one tick's counts up to the next
  // timed event (a fast-forward) or over a unit's wait on a full channel. Ticking every cycle
  // must give the same cycles and the same counters of every unit (busy, stall, idle, items),
  // pixel, overflow, hierarchical Z and CSG counters, and the same image, on every shipped
  // scene (the CSG scenes too: their pass has its own machine) under every shipped
  // configuration. Before the fast-forward repeated a tick's counts it counted its cycles
  // busy or idle, never stalled: csg_molecule's CSG issue unit at 320x240 showed 40 483
  // stalled cycles of the 75 693 ticking each cycle counts.
  const fs::path dir = fs::path(QACC_SOURCE_DIR) / "scenes";
  // Under the sanitizers three of the five (35 s there with all five): the same code paths.
  std::vector<std::pair<std::string, HwConfig>> configs;
  for (const char* n : {"default", "minimal", "default_hiz", "wide", "default_no_csg_pruning"})
    if (!kSanitizedBuild || configs.size() < 3)
      configs.emplace_back(n, loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/" + n + ".json"));
  std::vector<fs::path> scenes;
  for (const fs::path& d : {dir, dir / "csg"})
    for (const auto& e : fs::directory_iterator(d))
      if (e.path().extension() == ".json" && !leftOutOfSanitizedSweeps(e.path().stem().string()))
        scenes.push_back(e.path());
  int runs = 0, fastForwarded = 0, csgRuns = 0, itemRuns = 0, itemHizRejections = 0;
  for (const fs::path& path : scenes) {
    Scene scene = loadScene(path.string());
    scene.width = 160;
    scene.height = 120;
    for (const auto& [n, cfg] : configs) {
      const HwRender b = renderHwCycle(scene, cfg, 1, MachineClock::EveryCycle);
      const nlohmann::json cb = counts(b.stats);
      EXPECT_EQ(b.stats.fast_forwarded, 0u);
      for (const MachineClock clock : {MachineClock::Items, MachineClock::Repeating}) {
        const HwRender a = renderHwCycle(scene, cfg, 1, clock);
        const std::string what = path.filename().string() + ", " + n + ", " + a.stats.simulator_clock;
        if (clock == MachineClock::Repeating) fastForwarded += a.stats.fast_forwarded > 0;
        itemRuns += a.stats.simulator_clock == "items";
        itemHizRejections += a.stats.simulator_clock == "items" && a.stats.hiz.blocks_rejected > 0;
        EXPECT_EQ(counts(a.stats), cb) << what;
        expectIdentical(a.fb, b.fb, what);
      }
      ++runs;
      csgRuns += b.stats.csg.cycles > 0;
    }
  }
  EXPECT_GE(runs, 15);
  EXPECT_GE(csgRuns, 9) << "the CSG pass has its own machine on the same clock";
  EXPECT_GE(fastForwarded, runs / 2) << "the runs must exercise the fast-forward";
  EXPECT_GE(itemRuns, runs / 2) << "the item clock applies to most shipped configurations";
  EXPECT_GE(itemHizRejections, 5) << "the item clock must time hierarchical Z rejections (default_hiz)";
  std::printf("shipped: %d runs, %d item-clock runs, %d of them with hierarchical Z rejections\n", runs, itemRuns,
              itemHizRejections);
}

TEST(HwEngines, TheClockCountsWhatTickingEveryCycleCountsUnderRandomTimings) {
  // The same comparison under random timing parameters (every timing key: random_timing.h;
  // and the depth variant and the hierarchical Z unit) on four small scenes: a unit whose nextEvent or nextChange missed a
  // cycle where its tick counts differently would show here under some timing.
  std::vector<Scene> scenes;
  // torus: primitives culled at the host (the setup unit drops them after the box test).
  for (const char* n : {"gallery.json", "csg/csg_quadrics.json", "molecule.json", "torus.json"}) {
    scenes.push_back(loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + n));
    scenes.back().width = 64;
    scenes.back().height = 48;
  }
  const int trials = kSanitizedBuild ? 8 : 40;
  int sharedBanks = 0, itemRuns = 0, itemHizRejections = 0;
  for (int seed = 1; seed <= trials; ++seed) {
    std::mt19937 rng{std::uint32_t(seed)};
    const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    HwConfig cfg = randomTiming(HwConfig{}, rng);
    cfg.depth_variant = pick(0, 1) ? DepthVariant::Stable : DepthVariant::Reciprocal;
    cfg.hierarchical_z = pick(0, 3) > 0;  // in 3 of 4 trials: at 64x48 few lookups reject
    checkHwConfig(cfg, "random timing " + std::to_string(seed));
    sharedBanks += cfg.zbuffer_banks % cfg.pipelines != 0;
    for (const Scene& scene : scenes) {
      const HwRender b = renderHwCycle(scene, cfg, 1, MachineClock::EveryCycle);
      const nlohmann::json cb = counts(b.stats);
      for (const MachineClock clock : {MachineClock::Items, MachineClock::Repeating}) {
        const HwRender a = renderHwCycle(scene, cfg, 1, clock);
        const std::string what = scene.name + ", seed " + std::to_string(seed) + ", " + a.stats.simulator_clock;
        itemRuns += a.stats.simulator_clock == "items";
        itemHizRejections += a.stats.simulator_clock == "items" && a.stats.hiz.blocks_rejected > 0;
        ASSERT_EQ(counts(a.stats), cb) << what;
        expectIdentical(a.fb, b.fb, what);
      }
    }
  }
  EXPECT_GT(sharedBanks, 0) << "some trials must share banks between pipelines (the round-robin decides)";
  EXPECT_GE(itemRuns, trials / 2) << "the item clock must apply in some trials";
  // Under the sanitizers the 8 trials may reject no block (seen: 0 of 12 item-clock runs);
  // TheItemClockSeesHierarchicalZWritesWhenTickingDoes rejects in every trial there too.
  if (!kSanitizedBuild) {
    EXPECT_GE(itemHizRejections, trials / 8) << "the item clock must time hierarchical Z rejections in some trials";
  }
  std::printf("random timings: %d item-clock runs, %d of them with hierarchical Z rejections\n", itemRuns, itemHizRejections);
}

TEST(HwEngines, TheItemClockSeesHierarchicalZWritesWhenTickingDoes) {
  // The item clock times a hierarchical Z lookup by the Z writes due at the tile memory by
  // the lookup's cycle (item_clock.h). Whether a write lands a cycle early or late shows in
  // the counters only when it decides a lookup: most often with small tiles and a slow
  // shading unit whose backpressure spreads the Z writes out. Sphereflake (many small
  // spheres) under such timings: a lookup that sees only the writes due before its cycle
  // (not those due in it) differs here in 5 of the 40 trials (seeds 3, 12, 29, 30, 34), one
  // that sees those due a cycle later too in 6, where the random timings above catch such a
  // slip in about 2 of 1 000 runs. The writes of one cycle applied in the reverse of the Z
  // unit's round-robin order fail 22 trials, in a fixed port order 10.
  Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/sphereflake.json");
  scene.width = 320;
  scene.height = 240;
  const int trials = kSanitizedBuild ? 6 : 40;
  int rejecting = 0;
  for (int seed = 1; seed <= trials; ++seed) {
    std::mt19937 rng{std::uint32_t(seed)};
    const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    HwConfig cfg;
    cfg.bus_width_bits = 16 << pick(0, 2);
    cfg.host_fifo_depth = pick(1, 4);
    cfg.pipelines = 1 << pick(0, 3);
    cfg.zbuffer_banks = cfg.pipelines * pick(1, 2);  // private banks: the item clock applies
    cfg.pixel_fifo_depth = pick(1, 8);
    cfg.zbuffer_read_latency = pick(1, 4);
    cfg.zbuffer_bank_busy = pick(1, 4);
    cfg.shading_cycles_per_pixel = pick(3, 4);
    cfg.shading_latency = pick(1, 20);
    cfg.hierarchical_z = true;
    cfg.hiz_tile_size = 4;
    cfg.hiz_depth_bits = pick(9, 16);
    checkHwConfig(cfg, "hierarchical Z timing " + std::to_string(seed));
    const HwRender b = renderHwCycle(scene, cfg, 1, MachineClock::EveryCycle);
    const HwRender a = renderHwCycle(scene, cfg, 1, MachineClock::Items);
    const std::string what = "seed " + std::to_string(seed);
    ASSERT_EQ(a.stats.simulator_clock, "items") << what;
    EXPECT_EQ(counts(a.stats), counts(b.stats)) << what;
    expectIdentical(a.fb, b.fb, what);
    rejecting += a.stats.hiz.blocks_rejected > 0;
  }
  EXPECT_EQ(rejecting, trials) << "every trial must reject blocks";
}

TEST(HwEngines, MinimalAndWideConfigurationsAlsoBitIdentical) {
  Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/gallery.json");
  scene.width = 200;
  scene.height = 150;
  for (const char* n : {"minimal", "wide"}) {
    const HwConfig cfg = loadHwConfig(std::string(QACC_SOURCE_DIR) + "/hw_model/configs/" + n + ".json");
    expectIdentical(renderHw(scene, cfg, 2).fb, renderHwCycle(scene, cfg, 1).fb, n);
  }
}

TEST(HwEngines, LonePrimitiveCycleCountMatchesAnalyticExpectation) {
  const Scene scene = loneSphereScene(256, 256);
  HwConfig cfg;
  cfg.pipelines = 1;
  cfg.pixel_fifo_depth = 64;
  const HwRender r = renderHwCycle(scene, cfg, 1);
  OverflowCounter ovf;
  const PrimitiveSetup s = setupPrimitive(scene, 0, scene.camera.worldToWindow(256, 256),
                                          scene.camera.worldToWindow(256, 256).inverse(), cfg, ovf);
  // host transfer + setup + one pixel per cycle (one clip pass: 0 planes, surface) +
  // the pipeline, Z-buffer and shading latencies; each of the 5 FIFO hops costs a cycle,
  // the traversal's span solve one more.
  const std::uint64_t host = std::uint64_t(HostInterfaceUnit::Params::from(cfg).transferCycles(s.descriptorWords));
  const std::uint64_t setup = std::uint64_t(SetupUnit::Params::from(cfg).cycles(s));
  const std::uint64_t expected = host + setup + r.stats.pixels.tested + std::uint64_t(PixelPipelineUnit::Params::from(cfg).latency) +
                                 std::uint64_t(cfg.zbuffer_read_latency) + std::uint64_t(cfg.shading_latency) + 5 + 1;
  const double diff = double(r.stats.cycles) - double(expected);
  EXPECT_LE(std::abs(diff), 4.0) << "cycles " << r.stats.cycles << " expected " << expected;
  // With P = 2 the pixel part halves (about: rows of odd length waste a slot).
  cfg.pipelines = 2;
  const HwRender r2 = renderHwCycle(scene, cfg, 1);
  const double pixelPart2 = double(r2.stats.cycles) - double(expected - r.stats.pixels.tested);
  EXPECT_NEAR(pixelPart2, double(r.stats.pixels.tested) / 2.0, 0.02 * double(r.stats.pixels.tested));
}

TEST(HwEngines, BackPressureStallsButSameImage) {
  Scene scene = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/gallery.json");
  scene.width = 200;
  scene.height = 150;
  HwConfig base;
  const HwRender ref = renderHw(scene, base, 2);
  const HwRender fast = renderHwCycle(scene, base, 1);
  HwConfig tight = base;
  tight.pixel_fifo_depth = 1;
  tight.host_fifo_depth = 1;
  tight.setup_fifo_depth = 1;
  tight.zbuffer_banks = 1;
  tight.shading_cycles_per_pixel = 3;
  const HwRender slow = renderHwCycle(scene, tight, 1);
  expectIdentical(ref.fb, slow.fb, "tight FIFOs, one bank");
  EXPECT_GT(totalStalls(slow.stats), totalStalls(fast.stats));
  EXPECT_GT(slow.stats.cycles, fast.stats.cycles);
  std::uint64_t zstall = 0;
  for (const auto& u : slow.stats.units)
    if (u.name == "zbuffer") zstall = u.stall;
  EXPECT_GT(zstall, 0u);
}

TEST(HwEngines, DefaultConfigAccuracyOnBenchmarkScenes) {
  for (const char* name : {"gallery", "cylinders", "character"}) {
    const std::string path = std::string(QACC_SOURCE_DIR) + "/scenes/" + name + ".json";
    if (!fs::exists(path)) continue;
    Scene scene = loadScene(path);
    scene.width /= 2;
    scene.height /= 2;
    const FrameBuffer ref = renderReference(scene, 2);
    const HwRender hw = renderHw(scene, HwConfig(), 2);
    const AccuracyReport a = accuracyReport(ref, hw.fb, scene.camera);
    EXPECT_LE(a.wrong_fraction, 1e-3) << name << ": " << a.line();
    EXPECT_EQ(a.pinholes, 0u) << name << ": " << a.line();
    EXPECT_GT(a.psnr_db, 40.0) << name;
    EXPECT_LE(a.mean_depth_z24, 2.0) << name;
    EXPECT_EQ(hw.stats.overflow.total(), 0u) << name;
  }
}

TEST(HwEngines, PrimitivesOffScreenAreCulledAtTheHostForTheBoxTestsCycles) {
  // Two spheres on screen, one beside the view and one behind the eye: the two off-screen ones
  // are dropped before setup in both engines (same images), hw-cycle's setup spends only the
  // box test's cycles on them and traversal never sees them.
  Scene scene = loneSphereScene(128, 96);
  scene.primitives.push_back(makeSphere({0.5, 0, 0}, 0.7));
  scene.primitives.push_back(makeSphere({40, 0, 0}, 1.0));
  scene.primitives.push_back(makeSphere({0, 0, 12}, 1.0));
  scene.objects[0].count = scene.primitives.size();
  HwConfig cfg;
  const HwRender a = renderHw(scene, cfg, 2);
  const HwRender c = renderHwCycle(scene, cfg, 1);
  expectIdentical(a.fb, c.fb, "hw vs hw-cycle with culled primitives");
  EXPECT_EQ(a.stats.culled_at_host, 2u);
  EXPECT_EQ(c.stats.culled_at_host, 2u);
  EXPECT_EQ(c.stats.visible_primitives, 2u);
  const Eigen::Matrix4d M = scene.camera.worldToWindow(scene.width, scene.height);
  std::uint64_t setupCycles = 0;
  const SetupUnit::Params sp = SetupUnit::Params::from(cfg);
  for (int i = 0; i < 4; ++i) {
    OverflowCounter ovf;
    const PrimitiveSetup s = setupPrimitive(scene, i, M, M.inverse(), cfg, ovf);
    EXPECT_EQ(s.culled, i >= 2) << i;
    EXPECT_LT(s.boxTestOps, s.setupOps);
    setupCycles += std::uint64_t(sp.cycles(s));
  }
  for (const UnitStats& u : c.stats.units) {
    if (u.name == "setup") {
      EXPECT_GE(u.busy, setupCycles);
    }
    if (u.name == "traversal") {
      EXPECT_EQ(u.items, 2u);
    }
  }
  // Each culled primitive costs the box test, not the whole setup.
  OverflowCounter ovf;
  const PrimitiveSetup off = setupPrimitive(scene, 2, M, M.inverse(), cfg, ovf);
  EXPECT_EQ(sp.cycles(off), (boxTestOperationCount(0, false) + cfg.setup_mad_units - 1) / cfg.setup_mad_units);
}
