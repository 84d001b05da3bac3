// Facts about this build of qacc for self-describing outputs and helper scripts: its version
// (`git describe --always --dirty` of the source tree at build time) and the
// source tree's tools/ folder (where the plotting and composing scripts are).
#pragma once
#include <string>

namespace qacc {

const char* qaccVersion();
// The source tree this qacc was built from (the only file compiled with its path, so that
// the compiler cache serves every other object to any checkout), and its tools/ folder.
std::string qaccSourceDir();
std::string qaccToolsDir();

}  // namespace qacc
