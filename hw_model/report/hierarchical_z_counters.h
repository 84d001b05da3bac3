// HierarchicalZCounters: what the optional hierarchical Z unit did in a run (HwConfig::
// hierarchical_z; datapath/hierarchical_z_memory.h): the blocks of spans it looked up and
// rejected, their pixels, the primitives it rejected whole, and, in hw-cycle, the pixel
// issue cycles the rejected blocks would have taken less their lookup cycles (an estimate;
// the frame's saving is the difference of two runs, docs/HW_MODEL.md "Hierarchical Z").
// The two engines reject different amounts (hw sees every earlier write at once; in
// hw-cycle a write reaches the tile memory after the Z unit's latency), never different pixels
// of the image.
#pragma once
#include <cstdint>
#include <string>

namespace qacc {

struct HierarchicalZCounters {
  bool enabled = false;
  std::uint64_t blocks_tested = 0;        // blocks of spans (a span's pixels in one tile) looked up
  std::uint64_t blocks_rejected = 0;
  std::uint64_t pixels_rejected = 0;      // pixels of the rejected blocks (never issued to a pipeline)
  std::uint64_t primitives_tested = 0;    // primitives with at least one block looked up
  std::uint64_t primitives_rejected = 0;  // ... all of whose blocks were rejected
  std::uint64_t issue_cycles_saved = 0;   // hw-cycle: the rejected blocks' issue cycles less their lookups
  // A rejected block of n pixels: its pixels, and the issue cycles it would have taken on
  // `pipelines` pipelines less its lookup's `lookupCycles` (both clocks count through this).
  void blockRejected(int n, int pipelines, int lookupCycles) {
    ++blocks_rejected;
    pixels_rejected += std::uint64_t(n);
    const int issueCycles = (n + pipelines - 1) / pipelines;
    if (issueCycles > lookupCycles) issue_cycles_saved += std::uint64_t(issueCycles - lookupCycles);
  }
  // A primitive's end: counted when any of its blocks was looked up, rejected whole when none
  // was accepted.
  void primitiveDone(bool tested, bool accepted) {
    if (!tested) return;
    ++primitives_tested;
    primitives_rejected += !accepted;
  }
  void add(const HierarchicalZCounters& o) {
    blocks_tested += o.blocks_tested;
    blocks_rejected += o.blocks_rejected;
    pixels_rejected += o.pixels_rejected;
    primitives_tested += o.primitives_tested;
    primitives_rejected += o.primitives_rejected;
    issue_cycles_saved += o.issue_cycles_saved;
  }
  // The summary line of `qacc render`.
  std::string line(int tileSize) const {
    return "hierarchical Z (" + std::to_string(tileSize) + "x" + std::to_string(tileSize) + " tiles): " +
           std::to_string(pixels_rejected) + " pixels rejected in " + std::to_string(blocks_rejected) + " of " +
           std::to_string(blocks_tested) + " span blocks, " + std::to_string(primitives_rejected) + " of " +
           std::to_string(primitives_tested) + " primitives rejected whole" +
           (issue_cycles_saved ? "; " + std::to_string(issue_cycles_saved) + " issue cycles saved (estimate)" : "");
  }
};

}  // namespace qacc
