#pragma once
// Test support: a command run as a process through the shell, with a time-out of its own (a
// command that never ends fails its test instead of hanging the suite), its two output streams
// read together.
#include <sys/wait.h>
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

namespace yardsim::testing {

struct ShellResult {
  int status;       // exit status, -1 when killed by a signal
  std::string out;  // stdout and stderr together
};

// (shell command, time-out in s) => its exit status and output; killed after the time-out
inline ShellResult shell(const std::string& command, int timeoutSeconds = 120) {
  const std::string cmd =
      "timeout -s KILL " + std::to_string(timeoutSeconds) + " " + command + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int raw = pclose(p);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

}  // namespace yardsim::testing
