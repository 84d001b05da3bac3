#include "tools/cli/threads_option.h"

#include <omp.h>

#include <string>

namespace qacc {

CLI::Option* addThreadsOption(CLI::App* cmd, int& threads) {
  return cmd->add_option("--threads", threads, "Threads (default: all cores)")
      ->check(CLI::Range(1, 1024))
      ->each([](const std::string& v) { omp_set_num_threads(std::stoi(v)); });
}

}  // namespace qacc
