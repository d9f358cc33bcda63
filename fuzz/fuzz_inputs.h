// Fuzz inputs turned into files: the readers under test take paths, so each input is written to
// a per-process scratch directory first. Shared by the fuzz targets and the regression tests
// (tests/ref/fuzz_regression_test.cpp, tests/compare/stage_set_fuzz_regression_test.cpp,
// tests/cli/scene_compare_fuzz_regression_test.cpp), so a saved crasher is replayed exactly as
// it was found.
#pragma once

#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace vct::fuzz {

/// Separates the files of a stage-set input: manifest, then v.nrrd, then i.exr.
constexpr char kFileSeparator[] = "\n--VCT-FUZZ-FILE--\n";
constexpr const char* kStageSetFiles[] = {"vct-stages.json", "v.nrrd", "i.exr"};

inline std::filesystem::path scratch_dir() {
  static const std::filesystem::path dir = [] {
    auto p = std::filesystem::temp_directory_path() / ("vct_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  // Removed at a normal exit: fork mode starts a process (so a directory) per job.
  static const bool removed_at_exit = std::atexit([] {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }) == 0;
  (void)removed_at_exit;
  return dir;
}

inline std::string write_scratch(const std::string& name, const char* data, size_t size) {
  const auto p = scratch_dir() / name;
  std::ofstream(p, std::ios::binary | std::ios::trunc).write(data, std::streamsize(size));
  return p.string();
}

/// Splits `bytes` at kFileSeparator into at most three parts and writes them under their names
/// (missing parts are not written; earlier files of those names are removed).
inline void write_stage_set_files(const std::string& bytes) {
  const std::string sep = kFileSeparator;
  size_t start = 0;
  for (int part = 0; part < 3; ++part) {
    const auto path = scratch_dir() / kStageSetFiles[part];
    std::filesystem::remove(path);
    if (start > bytes.size()) continue;
    size_t end = bytes.find(sep, start);
    if (end == std::string::npos || part == 2) end = bytes.size();
    std::ofstream(path, std::ios::binary).write(bytes.data() + start, std::streamsize(end - start));
    start = end + sep.size();
  }
}

/// scene_compare_fuzz: a manifest, then any number of named files, each part after a separator
/// starting with its file name and a newline (e.g. "gbuffer_normal.exr\n<bytes>"): a whole small
/// run dir in one input. Names other than [A-Za-z0-9._-]{1,64} not starting with '.' are not
/// written (they would leave the directory). The directory is emptied first so no file of an
/// earlier input is read. Returns the directory (holding vct-stages.json).
inline std::filesystem::path write_named_stage_set(const std::string& bytes) {
  const auto dir = scratch_dir() / "named_stage_set";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto safe = [](const std::string& name) {
    if (name.empty() || name.size() > 64 || name[0] == '.') return false;
    for (char c : name)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) return false;
    return true;
  };
  const std::string sep = kFileSeparator;
  for (size_t start = 0, part = 0; start <= bytes.size(); ++part) {
    size_t end = bytes.find(sep, start);
    if (end == std::string::npos) end = bytes.size();
    const std::string body = bytes.substr(start, end - start);
    start = end + sep.size();
    std::string name = "vct-stages.json";
    size_t data = 0;
    if (part > 0) {
      const size_t nl = body.find('\n');
      name = body.substr(0, nl);
      data = nl == std::string::npos ? body.size() : nl + 1;
    }
    if (!safe(name)) continue;
    std::ofstream(dir / name, std::ios::binary | std::ios::trunc).write(body.data() + data, std::streamsize(body.size() - data));
  }
  return dir;
}

/// True for a binary glTF container (its magic), which takes the .glb file path.
inline bool is_glb(const char* data, size_t size) { return size >= 4 && std::memcmp(data, "glTF", 4) == 0; }

}  // namespace vct::fuzz
