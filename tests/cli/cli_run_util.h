// Helpers for the CLI tests that run the real `vct` binary in a subprocess and compare the files
// it writes byte for byte (determinism_cli_test.cpp, kill_resume_test.cpp).
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace vct::test {

namespace fs = std::filesystem;

/// This process's scratch root under the system temp dir, removed when the process exits.
inline const fs::path& scratch_root() {
  struct Root {
    fs::path path = fs::temp_directory_path() / ("vct_cli_" + std::to_string(::getpid()));
    ~Root() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const Root root;
  return root.path;
}

/// A fresh (emptied) directory under scratch_root().
inline fs::path fresh_dir(const std::string& name) {
  const fs::path p = scratch_root() / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

/// Starts `VCT_BINARY args...` with stdout to /dev/null and stderr to `err`; returns its pid.
inline pid_t spawn_vct(const std::vector<std::string>& args, const std::string& err = "/dev/null") {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(null, 1);
    ::dup2(e, 2);
    std::vector<char*> argv{const_cast<char*>(VCT_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(VCT_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

/// Runs `VCT_BINARY args` with `env` prefixed (e.g. "LP_NUM_THREADS=2"), output discarded.
inline int run_vct(const std::string& args, const std::string& env = "") {
  const std::string cmd = env + " '" + VCT_BINARY + "' " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// What one `vct` run printed, and its exit code.
struct VctOutput {
  int exit_code = -1;
  std::string out, err;
};

/// Runs `VCT_BINARY args`, keeping stdout and stderr (files under scratch_root()).
inline VctOutput run_vct_captured(const std::string& args) {
  const fs::path o = scratch_root() / "vct_stdout.txt", e = scratch_root() / "vct_stderr.txt";
  fs::create_directories(scratch_root());
  const std::string cmd = "'" + std::string(VCT_BINARY) + "' " + args + " >'" + o.string() + "' 2>'" + e.string() + "'";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(o), slurp(e)};
}

/// Every regular file below `dir` (relative path -> bytes), leaving out run.json (timings,
/// thread counts) and anything whose name matches `skip` (a substring) if given.
inline std::map<std::string, std::string> files_below(const fs::path& dir, const std::string& skip = "") {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = fs::relative(e.path(), dir).string();
    if (e.path().filename() == "run.json") continue;
    if (!skip.empty() && rel.find(skip) != std::string::npos) continue;
    out[rel] = slurp(e.path());
  }
  return out;
}

/// Names of files that differ or exist on one side only ("" if the two sets are identical).
inline std::string differences(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
  std::string d;
  for (const auto& [k, v] : a) {
    const auto it = b.find(k);
    if (it == b.end()) d += " missing:" + k;
    else if (it->second != v) d += " differs:" + k;
  }
  for (const auto& [k, v] : b)
    if (!a.count(k)) d += " extra:" + k;
  return d;
}

}  // namespace vct::test
