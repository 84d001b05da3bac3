#include "tools/report/python_tool.h"

#include <cstdlib>
#include <filesystem>

#include "tools/report/build_info.h"

namespace qacc {

std::string runPythonTool(const std::string& script, const std::string& dir) {
  const std::string path = qaccToolsDir() + "/" + script;
  if (!std::filesystem::exists(path)) return path + " not found";
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = python + " '" + path + "' '" + dir + "' > /dev/null";
  const int rc = std::system(cmd.c_str());
  if (rc != 0)
    return python + " " + path + " failed (status " + std::to_string(rc) +
           "; its error is printed above; it needs python3-matplotlib)";
  return "";
}

}  // namespace qacc
