#include "hw_model/engines/csg_cycle_pass.h"

#include <omp.h>

#include <stdexcept>
#include <string>

#include "hw_model/engines/machine_run.h"
#include "hw_model/timing/channel_registry.h"
#include "hw_model/timing/csg_interval_pipeline_unit.h"
#include "hw_model/timing/csg_issue_unit.h"
#include "hw_model/timing/csg_list_unit.h"
#include "hw_model/timing/csg_sweep_unit.h"
#include "hw_model/timing/shading_unit.h"
#include "hw_model/timing/zbuffer_unit.h"
#include "raster/pixel/tile_binner.h"

namespace qacc {

namespace {

// The jobs in the order the hardware takes them: tiles in order, csg objects in scene
// order within a tile; computed per tile in parallel.
std::vector<CsgJob> buildJobs(const CsgFrame& csg, const FrameSetup& fs, const HwConfig& cfg, int width, int height,
                              int threads, HwStats& st) {
  TileBinner bins(width, height);
  const std::size_t T = std::size_t(bins.tiles());
  std::vector<std::vector<CsgJob>> perTile(T);
  std::vector<PixelCounters> pc(T);
  std::vector<OverflowCounters> oc(T);
  std::vector<CsgCounters> cc(T);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int t = 0; t < bins.tiles(); ++t) {
    const ScreenBox tile = bins.tile(t);
    for (std::size_t k = 0; k < csg.trees.size(); ++k) {
      if (csg.trees[k].box().intersect(tile).empty()) continue;
      CsgJob job;
      job.tile = t;
      job.tree = int(k);
      drawCsgTile(csg.trees[k], fs, cfg, tile, t, nullptr, pc[std::size_t(t)], oc[std::size_t(t)],
                  cc[std::size_t(t)], &job);
      perTile[std::size_t(t)].push_back(std::move(job));
    }
  }
  std::vector<CsgJob> jobs;
  for (std::size_t t = 0; t < T; ++t) {
    st.pixels.add(pc[t]);
    st.overflow.add(oc[t]);
    st.csg.add(cc[t]);
    for (CsgJob& j : perTile[t]) jobs.push_back(std::move(j));
  }
  return jobs;
}

}  // namespace

void runCsgCyclePass(const CsgFrame& csg, const FrameSetup& fs, const HwConfig& cfg, int width, int height,
                     ZBufferMemory& zb, int threads, MachineClock clock, HwStats& st) {
  st.csg.objects = csg.trees.size();
  if (csg.trees.empty()) return;
  const std::vector<CsgJob> jobs = buildJobs(csg, fs, cfg, width, height, threads, st);

  ChannelRegistry wires;
  const std::size_t P = std::size_t(cfg.pipelines);
  auto& bufferFreed = wires.make<int>(std::size_t(kCsgListBuffers));
  auto& toSweep = wires.make<int>(std::size_t(kCsgListBuffers));
  std::vector<Channel<CsgToken>*> toPipeline, toList;
  std::vector<Channel<PointToken>*> toZ, toShading;
  for (std::size_t p = 0; p < P; ++p) {
    toPipeline.push_back(&wires.make<CsgToken>(std::size_t(cfg.pixel_fifo_depth)));
    toList.push_back(&wires.make<CsgToken>(std::size_t(cfg.pixel_fifo_depth)));
    toZ.push_back(&wires.make<PointToken>(std::size_t(cfg.pixel_fifo_depth)));
    toShading.push_back(&wires.make<PointToken>(std::size_t(cfg.pixel_fifo_depth)));
  }
  CsgIssueUnit issue(CsgIssueUnit::Params::from(cfg), jobs, bufferFreed, toPipeline);
  std::vector<CsgIntervalPipelineUnit> pipelines;
  pipelines.reserve(P);
  for (std::size_t p = 0; p < P; ++p)
    pipelines.emplace_back("pixel_pipeline_" + std::to_string(p), CsgIntervalPipelineUnit::Params::from(cfg), wires,
                           jobs, *toPipeline[p], *toList[p]);
  CsgListUnit list(jobs, toList, toSweep);
  CsgSweepUnit sweep(CsgSweepUnit::Params::from(cfg), jobs, toSweep, bufferFreed, toZ);
  const std::uint64_t writtenBefore = st.pixels.written;
  ZBufferUnit zunit(ZBufferUnit::Params::from(cfg), cfg, wires, zb, toZ, toShading, st.pixels);
  zunit.tiesInSceneOrder();
  std::vector<ShadingUnit> shading;
  shading.reserve(P);
  for (std::size_t p = 0; p < P; ++p)
    shading.emplace_back("shading_" + std::to_string(p), ShadingUnit::Params::from(cfg), wires, *toShading[p]);
  const std::uint64_t before = st.cycles;
  const std::uint64_t cycles =
      runMachine(clock, wires, st.fast_forwarded, issue, pipelines, list, sweep, zunit, shading);
  std::uint64_t delivered = 0;
  for (const ShadingUnit& u : shading) delivered += u.delivered();
  if (delivered != st.pixels.written - writtenBefore)
    throw std::logic_error("hw-cycle: the CSG pass shaded " + std::to_string(delivered) + " of " +
                           std::to_string(st.pixels.written - writtenBefore) + " pixels");
  st.csg.cycles = cycles;
  st.cycles += cycles;
  // One timeline per unit over the whole frame: a unit of both parts adds its CSG-pass
  // cycles; a unit of one part is idle during the other.
  std::vector<UnitStats> passStats;
  appendUnitStats(passStats, issue, pipelines, list, sweep, zunit, shading);
  std::vector<bool> matched(st.units.size(), false);
  for (const UnitStats& s : passStats) {
    bool found = false;
    for (std::size_t i = 0; i < st.units.size(); ++i)
      if (st.units[i].name == s.name) {
        st.units[i].busy += s.busy;
        st.units[i].stall += s.stall;
        st.units[i].idle += s.idle;
        st.units[i].items += s.items;
        matched[i] = found = true;
      }
    if (!found) {
      UnitStats n = s;
      n.idle += before;
      st.units.push_back(n);
    }
  }
  for (std::size_t i = 0; i < matched.size(); ++i)
    if (!matched[i]) st.units[i].idle += cycles;
}

}  // namespace qacc
