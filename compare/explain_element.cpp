#include "compare/explain_element.h"

namespace vct::cmp {

bool explains(const CompareOptions& opt, int x, int y, int z) {
  if (opt.explain.size() < 2) return false;
  const int ez = opt.explain.size() >= 3 ? opt.explain[2] : -1;
  return opt.explain[0] == x && opt.explain[1] == y && ez == z;
}

void record_explained(StageVerdict& v, Rule rule, const std::array<int, 3>& at, const std::vector<float>& reference,
                      const std::vector<float>& test, const WorstChannel& worst) {
  const AdmissionRow& row = admission_row(rule);
  nlohmann::json where = at[2] < 0 ? nlohmann::json{at[0], at[1]} : nlohmann::json{at[0], at[1], at[2]};
  v.extra["explain"] = {{"at", where},        {"rule", row.name},          {"kind", to_string(row.kind)},
                        {"reference", reference}, {"test", test},          {"error", worst.error},
                        {"bound", worst.bound},   {"derived_in", row.doc}};
}

}  // namespace vct::cmp
