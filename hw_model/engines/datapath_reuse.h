// DatapathReuse: what hw-cycle computes from the scene and the configuration's datapath
// alone, kept from one render to the next: the setup arithmetic (FrameSetup), the pixel trace
// (every issued pixel's datapath result, pixel_trace.h) and the resolved frame with the
// winners it was shaded from. A render of the same scene under a configuration that differs
// only in timing keys (isHwTimingKey: clock, bus, FIFOs, pipelines, clip evaluators, banks,
// latencies, radices, the hierarchical Z unit's tiles) computes the same setups and the same
// trace bit for bit (the clip passes aside: PixelTrace::retime), so it takes them from here
// and runs only what timing decides: the timed main pass (Z tests included) and the CSG pass.
// Its winners are the same too (the image does not depend on timing: the engines' tests),
// and its frame is taken from here only after checking that, record for record; otherwise it
// is shaded (no test has seen it happen). A sweep over timing knobs (sweeps/parallelism.json)
// thus models each point's cycles without computing its pixels again.
//
// The caller names the scene (setScene, required before a render): a slot (a scene file, say)
// and its content, where equal contents must mean the same primitives, lights, camera and
// background; the engine adds the image size and the datapath key (hwDatapathKey). One
// entry per slot: the last render of that slot that computed its own (a render that reuses
// the entry leaves it; one that does not match drops it before computing its own); at most
// maxBytes of entries are kept (an entry that does not fit beside those kept is not kept;
// one whose frame-sized arrays alone do not fit is not even built: mayKeep). HwStats::reused
// says what a render took from here; the sweep shows it as the column datapath_reused. Not
// thread-safe: one render at a time uses a store.
#pragma once
#include <cstddef>
#include <map>
#include <memory>
#include <string>

#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/zbuffer_memory.h"
#include "hw_model/engines/frame_setup.h"
#include "hw_model/engines/pixel_trace.h"
#include "raster/image/frame_buffer.h"

namespace qacc {

class DatapathReuse {
 public:
  static constexpr std::size_t kDefaultBytes = std::size_t(256) << 20;
  explicit DatapathReuse(std::size_t maxBytes = kDefaultBytes) : maxBytes_(maxBytes) {}
  // The scene of the renders that follow: its slot and its content.
  void setScene(std::string slot, std::string content) {
    slot_ = std::move(slot);
    content_ = std::move(content);
    named_ = true;
  }

  struct Entry {
    std::string scene;      // the content and size of the scene it was computed for
    std::string datapath;   // hwDatapathKey of the configuration it was computed under
    FrameSetup setup;
    PixelTrace trace;       // filled, of the main pass's setups (the csg objects' leaves hidden)
    ZBufferMemory winners{0, 0};  // after the main and the CSG passes
    FrameBuffer frame;      // resolved from `winners`
    std::uint64_t distinct = 0;  // HwStats::distinct_written of that frame
    std::size_t bytes() const;   // approximate: the frame-sized arrays, the trace, the setups, the ROMs
  };
  // The slot's entry if it holds this scene at this size under cfg's datapath; otherwise
  // null, and the slot's entry is dropped.
  Entry* find(int width, int height, const HwConfig& cfg);
  // Whether an entry of this size could fit beside those kept (its frame-sized arrays alone:
  // when they do not, the render keeps nothing and frees its trace as without a store).
  bool mayKeep(int width, int height) const;
  // Keeps `e`, computed for this scene at this size under cfg, in the slot, if it fits.
  void keep(int width, int height, const HwConfig& cfg, Entry&& e);
  std::size_t entries() const { return entries_.size(); }

 private:
  std::string scene(int width, int height) const;  // throws std::logic_error before setScene
  std::size_t otherSlotsBytes() const;             // the entries kept for the other slots
  std::string slot_, content_;
  bool named_ = false;
  std::size_t maxBytes_;
  std::map<std::string, std::unique_ptr<Entry>> entries_;
};

}  // namespace qacc
