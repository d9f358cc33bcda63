#include "verdict.h"

#include "compare/rule_masks.h"

#include <algorithm>

namespace vct::cmp {

std::string to_string(Verdict v) {
  switch (v) {
    case Verdict::Pass: return "pass";
    case Verdict::Warn: return "warn";
    case Verdict::Fail: return "fail";
    case Verdict::Missing: return "missing";
  }
  return "missing";
}

StageVerdict missing_stage(const std::string& stage, const std::string& why) {
  StageVerdict v;
  v.stage = stage;
  v.verdict = Verdict::Missing;
  v.note = why;
  return v;
}

std::string Report::first_failing() const {
  for (const auto& s : stages)
    if (s.verdict == Verdict::Fail) return s.stage;
  return "";
}

Verdict Report::overall() const {
  bool warn = false, any = false;
  for (const auto& s : stages) {
    if (s.verdict == Verdict::Fail) return Verdict::Fail;
    warn = warn || s.verdict == Verdict::Warn;
    any = any || s.verdict != Verdict::Missing;
  }
  if (!any) return Verdict::Missing;
  return warn ? Verdict::Warn : Verdict::Pass;
}

static double ratio(const Offender& o) {
  return o.bound > 0 ? double(o.error / o.bound) : 1e30 * double(o.error);
}

void keep_worst(std::vector<Offender>& all, size_t n) {
  // Stable order for equal ratios (coordinates) keeps the output identical run after run.
  auto worse = [](const Offender& a, const Offender& b) {
    const double ra = ratio(a), rb = ratio(b);
    if (ra != rb) return ra > rb;
    return a.at < b.at;
  };
  if (all.size() > n) {
    std::partial_sort(all.begin(), all.begin() + long(n), all.end(), worse);
    all.resize(n);
  } else {
    std::sort(all.begin(), all.end(), worse);
  }
}

nlohmann::json to_json(const StageVerdict& v) {
  nlohmann::json worst = nlohmann::json::array();
  for (const auto& o : v.worst) {
    nlohmann::json at = o.at[2] < 0 ? nlohmann::json{o.at[0], o.at[1]} : nlohmann::json{o.at[0], o.at[1], o.at[2]};
    worst.push_back({{"at", at}, {"reference", o.reference}, {"test", o.test}, {"error", o.error}, {"bound", o.bound}});
  }
  return {{"stage", v.stage},       {"verdict", to_string(v.verdict)}, {"model", v.model},
          {"bound", v.bound},       {"checked", v.checked},            {"out_of_bound", v.out_of_bound},
          {"allowed", v.allowed},   {"admitted_by", v.admitted.json()}, {"max_abs", v.max_abs},
          {"rms", v.rms},
          {"worst", worst},         {"mask", v.mask},                  {"note", v.note},
          {"extra", v.extra}};
}

nlohmann::json to_json(const Report& r) {
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& s : r.stages) stages.push_back(to_json(s));
  return {{"overall", to_string(r.overall())},
          {"first_failing", r.first_failing()},
          {"stages", stages},
          {"mask_legend", mask_legend()}};
}

}  // namespace vct::cmp
