// --cache DIR and --no-cache of the commands that print an accuracy line (render, batch):
// where the reference frame it compares with is kept (tools/engines/reference_cache.h).
#pragma once
#include <string>

#include <CLI/CLI.hpp>

namespace qacc {

// `use_cache` and `cache_dir` must outlive the parse (commands keep them in a shared_ptr).
inline void addReferenceCacheOptions(CLI::App* cmd, bool& use_cache, std::string& cache_dir) {
  cmd->add_option("--cache", cache_dir,
                  "Reference cache directory for the accuracy line (default $QACC_CACHE or ~/.cache/qacc)");
  cmd->add_flag("!--no-cache", use_cache, "Render the accuracy line's reference afresh (no reference cache)");
}

}  // namespace qacc
