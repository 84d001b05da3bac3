// qacc command line (design §7): render, batch, info and the commands registered in
// tools/commands.h. Errors print one line "qacc: error: ..." and exit with status 1.
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <cstdio>
#include <exception>

#include "tools/cli/commands.h"

int main(int argc, char** argv) {
#ifdef __GLIBC__
  // The main thread's heap keeps the memory it frees: glibc maps no block on its own (a freed
  // mapping goes back to the kernel) and never trims the heap. So the second and later frames
  // of bench, batch and sweep reuse the frame-sized buffers' pages already touched, where they
  // took fresh pages the kernel zeroed first (docs/PERFORMANCE.md "Freed memory kept"); every
  // engine's frame is timed in that same state. Worker threads' arenas keep glibc's own rules
  // (a block larger than an arena's heap is still mapped). The price: a freed block no later
  // one fits stays in the heap, so a single render's peak is a few MB higher (PERFORMANCE.md).
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, -1);
#endif
  CLI::App app{"qacc - emulator of the LIFL quadric display accelerator"};
  app.require_subcommand(1);
  qacc::addRenderCommand(app);
  qacc::addBatchCommand(app);
  qacc::addInfoCommand(app);
  qacc::addCompareCommand(app);
  qacc::addReduceCommand(app);
  qacc::addBenchCommand(app);
  qacc::addBenchLoadCommand(app);
  qacc::addSweepCommand(app);
  qacc::addAutosizeCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help (and CLI11's other "successes") print as CLI11 wants; every command-line error is
    // one "qacc: error:" line and exit status 1, like every other error.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "qacc: error: %s (see qacc --help)\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "qacc: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
