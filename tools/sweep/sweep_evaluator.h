// SweepEvaluator: measures one accelerator configuration on one scene with its scene knobs
// applied (the unit of work of `qacc sweep` and `qacc autosize`): the scene is patched
// (scene.macropatch, scene.reduction_level), sized (scene.size), optionally tessellated
// (scene.tessellation_level / _tolerance: its triangles go through the accelerator's
// flat-facet path), rendered with `hw` or `hw-cycle`, and compared with the reference of
// the same scene and size, which comes from the ReferenceCache (rendered once per scene,
// size and content). The row holds the scene knobs, every accuracy figure
// (accuracy_report.h), cycles, modeled frame time and fps, the cost model's gate count,
// the host time, and the paths of the thumbnails when asked for.
#pragma once
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "hw_model/config/hw_config.h"
#include "hw_model/engines/datapath_reuse.h"
#include "hw_model/report/accuracy_report.h"
#include "raster/image/frame_buffer.h"
#include "tools/engines/reference_cache.h"
#include "tools/sweep/sweep_spec.h"

namespace qacc {

class SweepEvaluator {
 public:
  SweepEvaluator(std::string engine, int threads, ReferenceCache& cache);
  // The most bytes of frames kept to reuse an image's accuracy figures (Measured below;
  // default kMeasuredBytes).
  void setMeasuredBytes(std::size_t bytes) { measuredBytes_ = bytes; }
  // Thumbnails of each render and its error map go to DIR/renders/NAME{,_err}.png
  // (maxWidth pixels wide); 0 or an empty DIR: none.
  void setThumbnails(const std::string& outDir, int maxWidth);
  // Throws std::invalid_argument (with the scene file) when a knob does not apply to the scene.
  nlohmann::ordered_json evaluate(const HwConfig& cfg, const nlohmann::ordered_json& knobs,
                                  const std::string& scenePath, const std::string& thumbName = "");
  // Scene knob columns with their values for a row ("" when not set).
  static void knobColumns(const nlohmann::ordered_json& knobs, nlohmann::ordered_json& row);

 private:
  struct Source {
    std::string dir, text, name;
    nlohmann::json doc;
  };
  const Source& source(const std::string& path);
  // The last image measured against each reference (keyed by the reference's scene text,
  // directory and size), with that reference, its accuracy report and the thumbnails written
  // for it: the reference is read from the cache once a run, and a point whose image is the
  // same, bit for bit (colour, depth and objects: what the report reads), reuses the figures
  // and thumbnails instead of measuring again. A sweep over timing knobs (pipelines, FIFOs,
  // banks, latencies) renders the same image at every point, and its accuracy line took more
  // host time than the accelerator engine. At most kMeasuredBytes of frames are kept (an
  // entry's two frames: 31 MB each at 1920x1080): an entry that does not fit beside those kept
  // is not kept (its reference's points are read and measured every time).
  struct Measured {
    FrameBuffer reference, image;  // without their primitive ids
    AccuracyReport report;
    std::string thumbnail, errorMap;  // the files written for it ("" when none)
  };
  static constexpr std::size_t kMeasuredBytes = std::size_t(256) << 20;
  std::map<std::string, Measured> measured_;
  // hw-cycle's setups, pixel traces and frames, one per scene file (the last rendered, with
  // its knobs and size): a point that changes only timing keys renders only the timed passes.
  DatapathReuse reuse_;
  // The scenes as loaded (knobs applied, culled to the view, tessellated), one per scene file
  // with the text it was loaded from (knobs, size, tessellation): a point that changes only
  // the accelerator's configuration does not load its scene again. At most kSceneBytes of
  // primitives are kept; a scene with no room beside those kept is not kept.
  static constexpr std::size_t kSceneBytes = std::size_t(256) << 20;
  std::map<std::string, std::pair<std::string, Scene>> scenes_;
  std::size_t measuredBytes_ = kMeasuredBytes;
  std::string engine_;
  int threads_;
  ReferenceCache& cache_;
  std::string outDir_;
  int thumbWidth_ = 0;
  std::map<std::string, Source> sources_;
};

}  // namespace qacc
