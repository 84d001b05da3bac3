// Runs one of the matplotlib scripts in the source tree's tools/ on an output directory
// (`tools/compose_side_by_side.py DIR`, `tools/plot_crossover.py DIR`) with the system
// python3, which has Debian's python3-matplotlib (a python3 earlier on PATH, e.g. pyenv's,
// may not).
#pragma once
#include <string>

namespace qacc {

// Returns "" when the script ran and exited 0, else why not (the caller says how to run it).
std::string runPythonTool(const std::string& script, const std::string& dir);

}  // namespace qacc
