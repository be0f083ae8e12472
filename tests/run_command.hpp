#pragma once

// Runs a program of the build as a user would, for the tests of the command-line tools.

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace tide::testing_support {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // standard output and standard error together
};

/// Runs `program arguments` through the shell and collects its output and exit code (-1 when it
/// did not exit normally).
inline CommandResult run_command(const std::string& program, const std::string& arguments) {
  const std::string command = program + " " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) result.output += buffer;
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace tide::testing_support
