// The accuracy line's reference frame (issue 16): `render` and `batch` read it from the
// reference cache when the scene's content, size and reference version match, render it
// otherwise, and the accuracy line is the same either way.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "modeling/loader/scene_loader.h"
#include "raster/reference/reference_renderer.h"
#include "tools/engines/reference_cache.h"
#include "tools/engines/render_job.h"

namespace fs = std::filesystem;
using namespace qacc;

namespace {

fs::path tempDir() {
  static fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("qacc_accuracy_reference_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

fs::path writeScene(const std::string& name, double radius) {
  const fs::path p = tempDir() / name;
  std::ofstream(p) << R"({"format": "qacc-scene/1", "image": {"width": 48, "height": 36},
  "camera": {"eye": [0, 0, 8], "target": [0, 0, 0]},
  "lights": [{"type": "directional", "direction": [-1, -1, -1]}],
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": )"
                   << radius << R"(}, {"type": "cylinder", "base": [1.5, -1.5, 0], "top": [1.5, 1.5, 0],
  "radius": 0.4, "solid": true}]})";
  return p;
}

RenderJob hwJob(const fs::path& scene) {
  RenderJob job;
  job.scene_path = scene.string();
  job.engine = "hw";
  job.options.threads = 1;
  job.cache_dir = (tempDir() / "cache").string();
  return job;
}

std::string cacheNote(const RenderJobResult& r) {
  for (const auto& n : r.result.notes)
    if (n.rfind("accuracy reference: ", 0) == 0) return n;
  return "";
}

}  // namespace

TEST(AccuracyReference, SecondRenderReadsTheCacheAndPrintsTheSameAccuracy) {
  const fs::path scene = writeScene("a.json", 1.0);
  const RenderJobResult first = runRenderJob(hwJob(scene));
  const RenderJobResult second = runRenderJob(hwJob(scene));
  EXPECT_NE(cacheNote(first).find("rendered into"), std::string::npos) << cacheNote(first);
  EXPECT_NE(cacheNote(second).find("read from"), std::string::npos) << cacheNote(second);
  RenderJob fresh = hwJob(scene);
  fresh.use_cache = false;
  fresh.cache_dir.clear();
  const RenderJobResult uncached = runRenderJob(fresh);
  EXPECT_EQ(cacheNote(uncached), "");
  ASSERT_FALSE(first.result.accuracy.empty());
  EXPECT_EQ(first.result.accuracy, second.result.accuracy);
  EXPECT_EQ(first.result.accuracy, uncached.result.accuracy);
}

TEST(AccuracyReference, AChangedSceneOrSizeIsNeverServedAStaleFrame) {
  const fs::path scene = writeScene("b.json", 1.0);
  const RenderJobResult before = runRenderJob(hwJob(scene));
  writeScene("b.json", 2.0);  // same file name, bigger sphere
  const RenderJobResult after = runRenderJob(hwJob(scene));
  EXPECT_NE(cacheNote(after).find("rendered into"), std::string::npos) << cacheNote(after);
  EXPECT_GT(after.result.fb.covered(), before.result.fb.covered());
  // Served the old frame, the accuracy line would count the grown sphere as spurious pixels.
  RenderJob fresh = hwJob(scene);
  fresh.use_cache = false;
  fresh.cache_dir.clear();
  EXPECT_EQ(after.result.accuracy, runRenderJob(fresh).result.accuracy);
  EXPECT_NE(after.result.accuracy, before.result.accuracy);
  RenderJob resized = hwJob(scene);
  resized.width = 64;
  resized.height = 48;
  const RenderJobResult r = runRenderJob(resized);
  EXPECT_NE(cacheNote(r).find("rendered into"), std::string::npos) << cacheNote(r);
}

TEST(AccuracyReference, CacheOptionsWithoutAnAccuracyLineAreRefused) {
  const fs::path scene = writeScene("c.json", 1.0);
  RenderJob ref = hwJob(scene);
  ref.engine = "reference";
  EXPECT_THROW(runRenderJob(ref), std::invalid_argument);
  RenderJob off = hwJob(scene);
  off.options.report_accuracy = false;
  EXPECT_THROW(runRenderJob(off), std::invalid_argument);
  off.cache_dir.clear();
  off.use_cache = false;
  EXPECT_THROW(runRenderJob(off), std::invalid_argument);
  off.use_cache = true;
  EXPECT_NO_THROW(runRenderJob(off));
}

TEST(AccuracyReference, FrameFileReadWithOrWithoutPrimitiveIds) {
  const fs::path scene = writeScene("d.json", 1.0);
  const FrameBuffer ref = renderReference(loadScene(scene.string()), 1);
  const std::string path = (tempDir() / "d.frame").string();
  writeFrameBuffer(path, ref);
  FrameBuffer all, lean;
  ASSERT_TRUE(readFrameBuffer(path, all));
  ASSERT_TRUE(readFrameBuffer(path, lean, false));
  for (const FrameBuffer* f : {&all, &lean}) {
    EXPECT_EQ(f->width, ref.width);
    EXPECT_EQ(f->height, ref.height);
    EXPECT_EQ(f->color.data, ref.color.data);
    EXPECT_TRUE(std::equal(f->depth.begin(), f->depth.end(), ref.depth.begin(), ref.depth.end()));
    EXPECT_TRUE(std::equal(f->object.begin(), f->object.end(), ref.object.begin(), ref.object.end()));
  }
  EXPECT_TRUE(std::equal(all.primitive.begin(), all.primitive.end(), ref.primitive.begin(), ref.primitive.end()));
  EXPECT_TRUE(lean.primitive.empty());
  // A file shorter or longer than its header says is refused either way.
  const auto size = fs::file_size(path);
  for (const std::uintmax_t wrong : {size - 1, size + 1}) {
    const std::string bad = (tempDir() / "bad.frame").string();
    fs::copy_file(path, bad, fs::copy_options::overwrite_existing);
    fs::resize_file(bad, wrong);
    FrameBuffer f;
    EXPECT_FALSE(readFrameBuffer(bad, f)) << wrong;
    EXPECT_FALSE(readFrameBuffer(bad, f, false)) << wrong;
  }
}

TEST(AccuracyReference, TheCachedReferenceOfTheAccuracyLineHasNoPrimitiveIds) {
  const fs::path scene = writeScene("e.json", 1.0);
  const RenderJob job = hwJob(scene);
  runRenderJob(job);  // stores the frame
  ReferenceCache cache(job.cache_dir);
  const std::string text = readSceneText(scene.string()), dir = sceneDirectory(scene.string());
  const auto never = []() -> Scene { throw std::logic_error("the frame should come from the cache"); };
  const FrameBuffer lean = cache.get(text, dir, 48, 36, never, 1, false);
  const FrameBuffer all = cache.get(text, dir, 48, 36, never, 1);
  EXPECT_EQ(cache.hits(), 2u);
  EXPECT_TRUE(lean.primitive.empty());
  EXPECT_EQ(all.primitive.size(), all.pixels());
  EXPECT_EQ(lean.color.data, all.color.data);
}
