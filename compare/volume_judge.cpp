// Plain volumes and the shared voxel helpers of the volume judges (compare/volume_judges.h).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/element_loop.h"
#include "compare/explain_element.h"
#include "compare/rule_masks.h"
#include "compare/volume_judges.h"

namespace vct::cmp {

bool same_size(const Volume& a, const Volume& b) { return a.nx == b.nx && a.ny == b.ny && a.nz == b.nz; }

std::vector<uint8_t> occupancy(const Volume& v) {
  std::vector<uint8_t> occ(v.voxel_count());
  for (size_t i = 0; i < occ.size(); ++i)
    occ[i] = (v.channels >= 4 ? v.data[i * size_t(v.channels) + 3] : v.data[i * size_t(v.channels)]) > 0.0f ? 1 : 0;
  return occ;
}

void xyz_of(const Volume& v, size_t i, int& x, int& y, int& z) {
  x = int(i % size_t(v.nx));
  y = int((i / size_t(v.nx)) % size_t(v.ny));
  z = int(i / (size_t(v.nx) * size_t(v.ny)));
}

Offender voxel_offender(const Volume& ref, const Volume& test, size_t i, float err, float bound) {
  Offender o;
  int x, y, z;
  xyz_of(ref, i, x, y, z);
  o.at = {x, y, z};
  for (int c = 0; c < ref.channels; ++c) o.reference.push_back(ref.voxel(x, y, z)[c]);
  for (int c = 0; c < test.channels; ++c) o.test.push_back(test.voxel(x, y, z)[c]);
  o.error = err;
  o.bound = bound;
  return o;
}

size_t explained_voxel(const CompareOptions& opt, const Volume& v) {
  if (opt.explain.size() != 3 || !v.contains(opt.explain[0], opt.explain[1], opt.explain[2])) return size_t(-1);
  return (size_t(opt.explain[2]) * size_t(v.ny) + size_t(opt.explain[1])) * size_t(v.nx) + size_t(opt.explain[0]);
}

void explain_voxel(StageVerdict& v, const Volume& ref, const Volume& test, size_t i, const std::vector<Rule>& rules,
                   const WorstChannel& worst) {
  if (i >= rules.size()) return;
  const Offender o = voxel_offender(ref, test, i, worst.error, worst.bound);
  record_explained(v, rules[i], o.at, o.reference, o.test, worst);
}

StageVerdict compare_volume_plain(const std::string& stage, const Volume& ref, const Volume& test, double abs, double rel,
                                  const CompareOptions& opt) {
  return compare_volume_masked(stage, ref, test, abs, rel, opt, nullptr);
}

StageVerdict compare_volume_masked(const std::string& stage, const Volume& ref, const Volume& test, double abs,
                                   double rel, const CompareOptions& opt, const Taint* tolerated,
                                   const std::vector<float>* extra_abs) {
  StageVerdict v;
  v.stage = stage;
  v.model = "volume-abs-rel";
  char b[120];
  std::snprintf(b, sizeof b, "|d| <= %.3g + %.3g |ref|", abs, rel);
  v.bound = b;
  if (!same_size(ref, test)) {
    v.verdict = Verdict::Fail;
    v.note = "volume sizes differ";
    return v;
  }
  std::vector<Rule> rules(ref.voxel_count(), Rule::VolumeWithinBound);
  std::vector<Offender> offenders;
  const size_t explained_index = explained_voxel(opt, ref);
  WorstChannel explained;
  const int ch = std::min(ref.channels, test.channels);
  double se = 0;
  for (size_t i = 0; i < ref.voxel_count(); ++i) {
    const double slack = extra_abs && i < extra_abs->size() ? double((*extra_abs)[i]) : 0.0;
    const WorstChannel w = worst_channel(ch, [&](int c) {
      const double r = ref.data[i * size_t(ref.channels) + size_t(c)], t = test.data[i * size_t(test.channels) + size_t(c)];
      const double d = std::abs(t - r);
      se += d * d;
      v.max_abs = std::max(v.max_abs, std::isfinite(d) ? d : 1e30);
      return ChannelDistance{d, abs + rel * std::abs(r) + slack, d};
    });
    ++v.checked;
    if (explained_index == i) explained = w;
    if (w.within()) continue;
    ++v.out_of_bound;
    const bool tied = tolerated && i < tolerated->size() && (*tolerated)[i];
    rules[i] = tied ? Rule::AboveUpstreamTie : Rule::Beyond;
    if (tied) continue;
    offenders.push_back(voxel_offender(ref, test, i, w.error, w.bound));
  }
  for (Rule r : rules) v.admitted.add(r);
  v.allowed = v.admitted[Rule::AboveUpstreamTie];
  v.rms = std::sqrt(se / double(std::max<size_t>(1, v.checked * size_t(std::max(ch, 1)))));
  v.verdict = v.out_of_bound > v.allowed ? Verdict::Fail : v.allowed ? Verdict::Warn : Verdict::Pass;
  v.note = std::to_string(v.out_of_bound) + " of " + std::to_string(v.checked) + " voxels beyond the bound";
  if (v.allowed) v.note += " (" + std::to_string(v.allowed) + " above voxels that tie upstream)";
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  explain_voxel(v, ref, test, explained_index, rules, explained);
  write_volume_rule_mask(opt, v, ref, rules);
  return v;
}

}  // namespace vct::cmp
