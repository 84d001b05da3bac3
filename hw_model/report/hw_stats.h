// HwStats: what an accelerator run measured (`--stats FILE`: JSON, and a CSV alongside).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "hw_model/report/accuracy_report.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/overflow_counters.h"
#include "hw_model/report/hierarchical_z_counters.h"
#include "hw_model/report/cost_model.h"
#include "hw_model/report/scene_needs.h"

namespace qacc {

struct PixelCounters {
  std::uint64_t tested = 0;          // issued by traversal
  std::uint64_t covered = 0;         // a visible point of the primitive (surface or cap)
  std::uint64_t caps = 0;            // ... of which on a cap
  std::uint64_t clipped = 0;         // Δ >= 0 (or cap candidate) but every point clipped
  std::uint64_t depth_rejected = 0;  // covered but failed the Z test
  std::uint64_t written = 0;         // passed the Z test
  std::uint64_t clip_passes = 0;     // clip-unit passes
  void add(const PixelCounters& o);
};

// The CSG path (engines/csg_tile.h): bounded per-pixel interval lists of the csg
// objects' leaves (datapath/csg_interval_list.h).
struct CsgCounters {
  std::uint64_t objects = 0;            // csg objects in the scene
  std::uint64_t leaf_pixels = 0;        // (pixel, leaf) interval evaluations by the pixel datapath
  std::uint64_t interval_ends = 0;      // interval ends kept in the per-pixel lists and swept
  std::uint64_t max_list_ends = 0;      // the longest per-pixel demand, in ends (before bounding)
  std::uint64_t resolved = 0;           // pixels whose tree was evaluated
  std::uint64_t overflowed_pixels = 0;  // pixels whose list overflowed (their image may be wrong)
  std::uint64_t dropped_intervals = 0;  // intervals left out of full lists
  // Tile pruning (csg_tile_pruning, modeling/csg/csg_tree_pruning.h), zero with it off:
  // per tile job, every leaf's box compared with the tile; the present leaves left out
  // because they sit under an empty intersection or difference, those products, and the
  // jobs whose whole tree is empty in their tile (no list buffer, nothing issued).
  std::uint64_t leaves_tested = 0;
  std::uint64_t leaves_pruned = 0;
  std::uint64_t products_pruned = 0;
  std::uint64_t jobs_pruned = 0;
  // hw-cycle: the cycles of the CSG pass, simulated by its timed units after the other
  // primitives (engines/csg_cycle_pass.h); included in `cycles`.
  std::uint64_t cycles = 0;
  void add(const CsgCounters& o);
  std::string line(const HwConfig& cfg) const;  // the summary line of `qacc render`
};

struct UnitStats {
  std::string name;
  std::uint64_t busy = 0, stall = 0, idle = 0;
  std::uint64_t items = 0;  // primitives or pixels the unit processed
};

struct HwStats {
  std::string engine;
  std::string config;
  std::string scene;
  int width = 0, height = 0;
  int threads = 1;
  std::uint64_t primitives = 0;
  std::uint64_t visible_primitives = 0;  // non-empty screen box
  // Dropped after the host interface, before setup: the exact screen box misses the screen
  // or the depth range (PrimitiveSetup::culled; hw-cycle costs the box test's cycles).
  std::uint64_t culled_at_host = 0;
  std::uint64_t facet_primitives = 0;    // through the flat-facet path
  PixelCounters pixels;
  OverflowCounters overflow;
  std::uint64_t cycles = 0;          // hw-cycle only (0 for hw)
  std::uint64_t fast_forwarded = 0;  // cycles before a timed event in which nothing moved (counted from one tick)
  // How hw-cycle's simulator went through the main pass's cycles (not a count: the same
  // counts either way): "items" (engines/item_clock.h), "repeated ticks" or "every cycle"
  // (engines/machine_run.h); empty for hw.
  std::string simulator_clock;
  std::vector<UnitStats> units;
  double clock_mhz = 0;
  double host_seconds = 0;           // wall time of the render
  double loop_seconds = 0;           // hw-cycle: wall time of the timing loop alone (one core; less its waits for the trace)
  double trace_seconds = 0;          // hw-cycle: wall time of the pixel datapath pass (pixel_trace.h), from planning to
                                     // the last pixel filled (with threads, beside the loop: the two overlap); 0 when reused
  // hw-cycle: what the render took from an earlier render of the same scene under the same
  // datapath (engines/datapath_reuse.h): "setup, pixel trace, frame", "setup, pixel trace"
  // (its winners differed, so it shaded its own), or empty (computed all).
  std::string reused;

  CostModel cost;                    // silicon cost of the configuration
  SceneNeeds needs;                  // the units the scene uses (priceNeeds)
  CostModel cost_needed;             // silicon cost of the part of the configuration the scene uses
  bool has_needs = false;
  HwConfig configuration;            // the resolved configuration (every key is saved)
  bool has_accuracy = false;         // accuracy against the reference was measured
  AccuracyReport accuracy;

  // The run's identity: engine, configuration (name, clock, cost), scene, image size, threads.
  void describeRun(const std::string& engineName, const HwConfig& cfg, const std::string& sceneName, int w, int h,
                   int nthreads) {
    engine = engineName;
    config = cfg.name;
    configuration = cfg;
    scene = sceneName;
    width = w;
    height = h;
    threads = nthreads;
    clock_mhz = cfg.clock_mhz;
    cost = CostModel::of(cfg);
  }
  // Prices the configuration `scene` needs beside the full one (scene_needs.h).
  void priceNeeds(const Scene& s) {
    needs = SceneNeeds::of(s);
    cost_needed = CostModel::of(configuration, &needs);
    has_needs = true;
  }
  double frameSeconds() const { return clock_mhz > 0 ? double(cycles) / (clock_mhz * 1e6) : 0; }
  double overdraw() const;  // covered / distinct pixels written
  std::uint64_t distinct_written = 0;  // pixels showing an object at the end
  CsgCounters csg;                     // zero without csg objects
  HierarchicalZCounters hiz;           // the hierarchical Z unit (enabled: HwConfig::hierarchical_z)

  std::string toJson() const;
  // toJson without what depends on the host (its times and rates, the slowdown, the thread
  // count) or on the simulator's clock (its name, the cycles the ticking clock fast-forwarded):
  // every count of the run, which another run of the same frame must reproduce under any clock.
  std::string countsJson() const;
  std::string toCsv() const;  // one header line + one value line
  // Writes path (JSON) and path with extension replaced by .csv.
  void write(const std::string& path) const;
  std::vector<std::string> summaryLines() const;
};

}  // namespace qacc
