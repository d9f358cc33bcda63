// A run directory (docs/pipeline.md): images, volumes and run.json. Everything needed to rebuild the
// report lives here; every file is written atomically.
#pragma once

#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

#include "core/image.h"
#include "core/volume.h"

namespace vct {

class RunDir {
 public:
  /// Creates `path` (and parents) if missing. Throws InputError if it exists as a file.
  explicit RunDir(std::string path);

  const std::string& path() const { return path_; }
  std::string file(const std::string& relative) const;

  /// <name>.exr (linear) + <name>.png (tone-mapped, exposure applied).
  void write_color(const std::string& name, const Image& img, float exposure = 1.0f);
  /// <name>.exr + <name>.png mapping [lo, hi] linearly to grey (depth, masks, counts).
  void write_data(const std::string& name, const Image& img, float lo, float hi);
  /// <name>.nrrd + <name>.png slice montage.
  void write_volume(const std::string& name, const Volume& vol, float spacing, float exposure = 1.0f);

  /// run.json content; callers add sections freely ("stages", "metrics", "verdicts", ...).
  nlohmann::json& json() { return json_; }
  /// Records a stage time in run.json["timings_ms"][backend][stage].
  void add_timing(const std::string& backend, const std::string& stage, double ms);
  /// Writes run.json (atomically); call whenever a consistent state is reached.
  void save() const;

 private:
  std::string path_;
  nlohmann::json json_;
};

/// Wall-clock stopwatch for stage timings.
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// Machine and library versions for run.json["environment"].
nlohmann::json environment_info();

}  // namespace vct
