#include "tools/report/build_info.h"

#include "qacc_version.h"  // generated at every build (tools/report/version.cmake)

#ifndef QACC_GIT_VERSION
#define QACC_GIT_VERSION "unknown"
#endif
#ifndef QACC_SOURCE_DIR
#define QACC_SOURCE_DIR "."
#endif

namespace qacc {

const char* qaccVersion() { return QACC_GIT_VERSION; }
std::string qaccSourceDir() { return QACC_SOURCE_DIR; }
std::string qaccToolsDir() { return qaccSourceDir() + "/tools"; }

}  // namespace qacc
