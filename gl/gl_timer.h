// GPU time per stage from GPU timer queries (timestamp pairs; see gl_timer.cpp). Results are
// collected once at the end so the queries never stall the pipeline mid-frame.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gl_api.h"

namespace vct::gl {

class GpuTimers {
 public:
  /// `finish_each_stage`: glFinish before each stage's closing timestamp (needed by binning CPU
  /// rasterizers such as llvmpipe, see gl_timer.cpp; on a GPU it would hide missing barriers).
  explicit GpuTimers(bool finish_each_stage = true) : finish_(finish_each_stage) {}
  void set_finish_each_stage(bool finish) { finish_ = finish; }
  void begin(const std::string& stage);
  void end();
  /// Waits for every query; stage name -> milliseconds (repeated stages are summed).
  std::map<std::string, double> collect();

 private:
  struct Query {
    std::string stage;
    GLuint begin, end;
  };
  std::vector<Query> queries_;
  bool open_ = false;
  bool finish_ = true;
};

/// begin() in the constructor, end() in the destructor.
class ScopedTimer {
 public:
  ScopedTimer(GpuTimers& t, const std::string& stage) : t_(t) { t_.begin(stage); }
  ~ScopedTimer() { t_.end(); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  GpuTimers& t_;
};

}  // namespace vct::gl
