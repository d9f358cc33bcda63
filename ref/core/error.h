// The two kinds of failure the command line maps to exit codes (README.md):
// bad input or usage -> 2, missing environment (e.g. no GL context) -> 3.
#pragma once

#include <stdexcept>
#include <string>

namespace vct {

/// Something the user gave us is wrong. `what()` is one line naming the file and the problem.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& problem)
      : std::runtime_error(file.empty() ? problem : file + ": " + problem) {}
};

/// The machine lacks something we need (GL context, a tool). Exit code 3.
class EnvironmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum ExitCode : int { kExitOk = 0, kExitFailed = 1, kExitBadInput = 2, kExitNoEnvironment = 3 };

}  // namespace vct
