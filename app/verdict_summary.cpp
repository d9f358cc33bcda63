#include "verdict_summary.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "stages/stage_registry.h"

namespace vct::app {

namespace {
int severity(cmp::Verdict v) {
  switch (v) {
    case cmp::Verdict::Fail: return 3;
    case cmp::Verdict::Warn: return 2;
    case cmp::Verdict::Pass: return 1;
    case cmp::Verdict::Missing: return 0;
  }
  return 0;
}
// Mip levels fold into their chain ("mip.iso.*"); other families (shadow maps) stay per member.
std::string family(const std::string& stage) {
  const auto ref = find_stage(stage);
  if (!ref || ref->row->index != StageIndex::MipLevel) return stage;
  return std::string(ref->row->name) + ".*";
}

// The rules that admitted elements beyond their bound (and how many none admitted), most first.
void print_admitted(const cmp::StageVerdict& s) {
  std::vector<std::pair<size_t, cmp::Rule>> counts;
  for (const cmp::AdmissionRow& row : cmp::admission_table())
    if (!cmp::within_bound_rule(row.rule) && s.admitted[row.rule] > 0) counts.push_back({s.admitted[row.rule], row.rule});
  if (counts.empty()) return;
  std::stable_sort(counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string text;
  for (const auto& [n, rule] : counts) text += (text.empty() ? "" : ", ") + cmp::rule_name(rule) + " " + std::to_string(n);
  std::printf("       admitted by: %s\n", text.c_str());
}
}  // namespace

void print_verdicts(const cmp::Report& report, const std::string& title) {
  std::printf("%s: %s", title.c_str(), cmp::to_string(report.overall()).c_str());
  const std::string first = report.first_failing();
  if (!first.empty()) std::printf("  (first failing stage: %s)", first.c_str());
  std::printf("\n");
  // Fold mips: keep the worst level of each pyramid.
  std::vector<std::string> order;
  std::map<std::string, const cmp::StageVerdict*> worst;
  for (const auto& s : report.stages) {
    const std::string f = family(s.stage);
    auto it = worst.find(f);
    if (it == worst.end()) order.push_back(f), worst[f] = &s;
    else if (severity(s.verdict) > severity(it->second->verdict)) it->second = &s;
  }
  for (const auto& f : order) {
    const cmp::StageVerdict& s = *worst[f];
    const char* mark = s.verdict == cmp::Verdict::Fail ? "FAIL" : s.verdict == cmp::Verdict::Warn ? "warn"
                       : s.verdict == cmp::Verdict::Pass ? "pass" : "  - ";
    std::printf("  %-4s %-26s %s\n", mark, (f == s.stage ? f : f + " (" + s.stage.substr(s.stage.rfind('.') + 1) + ")").c_str(),
                s.note.substr(0, 90).c_str());
    if (s.verdict == cmp::Verdict::Warn || s.verdict == cmp::Verdict::Fail) print_admitted(s);
    if (s.verdict == cmp::Verdict::Fail && !s.worst.empty()) {
      const cmp::Offender& o = s.worst.front();
      std::printf("       worst at (%d,%d%s): ref", o.at[0], o.at[1], o.at[2] >= 0 ? (", " + std::to_string(o.at[2])).c_str() : "");
      for (float v : o.reference) std::printf(" %.5g", double(v));
      std::printf("  test");
      for (float v : o.test) std::printf(" %.5g", double(v));
      std::printf("  (bound %.3g)\n", double(o.bound));
    }
  }
}

void print_bias(const std::vector<cmp::BiasComponent>& bias) {
  std::printf("VCT vs path tracer (reference = PT, relMSE eps = %.2g):\n", cmp::kRelMseEpsilon);
  std::printf("  %-20s %10s %11s %7s  %s\n", "component", "relMSE", "rel. bias", "SSIM", "noise-aware judgement");
  for (const auto& b : bias) {
    if (!b.available) {
      std::printf("  %-20s %s\n", b.component.c_str(), b.note.c_str());
      continue;
    }
    std::printf("  %-20s %10.4g %+10.2f%% %7.3f  %s\n", b.component.c_str(), b.metrics.rel_mse, 100 * b.metrics.relative_bias,
                b.metrics.ssim, b.note.substr(0, 80).c_str());
  }
}

}  // namespace vct::app
