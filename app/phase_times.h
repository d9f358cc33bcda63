// Wall-clock time of each phase of a command (load, each render, each write, each comparison, the
// report's parts), in the order they ran, so a user sees where a validate run spends its time
// (docs/performance.md, "Where validate's time goes"). Renders are tagged so the share of
// everything else can be stated.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/run_dir.h"

namespace vct::app {

struct Phase {
  std::string name;
  double ms = 0.0;
  bool render = false;  // a backend rendering (the work the run exists for)
};

class PhaseTimes {
 public:
  void add(const std::string& name, double ms, bool render = false) { phases_.push_back({name, ms, render}); }

  /// Runs f, records its wall time under `name`, returns what f returns.
  template <class F>
  auto time(const std::string& name, F&& f, bool render = false) -> decltype(f()) {
    Stopwatch sw;
    struct Record {  // records on every exit, also when f throws
      PhaseTimes& self;
      const std::string& name;
      Stopwatch& sw;
      bool render;
      ~Record() { self.add(name, sw.ms(), render); }
    } record{*this, name, sw, render};
    return f();
  }

  double render_ms() const;
  double other_ms() const;
  const std::vector<Phase>& phases() const { return phases_; }

  /// {"phases": [{name, ms, render}], "render_ms", "other_ms", "total_ms"}.
  nlohmann::json to_json() const;
  /// One line per phase ("  12.3 s  name") and a closing line with the render / other split.
  std::string table() const;

 private:
  std::vector<Phase> phases_;
};

/// Report part times written by report/make_report.py into REPORT_DIR/part_times.json
/// ({"parts": [{"name", "ms"}], "total_ms"}), added as "report: NAME" phases; the rest of the
/// report's wall time (Python start-up, imports, writing) as "report: start-up and rest".
/// Returns false (and adds nothing but the total) when the file is missing or unreadable.
bool add_report_parts(PhaseTimes& phases, const std::string& part_times_json, double report_wall_ms);

}  // namespace vct::app
