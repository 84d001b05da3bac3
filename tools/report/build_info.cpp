#include "tools/report/build_info.h"

#include "qacc_version.h"  // generated at every build (tools/report/version.cmake)

#ifndef QACC_GIT_VERSION
#define QACC_GIT_VERSION "unknown"
#endif
#ifndef QACC_TOOLS_DIR
#define QACC_TOOLS_DIR "tools"
#endif

namespace qacc {

const char* qaccVersion() { return QACC_GIT_VERSION; }
std::string qaccToolsDir() { return QACC_TOOLS_DIR; }

}  // namespace qacc
