// Facts about this build of qacc for self-describing outputs and helper scripts: its version
// (`git describe --always --dirty` of the source tree at build time) and the
// source tree's tools/ folder (where the plotting and composing scripts are).
#pragma once
#include <string>

namespace qacc {

const char* qaccVersion();
std::string qaccToolsDir();

}  // namespace qacc
