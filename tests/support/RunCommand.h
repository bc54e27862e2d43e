#pragma once
// Runs the semslam command-line tool from tests and captures its exit code and output.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace semslam::test {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

/// Runs a shell command line, its stderr joined to its stdout.
inline CommandResult runShell(const std::string& commandLine) {
  const std::string command = commandLine + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// Runs `build/bin/semslam ARGUMENTS` through the shell (arguments are passed verbatim: quote paths yourself).
inline CommandResult runSemslam(const std::string& arguments) {
  return runShell(std::string("\"") + SEMSLAM_CLI + "\" " + arguments);
}

}  // namespace semslam::test
