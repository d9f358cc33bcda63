// Fuzz inputs turned into files: the readers under test take paths, so each input is written to
// a per-process scratch directory first. Shared by the fuzz targets and the regression test
// (tests/ref/fuzz_regression_test.cpp), so a saved crasher is replayed exactly as it was found.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
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

/// True for a binary glTF container (its magic), which takes the .glb file path.
inline bool is_glb(const char* data, size_t size) { return size >= 4 && std::memcmp(data, "glTF", 4) == 0; }

}  // namespace vct::fuzz
