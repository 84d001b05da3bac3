#include "tools/cli/threads_option.h"

#include <omp.h>

#include <string>

namespace qacc {

CLI::Option* addThreadsOption(CLI::App* cmd, int& threads) {
  return cmd->add_option("--threads", threads, "Threads (default: all cores)")
      ->check(CLI::Range(1, 1024))
      ->each([](const std::string& v) {
        int n = 0;  // read as CLI11 reads the option's value (010 is 8, 0x10 is 16)
        if (CLI::detail::lexical_cast(v, n)) omp_set_num_threads(n);
      });
}

}  // namespace qacc
