// --threads N of the commands that draw (render, batch, compare, reduce, sweep, autosize): the
// engines' thread count, and the default of every other parallel loop the command runs (the
// accuracy line's metrics, the modelers while a scene loads), so that `--threads 1` runs on
// one core, as shards under `parallel -j N` expect. Without it, every loop uses all cores.
#pragma once
#include <CLI/CLI.hpp>

namespace qacc {

CLI::Option* addThreadsOption(CLI::App* cmd, int& threads);

}  // namespace qacc
