// A run directory (docs/pipeline.md): images, volumes and run.json. Everything needed to rebuild the
// report lives here; every file is written atomically.
//
// The directory a command is asked to write (--out) is a "run": while a process writes it, it
// holds an exclusive lock on <dir>/.vct-lock, so a second process writing the same --out is
// refused with one line instead of interleaving files; and until the command finishes, the file
// INCOMPLETE says so (run.json "status": "incomplete"), so a run killed midway (kill -9, a full
// disk) is told from a finished one. Rerunning the command finishes it (issue 19, docs/report.md).
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/image.h"
#include "core/volume.h"

namespace vct {

/// File names a run keeps beside its outputs.
inline constexpr const char* kRunLockFile = ".vct-lock";
inline constexpr const char* kIncompleteMarker = "INCOMPLETE";

/// Part: a folder inside a run (ref/, pt/ ...), written by the process that holds the run.
/// Run: the directory of a command's --out: locked, and INCOMPLETE until finish().
enum class RunRole { Part, Run };

class RunLock;

class RunDir {
 public:
  /// Creates `path` (and parents) if missing. Throws InputError if it exists as a file, cannot
  /// be written (read-only), or (Run) another process is writing it.
  explicit RunDir(std::string path, RunRole role = RunRole::Part);
  ~RunDir();
  RunDir(const RunDir&) = default;
  RunDir& operator=(const RunDir&) = default;

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
  /// Starts json() from the run.json already in the directory, so a command writing into another
  /// command's run (vct pathtrace into a validate run, vct compare --out into a run) keeps its
  /// sections. An unreadable run.json is simply replaced.
  void keep_existing_json();
  /// Records a stage time in run.json["timings_ms"][backend][stage].
  void add_timing(const std::string& backend, const std::string& stage, double ms);
  /// Writes run.json (atomically); call whenever a consistent state is reached. A Run's
  /// run.json carries "status": "incomplete" until finish().
  void save() const;
  /// A Run is done: run.json says "status": "complete" and INCOMPLETE is removed.
  void finish();

 private:
  std::string path_;
  nlohmann::json json_;
  RunRole role_ = RunRole::Part;
  bool finished_ = false;
  std::shared_ptr<RunLock> lock_;
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

/// Runs `work` and adds its wall time to timings[name] (a frame's per-stage timings).
template <class Work>
void timed(std::map<std::string, double>& timings, const std::string& name, Work&& work) {
  const Stopwatch sw;
  work();
  timings[name] += sw.ms();
}

/// Machine and library versions for run.json["environment"].
nlohmann::json environment_info();

}  // namespace vct
