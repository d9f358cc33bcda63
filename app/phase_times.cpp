#include "phase_times.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "io/bounded_json.h"

namespace vct::app {

namespace {
double rusage_ms(int who) {
  rusage u{};
  if (getrusage(who, &u) != 0) return 0.0;
  return 1e3 * (double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec));
}

std::string seconds_or_dash(double ms) {
  char b[32];
  if (ms < 0.0) return "       -";
  std::snprintf(b, sizeof b, "%6.2f s", ms / 1000.0);
  return b;
}
}  // namespace

double process_cpu_ms() { return rusage_ms(RUSAGE_SELF) + rusage_ms(RUSAGE_CHILDREN); }

double thread_cpu_ms() { return rusage_ms(RUSAGE_THREAD); }

double PhaseTimes::render_cpu_ms() const {
  double ms = 0.0;
  for (const Phase& p : phases_)
    if (p.render && !p.concurrent) ms += std::max(0.0, p.cpu_ms);
  return ms;
}

double PhaseTimes::other_cpu_ms() const {
  double ms = 0.0;
  for (const Phase& p : phases_)
    if (!p.render && !p.concurrent) ms += std::max(0.0, p.cpu_ms);
  return ms;
}

double PhaseTimes::render_ms() const {
  double ms = 0.0;
  for (const Phase& p : phases_)
    if (p.render && !p.concurrent) ms += p.ms;
  return ms;
}

double PhaseTimes::other_ms() const {
  double ms = 0.0;
  for (const Phase& p : phases_)
    if (!p.render && !p.concurrent) ms += p.ms;
  return ms;
}

nlohmann::json PhaseTimes::to_json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const Phase& p : phases_) {
    nlohmann::json j = {{"name", p.name}, {"ms", p.ms}, {"render", p.render}};
    if (p.cpu_ms >= 0.0) j["cpu_ms"] = p.cpu_ms;
    if (p.concurrent) j["concurrent"] = true;
    list.push_back(j);
  }
  const double r = render_ms(), o = other_ms();
  return {{"phases", list},       {"render_ms", r},
          {"other_ms", o},        {"total_ms", r + o},
          {"render_cpu_ms", render_cpu_ms()}, {"other_cpu_ms", other_cpu_ms()}};
}

std::string PhaseTimes::table() const {
  std::string out = "phases (wall clock; CPU = all threads and child processes):\n      wall       CPU\n";
  char line[320];
  for (const Phase& p : phases_) {
    // A group's members are indented: they ran side by side, their times overlap.
    std::snprintf(line, sizeof line, "  %8.2f s  %s  %s%s%s\n", p.ms / 1000.0, seconds_or_dash(p.cpu_ms).c_str(),
                  p.concurrent ? "  | " : "", p.name.c_str(), p.render ? "  [render]" : "");
    out += line;
  }
  const double r = render_ms(), o = other_ms(), rc = render_cpu_ms(), oc = other_cpu_ms();
  std::snprintf(line, sizeof line,
                "  %8.2f s  %6.2f s  total: renders %.2f s, everything else %.2f s (%.0f %% of the renders)\n"
                "  CPU time: renders %.2f s, everything else %.2f s (%.0f %% of the renders)\n",
                (r + o) / 1000.0, (rc + oc) / 1000.0, r / 1000.0, o / 1000.0, r > 0.0 ? 100.0 * o / r : 0.0,
                rc / 1000.0, oc / 1000.0, rc > 0.0 ? 100.0 * oc / rc : 0.0);
  return out + line;
}

bool add_report_parts(PhaseTimes& phases, const std::string& part_times_json, double report_wall_ms,
                      double report_cpu_ms) {
  nlohmann::json listed;
  try {
    const nlohmann::json j = read_bounded_json_file(part_times_json, "report part times");
    if (j.is_object()) listed = j.value("parts", nlohmann::json::array());
    if (!listed.is_array()) throw std::runtime_error("no parts");
  } catch (const std::exception&) {
    phases.add("report", report_wall_ms, false, report_cpu_ms);
    return false;
  }
  double parts = 0.0, parts_cpu = 0.0;
  bool cpu_known = report_cpu_ms >= 0.0;
  for (const auto& p : listed) {
    if (!p.is_object()) continue;
    const double ms = p.value("ms", 0.0), cpu = p.value("cpu_ms", -1.0);
    const auto name = p.find("name");
    phases.add("report: " + (name != p.end() && name->is_string() ? name->get<std::string>() : std::string("?")), ms,
               false, cpu);
    parts += ms;
    parts_cpu += std::max(0.0, cpu);
    cpu_known = cpu_known && cpu >= 0.0;
  }
  phases.add("report: start-up and rest", std::max(0.0, report_wall_ms - parts), false,
             cpu_known ? std::max(0.0, report_cpu_ms - parts_cpu) : -1.0);
  return true;
}

}  // namespace vct::app
