#include "tools/sweep/sweep_evaluator.h"

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "hw_model/report/accuracy_report.h"
#include "hw_model/report/stats_file.h"
#include "modeling/loader/scene_loader.h"
#include "modeling/tessellation/facet_scene.h"
#include "modeling/tessellation/tessellation.h"
#include "raster/image/png_io.h"
#include "tools/engines/hw_engine.h"
#include "tools/sweep/thumbnail.h"

namespace qacc {

namespace fs = std::filesystem;

SweepEvaluator::SweepEvaluator(std::string engine, int threads, ReferenceCache& cache)
    : engine_(std::move(engine)), threads_(threads), cache_(cache) {}

void SweepEvaluator::setThumbnails(const std::string& outDir, int maxWidth) {
  outDir_ = outDir;
  thumbWidth_ = outDir.empty() ? 0 : maxWidth;
}

const SweepEvaluator::Source& SweepEvaluator::source(const std::string& path) {
  auto it = sources_.find(path);
  if (it != sources_.end()) return it->second;
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open scene");
  std::stringstream ss;
  ss << in.rdbuf();
  Source s;
  s.text = ss.str();
  const fs::path p(path);
  s.dir = p.has_parent_path() ? p.parent_path().string() : ".";
  s.doc = nlohmann::json::parse(s.text, nullptr, false);
  if (s.doc.is_discarded() || !s.doc.is_object() || !s.doc.contains("objects") || !s.doc["objects"].is_array())
    loadScene(path);  // throws the loader's message
  s.name = s.doc.value("name", p.stem().string());
  return sources_.emplace(path, std::move(s)).first->second;
}

void SweepEvaluator::knobColumns(const nlohmann::ordered_json& knobs, nlohmann::ordered_json& row) {
  for (const std::string& k : sceneKnobNames())
    if (k != "scene.size") row[k] = knobs.contains(k) ? knobs[k] : nlohmann::ordered_json("");
}

namespace {

// Sets `key` = value on every object of `type`; refuses a scene that has none.
void patchObjects(nlohmann::json& doc, const std::string& type, const std::string& key, const nlohmann::json& value,
                  const std::string& path, const std::string& knob, bool dropRefine) {
  int n = 0;
  for (auto& o : doc["objects"])
    if (o.is_object() && o.value("type", "") == type) {
      o[key] = value;
      if (dropRefine) o.erase("refine_error");
      ++n;
    }
  if (n == 0) throw std::invalid_argument(path + ": " + knob + " applies to " + type + " objects, and the scene has none");
}

// Whether two frames hold the same colour, depth and objects, bit for bit.
bool sameImage(const FrameBuffer& a, const FrameBuffer& b) {
  return a.width == b.width && a.height == b.height && a.color.data == b.color.data &&
         a.depth.size() == b.depth.size() && a.object.size() == b.object.size() &&
         std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(double)) == 0 &&
         std::memcmp(a.object.data(), b.object.data(), a.object.size() * sizeof(std::int32_t)) == 0;
}

std::size_t imageBytes(const FrameBuffer& f) {
  return f.color.data.size() + f.depth.size() * sizeof(double) + f.object.size() * sizeof(std::int32_t);
}

}  // namespace

nlohmann::ordered_json SweepEvaluator::evaluate(const HwConfig& cfg, const nlohmann::ordered_json& knobs,
                                                const std::string& scenePath, const std::string& thumbName) {
  const Source& src = source(scenePath);
  nlohmann::json doc = src.doc;
  if (knobs.contains("scene.macropatch"))
    patchObjects(doc, "macropatch", "model", knobs["scene.macropatch"], scenePath, "scene.macropatch", false);
  // The truth does not depend on the degree-reduction level (the reference ray-casts the
  // exact surface) nor on the tessellation: the reference is rendered from this text.
  const std::string refText = doc.dump();
  if (knobs.contains("scene.reduction_level"))
    patchObjects(doc, "algebraic", "level", knobs["scene.reduction_level"], scenePath, "scene.reduction_level", true);
  // The scene is culled against the view at the size it is rendered at (view_culling.h).
  ViewCulling view;
  if (knobs.contains("scene.size")) {
    view.width = knobs["scene.size"][0].get<int>();
    view.height = knobs["scene.size"][1].get<int>();
  }
  // The scene as rendered: its text with the knobs applied, its directory (the files it
  // names), the size it is culled at and its tessellation.
  const auto knob = [&](const char* k) { return knobs.contains(k) ? knobs[k].dump() : std::string("-"); };
  const std::string sceneText = knobs.contains("scene.reduction_level") ? doc.dump() : refText;
  const std::string sceneKey = src.dir + "\n" + sceneText + "\n" + knob("scene.size") + "\n" +
                               knob("scene.tessellation_level") + "\n" + knob("scene.tessellation_tolerance");
  // One scene kept per scene file (the last loaded), dropped before another is loaded.
  auto loaded = scenes_.find(scenePath);
  if (loaded != scenes_.end() && loaded->second.first != sceneKey) {
    scenes_.erase(loaded);
    loaded = scenes_.end();
  }
  Scene notKept;  // a scene with no room beside those kept
  const Scene* found = loaded != scenes_.end() ? &loaded->second.second : nullptr;
  if (!found) {
    Scene scene = parseScene(sceneText, scenePath, src.dir, Limits{}, view);
    if (knobs.contains("scene.size")) {
      scene.width = view.width;
      scene.height = view.height;
    }
    if (knobs.contains("scene.tessellation_level") || knobs.contains("scene.tessellation_tolerance")) {
      TessellationOptions to;
      if (knobs.contains("scene.tessellation_level")) to.triangles = knobs["scene.tessellation_level"].get<int>();
      if (knobs.contains("scene.tessellation_tolerance")) to.chord_error = knobs["scene.tessellation_tolerance"].get<double>();
      scene = facetScene(scene, tessellateScene(scene, to));
    }
    const auto bytes = [](const Scene& sc) {
      std::size_t n = 0;
      for (const Primitive& p : sc.primitives) n += sizeof(Primitive) + p.clip.size() * sizeof(HalfSpace);
      return n;
    };
    std::size_t kept = 0;
    for (const auto& [path, entry] : scenes_) kept += bytes(entry.second);
    if (kept + bytes(scene) <= kSceneBytes) {
      found = &scenes_.emplace(scenePath, std::make_pair(sceneKey, std::move(scene))).first->second.second;
    } else {
      notKept = std::move(scene);
      found = &notKept;
    }
  }
  const Scene& scene = *found;
  nlohmann::ordered_json row;
  row["scene"] = src.name;
  row["scene.width"] = scene.width;
  row["scene.height"] = scene.height;
  knobColumns(knobs, row);
  row["primitives"] = scene.primitives.size();

  const int w = scene.width, h = scene.height;
  const std::size_t rendersBefore = cache_.renders();
  const std::string refKey = std::to_string(w) + "x" + std::to_string(h) + "\n" + src.dir + "\n" + refText;
  auto memo = measured_.find(refKey);
  // The reference of a kept measurement is this one (the same text, directory and size: the
  // files it names are read once a run, as the scene's are), without the cache's hashing and
  // reading; colour, depth and objects are all the report and the thumbnails read. Under
  // --no-cache every item renders its reference, and reuses the kept figures only if both
  // frames are the same.
  FrameBuffer fetched;  // the reference from the cache (or rendered), when not the kept one
  const bool fetch = memo == measured_.end() || cache_.disabled();
  if (fetch)
    fetched = cache_.get(refText, src.dir, w, h, [&] { return parseScene(refText, scenePath, src.dir, Limits{}, ViewCulling{true, w, h}); },
                         threads_, false);
  const FrameBuffer* ref = fetch ? &fetched : &memo->second.reference;
  const auto t0 = std::chrono::steady_clock::now();
  HwStats stats;
  reuse_.setScene(scenePath, sceneKey);
  const FrameBuffer fb = renderWithHwEngine(engine_, scene, cfg, threads_, stats, &reuse_);
  const double hostS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const bool reused = memo != measured_.end() && sameImage(memo->second.image, fb) &&
                      (!fetch || sameImage(memo->second.reference, fetched));
  Measured fresh;  // a measurement with no room in the memo
  Measured* measured = reused ? &memo->second : &fresh;
  if (!reused) {
    // This reference's entry is replaced; the new one is kept only if it fits beside the
    // others (when it does not, the entries already kept stay: a sweep cycling through more
    // references than fit still reuses those).
    if (memo != measured_.end()) {
      if (!fetch) {
        fetched = std::move(memo->second.reference);
        ref = &fetched;
      }
      measured_.erase(memo);
    }
    std::size_t kept = 0;
    for (const auto& [k, m] : measured_) kept += imageBytes(m.reference) + imageBytes(m.image);
    if (kept + imageBytes(fetched) + imageBytes(fb) <= measuredBytes_) {
      measured = &measured_[refKey];
      measured->reference = std::move(fetched);
      ref = &measured->reference;
      measured->image = fb;
      measured->image.primitive = {};
    }
    measured->report = accuracyReport(*ref, fb, scene.camera);
  }
  const AccuracyReport& acc = measured->report;
  row["status"] = "ok";
  for (const auto& [k, v] : acc.fields()) row[k] = jsonNumber(v);
  row["caps"] = stats.pixels.caps;
  row["overflows"] = stats.overflow.total();
  row["depth_clamps"] = stats.overflow.depth_clamps;
  row["cycles"] = stats.cycles;
  const double ft = stats.frameSeconds();
  row["frame_ms"] = ft * 1e3;
  row["fps"] = ft > 0 ? 1.0 / ft : 0.0;
  row["gates_kge"] = stats.cost.totalGe() / 1e3;
  row["gates_needed_kge"] = stats.has_needs ? stats.cost_needed.totalGe() / 1e3 : row["gates_kge"].get<double>();
  row["host_seconds"] = hostS;
  row["reference_rendered"] = cache_.renders() > rendersBefore;
  row["accuracy_reused"] = reused;
  row["datapath_reused"] = stats.reused;
  if (thumbWidth_ > 0 && !thumbName.empty()) {
    const fs::path dir = fs::path(outDir_) / "renders";
    fs::create_directories(dir);
    // The same image against the same reference: the same thumbnails, copied.
    const fs::path thumb = dir / (thumbName + ".png"), err = dir / (thumbName + "_err.png");
    if (!measured->thumbnail.empty() && fs::exists(measured->thumbnail) && fs::exists(measured->errorMap)) {
      fs::copy_file(measured->thumbnail, thumb, fs::copy_options::overwrite_existing);
      fs::copy_file(measured->errorMap, err, fs::copy_options::overwrite_existing);
    } else {
      writePng(thumb.string(), thumbnail(fb.color, thumbWidth_));
      writePng(err.string(), errorMapThumbnail(*ref, fb, thumbWidth_));
      measured->thumbnail = thumb.string();
      measured->errorMap = err.string();
    }
    const std::string refName = "reference_" + src.name + "_" + std::to_string(w) + "x" + std::to_string(h) + ".png";
    if (!fs::exists(dir / refName)) writePng((dir / refName).string(), thumbnail(ref->color, thumbWidth_));
    row["reference_thumbnail"] = "renders/" + refName;
    row["thumbnail"] = "renders/" + thumbName + ".png";
    row["error_map"] = "renders/" + thumbName + "_err.png";
  }
  return row;
}

}  // namespace qacc
