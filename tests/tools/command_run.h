// Running a command from a test of qacc's command line: the shell runs it, the test gets
// its exit status and what it wrote to standard output (add "2>&1" to the command for its
// errors too, "2>&1 >/dev/null" for its errors alone).
#pragma once
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace qacc {

struct CommandRun {
  int status = -1;  // the exit status; -1 when the command did not exit (a signal)
  std::string out;
};

inline CommandRun runCommand(const std::string& cmd) {
  CommandRun r;
  FILE* f = popen(cmd.c_str(), "r");
  if (!f) return r;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) r.out.append(buf, n);
  const int st = pclose(f);
  r.status = st != -1 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// `qacc ARGS` as a shell command: the executable under test, quoted.
inline std::string qaccCommand(const std::string& args) { return "\"" + std::string(QACC_EXE) + "\" " + args; }

}  // namespace qacc
