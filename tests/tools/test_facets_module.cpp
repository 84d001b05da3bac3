// The facets engine's renderer is a module the qacc executable loads on demand
// (raster/osmesa/facets_module.h): the executable itself needs no Mesa, and a missing module
// is a clear error, not a crash.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "raster/osmesa/osmesa_renderer.h"
#include "tests/tools/command_run.h"

namespace fs = std::filesystem;

namespace {

// A shell command's exit status and its output, standard error included.
qacc::CommandRun shell(const std::string& cmd) { return qacc::runCommand(cmd + " 2>&1"); }

fs::path tempDir() {
  const fs::path d = fs::temp_directory_path() / ("qacc_facets_module_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

}  // namespace

// Mesa (libOSMesa, and through it libLLVM, z3 and ICU) is not among the libraries the
// executable needs: every command but the facets engine starts without it.
TEST(FacetsModule, TheExecutableDoesNotNeedMesa) {
  const qacc::CommandRun r = shell("readelf -d \"" + std::string(QACC_EXE) + "\"");
  ASSERT_EQ(r.status, 0) << r.out;
  ASSERT_NE(r.out.find("(NEEDED)"), std::string::npos) << r.out;  // the listing was read
  for (const char* lib : {"libOSMesa", "libGL", "libLLVM", "libopencsg", "libGLEW"})
    EXPECT_EQ(r.out.find(lib), std::string::npos) << lib << " is linked into qacc:\n" << r.out;
}

// The module beside the executable draws; without it, the facets engine says what is missing.
TEST(FacetsModule, LoadedFromTheExecutablesDirectoryOrAClearError) {
  if (!qacc::facetRendererAvailable()) GTEST_SKIP() << "built without OSMesa";
  const fs::path dir = tempDir();
  const std::string scene = std::string(QACC_SOURCE_DIR) + "/scenes/gallery.json";
  const std::string args = " render \"" + scene + "\" --engine facets --width 64 --height 48 -o \"";
  const qacc::CommandRun ok = shell("\"" + std::string(QACC_EXE) + "\"" + args + (dir / "with.png").string() + "\"");
  EXPECT_EQ(ok.status, 0) << ok.out;
  EXPECT_TRUE(fs::exists(dir / "with.png"));

  const fs::path lone = dir / "lone";
  fs::create_directories(lone);
  fs::copy_file(QACC_EXE, lone / "qacc", fs::copy_options::overwrite_existing);
  const qacc::CommandRun missing =
      shell("\"" + (lone / "qacc").string() + "\"" + args + (dir / "without.png").string() + "\"");
  EXPECT_EQ(missing.status, 1) << missing.out;
  EXPECT_NE(missing.out.find("qacc: error: facets: cannot load the facets engine's module"), std::string::npos)
      << missing.out;
  EXPECT_NE(missing.out.find("libqacc_facets.so"), std::string::npos) << missing.out;
  EXPECT_FALSE(fs::exists(dir / "without.png"));
  // compare draws the facets last: the missing module is reported before anything is rendered.
  const qacc::CommandRun cmp = shell("\"" + (lone / "qacc").string() + "\" compare \"" + scene + "\" --width 64 --height 48 --out \"" +
                                 (dir / "cmp").string() + "\"");
  EXPECT_EQ(cmp.status, 1) << cmp.out;
  EXPECT_NE(cmp.out.find("libqacc_facets.so"), std::string::npos) << cmp.out;
  EXPECT_EQ(cmp.out.find("hw-cycle"), std::string::npos) << "rendered before the module was loaded:\n" << cmp.out;
  // Every other engine runs from the lone executable.
  const qacc::CommandRun hw = shell("\"" + (lone / "qacc").string() + "\" render \"" + scene +
                           "\" --engine hw --no-accuracy --width 64 --height 48 -o \"" + (dir / "hw.png").string() + "\"");
  EXPECT_EQ(hw.status, 0) << hw.out;
  fs::remove_all(dir);
}
