// DatapathReuse (hw_model/engines/datapath_reuse.h): a render that takes the setups, the pixel
// trace and the frame of an earlier render of the same scene under the same datapath gives
// every count and every pixel a render from scratch gives, under random timing keys; a
// datapath key, another scene, another size or another set of winners is never reused; and
// the classification of the keys is checked key by key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <random>
#include <set>
#include <stdexcept>
#include <string>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/cycle_engine.h"
#include "modeling/loader/scene_loader.h"
#include "tests/hw_model/frame_expectations.h"
#include "tests/hw_model/random_timing.h"
#include "tests/sanitized_build.h"

using namespace qacc;

namespace {

nlohmann::json counts(const HwStats& st) { return nlohmann::json::parse(st.countsJson()); }

Scene smallScene(const char* name, int w = 64, int h = 48) {
  Scene s = loadScene(std::string(QACC_SOURCE_DIR) + "/scenes/" + name);
  s.width = w;
  s.height = h;
  return s;
}

}  // namespace

TEST(DatapathReuse, TimingKeysGiveWhatARenderFromScratchGives) {
  // gallery: clip planes and caps (the clip passes follow clip_evaluators); csg_quadrics: the
  // CSG pass; molecule: many primitives; torus: primitives culled at the host. Under the
  // default datapath and with the hierarchical Z unit (another setup: its depth floors).
  const int trials = kSanitizedBuild ? 3 : 12;
  int reusedFrames = 0, clipPassChanges = 0;
  std::set<std::string> varied;  // the timing keys some trial changed
  for (const char* name : {"gallery.json", "csg/csg_quadrics.json", "molecule.json", "torus.json"}) {
    const Scene scene = smallScene(name);
    for (const bool hiz : {false, true}) {
      HwConfig base;
      base.hierarchical_z = hiz;
      DatapathReuse reuse;
      reuse.setScene(name, name);
      const HwRender first = renderHwCycle(scene, base, 1, MachineClock::Items, &reuse);
      EXPECT_EQ(first.stats.reused, "") << name;
      ASSERT_EQ(reuse.entries(), 1u);
      std::mt19937 rng{hiz ? 7u : 3u};
      for (int t = 0; t < trials; ++t) {
        const HwConfig cfg = randomTiming(base, rng);
        checkHwConfig(cfg, "random timing");
        const std::string what = std::string(name) + (hiz ? ", hierarchical Z" : "") + ", trial " + std::to_string(t);
        const int threads = 1 + t % 2;
        const HwRender a = renderHwCycle(scene, cfg, threads, MachineClock::Items, &reuse);
        const HwRender b = renderHwCycle(scene, cfg, threads);
        EXPECT_EQ(a.stats.reused, "setup, pixel trace, frame") << what;
        EXPECT_EQ(b.stats.reused, "") << what;
        EXPECT_EQ(a.stats.trace_seconds, 0.0) << what << ": no trace was computed";
        EXPECT_EQ(counts(a.stats), counts(b.stats)) << what;
        expectIdentical(a.fb, b.fb, what);
        reusedFrames += a.stats.reused == "setup, pixel trace, frame";
        for (const std::string& key : hwConfigKeys())
          if (hwConfigValue(cfg, key) != hwConfigValue(base, key)) {
            EXPECT_TRUE(isHwTimingKey(key)) << key;
            varied.insert(key);
          }
        clipPassChanges += cfg.clip_evaluators < 4;
      }
    }
  }
  EXPECT_EQ(reusedFrames, 8 * trials);
  EXPECT_GT(clipPassChanges, 0);
  for (const std::string& key : hwConfigKeys()) {
    if (isHwTimingKey(key)) {
      EXPECT_TRUE(varied.count(key)) << key << " is a timing key that no trial changed";
    }
  }
}

TEST(DatapathReuse, ADatapathKeyAnotherSceneOrSizeIsComputedAgain) {
  const Scene scene = smallScene("gallery.json");
  DatapathReuse reuse;
  reuse.setScene("gallery", "gallery");
  const HwConfig base;
  renderHwCycle(scene, base, 1, MachineClock::Items, &reuse);
  // A datapath key: computed again, and kept in place of the first.
  HwConfig narrow = base;
  narrow.normal_bits = 12;
  narrow.unit_frac_bits = 10;
  const HwRender a = renderHwCycle(scene, narrow, 1, MachineClock::Items, &reuse);
  EXPECT_EQ(a.stats.reused, "");
  EXPECT_EQ(counts(a.stats), counts(renderHwCycle(scene, narrow, 1).stats));
  EXPECT_EQ(reuse.entries(), 1u);
  EXPECT_EQ(renderHwCycle(scene, narrow, 1, MachineClock::Items, &reuse).stats.reused, "setup, pixel trace, frame");
  EXPECT_EQ(renderHwCycle(scene, base, 1, MachineClock::Items, &reuse).stats.reused, "");
  // Another size of the same scene: computed again, in the same slot.
  const Scene larger = smallScene("gallery.json", 80, 60);
  EXPECT_EQ(renderHwCycle(larger, base, 1, MachineClock::Items, &reuse).stats.reused, "");
  EXPECT_EQ(reuse.entries(), 1u);
  EXPECT_EQ(renderHwCycle(larger, base, 1, MachineClock::Items, &reuse).stats.reused, "setup, pixel trace, frame");
  // Another content in the slot (a knob of the scene): computed again.
  reuse.setScene("gallery", "gallery, another knob");
  EXPECT_EQ(renderHwCycle(larger, base, 1, MachineClock::Items, &reuse).stats.reused, "");
  EXPECT_EQ(reuse.entries(), 1u);
  // Another slot: an entry of its own, beside the first.
  reuse.setScene("gallery, a second slot", "gallery");
  EXPECT_EQ(renderHwCycle(scene, base, 1, MachineClock::Items, &reuse).stats.reused, "");
  EXPECT_EQ(reuse.entries(), 2u);
  reuse.setScene("gallery", "gallery, another knob");
  EXPECT_EQ(renderHwCycle(larger, base, 1, MachineClock::Items, &reuse).stats.reused, "setup, pixel trace, frame");
}

TEST(DatapathReuse, OtherWinnersAreShadedAgain) {
  // The frame is taken only for the same winners, record for record: a kept entry whose
  // winners differ (here altered by hand) gives its setups and trace, not its frame.
  const Scene scene = smallScene("molecule.json");
  DatapathReuse reuse;
  reuse.setScene("molecule", "molecule");
  HwConfig cfg;
  const HwRender fresh = renderHwCycle(scene, cfg, 1, MachineClock::Items, &reuse);
  DatapathReuse::Entry* e = reuse.find(scene.width, scene.height, cfg);
  ASSERT_NE(e, nullptr);
  std::size_t pix = 0;
  while (pix < e->winners.size() && e->winners.px[pix].prim < 0) ++pix;
  ASSERT_LT(pix, e->winners.size());
  e->winners.px[pix].z ^= 1;
  e->frame.color.data[3 * pix] ^= 0xFF;  // a frame that must not be taken
  cfg.pipelines = 4;
  const HwRender a = renderHwCycle(scene, cfg, 1, MachineClock::Items, &reuse);
  EXPECT_EQ(a.stats.reused, "setup, pixel trace");
  expectIdentical(a.fb, fresh.fb, "winners altered");
  EXPECT_EQ(counts(a.stats), counts(renderHwCycle(scene, cfg, 1).stats));
}

TEST(DatapathReuse, AnEntryWithNoRoomIsNotKept) {
  const Scene scene = smallScene("torus.json");
  DatapathReuse reuse(1024);  // bytes: less than one entry
  reuse.setScene("torus", "torus");
  const HwConfig cfg;
  EXPECT_FALSE(reuse.mayKeep(scene.width, scene.height));
  renderHwCycle(scene, cfg, 1, MachineClock::Items, &reuse);
  EXPECT_EQ(reuse.entries(), 0u);
  EXPECT_EQ(renderHwCycle(scene, cfg, 1, MachineClock::Items, &reuse).stats.reused, "");
  // Room for the frame-sized arrays but not for the setups and the trace: built, then not kept.
  const std::size_t frame = std::size_t(scene.width) * std::size_t(scene.height) * (sizeof(ZEntry) + 3 + 8 + 8);
  DatapathReuse tight(frame + 16);
  tight.setScene("torus", "torus");
  EXPECT_TRUE(tight.mayKeep(scene.width, scene.height));
  renderHwCycle(scene, cfg, 1, MachineClock::Items, &tight);
  EXPECT_EQ(tight.entries(), 0u);
}

TEST(DatapathReuse, ARenderBeforeTheSceneIsNamedIsRefused) {
  // Without a scene name, two scenes of one size and datapath would look the same.
  const Scene scene = smallScene("torus.json");
  DatapathReuse reuse;
  EXPECT_THROW(renderHwCycle(scene, HwConfig{}, 1, MachineClock::Items, &reuse), std::logic_error);
}

TEST(DatapathReuse, EveryKeyButTheTimingKeysAndTheNameIsInTheDatapathKey) {
  // Each key changed alone: the datapath key changes exactly when the key is not a timing
  // key. A key added to HwConfig is datapath until it is listed as timing.
  const HwConfig base;
  const std::string baseKey = hwDatapathKey(base);
  int timing = 0, datapath = 0;
  for (const std::string& key : hwConfigKeys()) {
    if (key == "name") continue;
    const nlohmann::json v = hwConfigValue(base, key);
    std::vector<nlohmann::json> candidates;
    if (v.is_boolean()) candidates = {!v.get<bool>()};
    else if (v.is_number_integer()) candidates = {v.get<int>() + 1, v.get<int>() - 1, v.get<int>() * 2, v.get<int>() / 2};
    else if (v.is_number()) candidates = {v.get<double>() * 2};
    else candidates = {"truncate", "nearest", "nearest_even", "saturate", "wrap", "stable", "reciprocal", "newton", "recurrence"};
    bool changed = false;
    for (const nlohmann::json& c : candidates) {
      if (c == v) continue;
      HwConfig cfg = base;
      try {
        setHwConfigKey(cfg, key, c, "test");
      } catch (const std::invalid_argument&) {
        continue;
      }
      if (hwConfigValue(cfg, key) == v) continue;
      EXPECT_EQ(hwDatapathKey(cfg) != baseKey, !isHwTimingKey(key)) << key << " = " << c.dump();
      changed = true;
      break;
    }
    EXPECT_TRUE(changed) << key << ": no other value was accepted";
    (isHwTimingKey(key) ? timing : datapath) += 1;
  }
  EXPECT_EQ(timing, 20);
  EXPECT_GE(datapath, 20);
  HwConfig renamed = base;
  renamed.name = "another";
  EXPECT_EQ(hwDatapathKey(renamed), baseKey);
  EXPECT_FALSE(isHwTimingKey("not_a_key"));
}
