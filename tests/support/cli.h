#pragma once
// Test support: the gdpn program run as a user runs it, from the source folder.
// Needs GDPN_CLI (the program) and GDPN_SOURCE_DIR defined by the test's target.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace gdpn::testing {

/// What a run of the program gave.
struct CliResult {
  int code = -1;
  std::string out;  // stdout and stderr together
};

/// Runs `commands` (a shell line that may call "$GDPN", the program) in the source folder.
inline CliResult runShell(const std::string& commands) {
  const std::string cmd = std::string("cd '") + GDPN_SOURCE_DIR + "' && GDPN='" + GDPN_CLI + "' && { " + commands +
                          "; } 2>&1";
  CliResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// Runs `gdpn <args>` (shell words) in the source folder.
inline CliResult runGdpn(const std::string& args) { return runShell("\"$GDPN\" " + args); }

}  // namespace gdpn::testing
