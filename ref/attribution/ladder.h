// A ladder of estimators for one VCT component (docs/attribution.md): rung 0 is the truth (the
// path tracer), the last rung is VCT itself, and each rung in between replaces one approximation
// of VCT by its exact counterpart, on the same pixels, G-buffer and voxel field. Term k is
// rung k - rung k-1, so the terms telescope to the total bias (VCT - truth).
//
// The terms are not read off one set of estimates (that would sum to the total by construction):
// every rung is estimated twice from independent random streams A and B, term k is
// rung_k(A) - rung_{k-1}(B), and the total is rung_K(B) - rung_0(A). Then
//   sum of terms - total = sum_k (rung_k(A) - rung_k(B)),
// a sum of independent zero-mean differences whose standard error is known: the budget checks
// that its terms add up to the total within it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "attribution/rung_image.h"

namespace vct::attr {

struct Rung {
  std::string name;   // e.g. "exact_gathering"
  std::string what;   // one line for readers
  bool deterministic = false;  // estimated once (both streams would give the same image)
  std::function<RungImage(uint32_t stream)> estimate;
};

struct Term {
  std::string name;        // the approximation this step adds, e.g. "voxel_field"
  MeanSe value;            // mean luminance of the difference and its standard error
  RungImage image;         // per-pixel difference (heat maps)
};

struct ComponentBudget {
  std::string component;
  std::vector<std::string> rung_names, rung_whats;
  std::vector<MeanSe> rungs;   // stream A
  std::vector<Term> terms;     // terms[k-1] = rung k - rung k-1 (names: term_names)
  Term total;                  // rung K (B) - rung 0 (A)
  double sum_of_terms = 0.0, sum_se = 0.0;  // sum of the term means and its SE (independent terms)
  double discrepancy = 0.0, discrepancy_se = 0.0;  // sum_of_terms - total, and its SE
  double rounding = 0.0;  // float rounding allowed on top (deterministic rungs have SE 0)
  /// |discrepancy| <= k * discrepancy_se + rounding (k = kSumCheckSigmas).
  bool sums_to_total() const;
};

/// 4 standard errors: a correct estimator fails the sum check with probability 6e-5 (two-sided
/// normal tail); docs/compare.md, "Attribution".
inline constexpr double kSumCheckSigmas = 4.0;

/// Streams of the two independent estimates of every rung.
inline constexpr uint32_t kStreamA = 1, kStreamB = 2;

/// Runs the ladder on the pixels where mask > 0. term_names.size() == rungs.size() - 1.
ComponentBudget run_ladder(const std::string& component, const std::vector<Rung>& rungs,
                           const std::vector<std::string>& term_names, const Image& mask);

}  // namespace vct::attr
