// What the checkpoint and partial-sums tests share: a scratch directory removed afterwards, and
// the small render they resume, split and merge (20x16, depth 5, a fixed seed).
#pragma once

#include <filesystem>
#include <string>

#include "core/settings.h"

namespace vct::pt::test {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name) : path(std::filesystem::temp_directory_path() / ("vct_pt_test_" + name)) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string str() const { return path.string(); }
  std::string file(const std::string& f) const { return (path / f).string(); }
};

inline Settings settings_with(int spp, uint32_t seed = 1) {
  Settings s;
  s.pt.width = 20;
  s.pt.height = 16;
  s.pt.spp = spp;
  s.pt.seed = seed;
  s.pt.max_depth = 5;
  return s;
}

}  // namespace vct::pt::test
