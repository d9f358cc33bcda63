#include "attribution/ladder.h"

#include <cmath>

#include "core/error.h"

namespace vct::attr {

bool ComponentBudget::sums_to_total() const {
  return std::abs(discrepancy) <= kSumCheckSigmas * discrepancy_se + rounding;
}

namespace {

Term make_term(const std::string& name, const RungImage& a, const RungImage& b, const Image& mask) {
  Term t;
  t.name = name;
  t.image = difference(a, b);
  t.value = masked_mean(t.image, mask);
  return t;
}

}  // namespace

ComponentBudget run_ladder(const std::string& component, const std::vector<Rung>& rungs,
                           const std::vector<std::string>& term_names, const Image& mask) {
  if (rungs.size() < 2 || term_names.size() + 1 != rungs.size())
    throw std::logic_error("run_ladder: need K+1 rungs for K terms");
  ComponentBudget b;
  b.component = component;
  std::vector<RungImage> a_images, b_images;
  for (const Rung& r : rungs) {
    b.rung_names.push_back(r.name);
    b.rung_whats.push_back(r.what);
    a_images.push_back(r.estimate(kStreamA));
    b_images.push_back(r.deterministic ? a_images.back() : r.estimate(kStreamB));
    b.rungs.push_back(masked_mean(a_images.back(), mask));
  }
  for (size_t k = 1; k < rungs.size(); ++k)
    b.terms.push_back(make_term(term_names[k - 1], a_images[k], b_images[k - 1], mask));
  b.total = make_term("total", b_images.back(), a_images.front(), mask);
  // The terms share rungs (term k and k+1 both read rung k, from streams A and B), so their
  // errors are independent: each stream of each rung enters one term only.
  double var = 0.0, disc_var = 0.0;
  for (const Term& t : b.terms) {
    b.sum_of_terms += t.value.mean;
    var += t.value.se * t.value.se;
  }
  b.sum_se = std::sqrt(var);
  b.discrepancy = b.sum_of_terms - b.total.value.mean;
  // sum - total = sum_k (rung_k(A) - rung_k(B)): every stream of every rung once.
  for (size_t k = 0; k < rungs.size(); ++k) {
    const double se_a = b.rungs[k].se, se_b = masked_mean(b_images[k], mask).se;
    disc_var += se_a * se_a + se_b * se_b;
  }
  b.discrepancy_se = std::sqrt(disc_var);
  // Each pixel's differences are float subtractions of non-negative radiance (relative error
  // <= 2^-24 of their operands), and each rung's pixels enter at most three of them (two terms and
  // the total), so the rounding in the discrepancy is <= 3 x 2^-24 x sum_k |rung_k|; 2^-20 leaves
  // a factor > 5 (docs/compare.md, "Attribution").
  double magnitude = 0.0;
  for (const MeanSe& r : b.rungs) magnitude += std::abs(r.mean);
  b.rounding = std::ldexp(magnitude, -20);
  return b;
}

}  // namespace vct::attr
