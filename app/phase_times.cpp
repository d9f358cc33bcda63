#include "phase_times.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace vct::app {

double PhaseTimes::render_ms() const {
  double ms = 0.0;
  for (const Phase& p : phases_)
    if (p.render) ms += p.ms;
  return ms;
}

double PhaseTimes::other_ms() const {
  double ms = 0.0;
  for (const Phase& p : phases_)
    if (!p.render) ms += p.ms;
  return ms;
}

nlohmann::json PhaseTimes::to_json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const Phase& p : phases_) list.push_back({{"name", p.name}, {"ms", p.ms}, {"render", p.render}});
  const double r = render_ms(), o = other_ms();
  return {{"phases", list}, {"render_ms", r}, {"other_ms", o}, {"total_ms", r + o}};
}

std::string PhaseTimes::table() const {
  std::string out = "phases (wall clock):\n";
  char line[256];
  for (const Phase& p : phases_) {
    std::snprintf(line, sizeof line, "  %8.2f s  %s%s\n", p.ms / 1000.0, p.name.c_str(), p.render ? "  [render]" : "");
    out += line;
  }
  const double r = render_ms(), o = other_ms();
  std::snprintf(line, sizeof line, "  %8.2f s  total: renders %.2f s, everything else %.2f s (%.0f %% of the renders)\n",
                (r + o) / 1000.0, r / 1000.0, o / 1000.0, r > 0.0 ? 100.0 * o / r : 0.0);
  return out + line;
}

bool add_report_parts(PhaseTimes& phases, const std::string& part_times_json, double report_wall_ms) {
  nlohmann::json j;
  try {
    std::ifstream in(part_times_json);
    if (!in) throw std::runtime_error("missing");
    j = nlohmann::json::parse(in);
  } catch (const std::exception&) {
    phases.add("report", report_wall_ms);
    return false;
  }
  double parts = 0.0;
  for (const auto& p : j.value("parts", nlohmann::json::array())) {
    const double ms = p.value("ms", 0.0);
    phases.add("report: " + p.value("name", std::string("?")), ms);
    parts += ms;
  }
  phases.add("report: start-up and rest", std::max(0.0, report_wall_ms - parts));
  return true;
}

}  // namespace vct::app
