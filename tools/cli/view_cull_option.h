// --no-view-cull, for every command that loads a scene: the loader then models every piece,
// also those whose bounds miss the view (modeling/loader/view_culling.h).
#pragma once
#include <CLI/CLI.hpp>

namespace qacc {

// Adds --no-view-cull to `cmd`; it sets `enabled` to false. `enabled` must outlive the parse.
void addViewCullOption(CLI::App* cmd, bool& enabled);

}  // namespace qacc
