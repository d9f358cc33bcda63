// Per-stage verdicts of a comparison (docs/compare.md) and the report that collects
// them in pipeline order; serialised into run.json["verdicts"].
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/admission.h"

namespace vct::cmp {

enum class Verdict { Pass, Warn, Fail, Missing };
std::string to_string(Verdict v);

/// One pixel (z = -1) or voxel that broke its bound, with both values.
struct Offender {
  std::array<int, 3> at{0, 0, -1};
  std::vector<float> reference, test;
  float error = 0.0f;  // |test - reference| in the worst channel
  float bound = 0.0f;  // the tolerance that applied there
};

struct StageVerdict {
  std::string stage;       // canonical stage name, e.g. "voxel.radiance", "mip.iso.2"
  std::string model;       // tolerance model applied, e.g. "d32f-depth"
  std::string bound;       // the bound in words (with its source in docs/compare.md)
  Verdict verdict = Verdict::Missing;
  size_t checked = 0;      // pixels / voxels compared
  size_t out_of_bound = 0; // beyond the bound (some may be allowed, e.g. edge ties)
  size_t allowed = 0;      // of those, tolerated (edge ties, holes)
  RuleTally admitted;      // per admission rule, the elements it admitted first (compare/admission.h)
  double max_abs = 0.0, rms = 0.0;
  std::vector<Offender> worst;  // worst N, largest error / bound first
  std::string mask;        // error-mask PNG, relative to the run directory (empty if none)
  std::string note;        // one sentence for the human
  nlohmann::json extra = nlohmann::json::object();
};

/// A stage judged missing (one side lacks it, or its inputs), with why.
StageVerdict missing_stage(const std::string& stage, const std::string& why);

struct Report {
  std::vector<StageVerdict> stages;  // pipeline order
  /// First stage that failed (later failures are usually its consequence); empty if none.
  std::string first_failing() const;
  Verdict overall() const;  // Fail if any fail, else Warn if any warn, else Pass
};

nlohmann::json to_json(const StageVerdict& v);
nlohmann::json to_json(const Report& r);

/// Keeps the N worst offenders (by error/bound) from `all` in order.
void keep_worst(std::vector<Offender>& all, size_t n);

}  // namespace vct::cmp
