// Wall-clock and CPU time of each phase of a command (load, each render, each write, each
// comparison, the report's parts), in the order they ran, so a user sees where a validate run
// spends its time (docs/performance.md, "Where validate's time goes"). Renders are tagged so the
// share of everything else can be stated. CPU time (all threads, and child processes once waited
// for: the report) tells work from waiting on a shared machine, where wall time swings 2-4x.
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
  double cpu_ms = -1.0;  // CPU time of the process and its waited-for children; < 0: not measured
  // Ran beside others inside a group phase (its CPU: its own thread's); the group is counted in
  // the totals, not its members.
  bool concurrent = false;
};

/// CPU time so far of the calling thread, in ms.
double thread_cpu_ms();

/// CPU time so far of this process (all threads) and of its children already waited for, in ms.
double process_cpu_ms();

class PhaseTimes {
 public:
  void add(const std::string& name, double ms, bool render = false, double cpu_ms = -1.0) {
    phases_.push_back({name, ms, render, cpu_ms, false});
  }
  /// A task that ran inside the group phase added just before it.
  void add_concurrent(const std::string& name, double ms, double cpu_ms) {
    phases_.push_back({name, ms, false, cpu_ms, true});
  }

  /// Runs f, records its wall and CPU time under `name`, returns what f returns.
  template <class F>
  auto time(const std::string& name, F&& f, bool render = false) -> decltype(f()) {
    Stopwatch sw;
    struct Record {  // records on every exit, also when f throws
      PhaseTimes& self;
      const std::string& name;
      Stopwatch& sw;
      bool render;
      double cpu0 = process_cpu_ms();
      ~Record() { self.add(name, sw.ms(), render, process_cpu_ms() - cpu0); }
    } record{*this, name, sw, render};
    return f();
  }

  double render_ms() const;
  double other_ms() const;
  /// CPU time of the renders / of everything else (phases not measured count 0).
  double render_cpu_ms() const;
  double other_cpu_ms() const;
  const std::vector<Phase>& phases() const { return phases_; }

  /// {"phases": [{name, ms, cpu_ms, render, concurrent}], "render_ms", "other_ms", "total_ms",
  /// "render_cpu_ms", "other_cpu_ms"} (cpu_ms absent where not measured; concurrent only when true).
  nlohmann::json to_json() const;
  /// One line per phase ("  12.30 s   20.10 s  name": wall, CPU) and closing lines with the
  /// render / other split in wall and CPU time.
  std::string table() const;

 private:
  std::vector<Phase> phases_;
};

/// Report part times written by report/make_report.py into REPORT_DIR/part_times.json
/// ({"parts": [{"name", "ms", "cpu_ms"}], "total_ms"}), added as "report: NAME" phases; the rest
/// of the report's wall and CPU time (Python start-up, imports, writing) as "report: start-up and
/// rest". Returns false (and adds nothing but the total) when the file is missing or unreadable.
bool add_report_parts(PhaseTimes& phases, const std::string& part_times_json, double report_wall_ms,
                      double report_cpu_ms = -1.0);

}  // namespace vct::app
