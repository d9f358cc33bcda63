// voxel.radiance (compare/volume_judges.h): the storage and reduction model's bound at each voxel's
// fragment count plus the reference's shading slack (docs/compare.md, "Voxel shading slack").
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/counted_shares.h"
#include "compare/element_loop.h"
#include "compare/rule_masks.h"
#include "compare/tolerance.h"
#include "compare/volume_judges.h"
#include "stages/multibounce.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {
namespace st = stage_names;

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g%%", 100.0 * fraction);
  return buf;
}

// Any of the RGB channels non-zero (a voxel with light, whatever its opacity).
bool carries_light(const Volume& v, size_t i) {
  if (v.channels < 4) return false;
  for (int c = 0; c < 3; ++c)
    if (v.data[i * size_t(v.channels) + size_t(c)] != 0.0f) return true;
  return false;
}

const Volume* same_sized(const StageSet& s, const char* stage, const Volume& like) {
  auto it = s.volumes.find(stage);
  return it != s.volumes.end() && same_size(it->second, like) ? &it->second : nullptr;
}

// What the rule reads from the reference (and the test's fragment counts).
struct RadianceInputs {
  const Volume& ref;
  const Volume& test;
  VoxelModel model;
  const Volume *lo = nullptr, *hi = nullptr;  // the CAS / running-mean interval (both or neither)
  const Volume* slack = nullptr;              // voxel.shading_slack
  const Volume *fragments = nullptr, *test_fragments = nullptr;
  const Volume* exact = nullptr;              // voxel.exact, where it applies
  const Volume* count_range = nullptr;        // voxel.fragment_count_range (lo, hi)
};

RadianceInputs radiance_inputs(const StageSet& rs, const StageSet& ts) {
  RadianceInputs in{rs.volumes.at(st::kVoxelRadiance), ts.volumes.at(st::kVoxelRadiance),
                    voxel_model(ts.storage, ts.reduction, rs.reduction)};
  in.lo = same_sized(rs, st::kVoxelCasLo, in.ref);
  in.hi = same_sized(rs, st::kVoxelCasHi, in.ref);
  if (!in.model.cas_interval || !in.lo || !in.hi) in.lo = in.hi = nullptr;
  // Each voxel's mean may move by its fragments' mean shading slack (docs/compare.md "Voxel shading slack").
  in.slack = same_sized(rs, st::kVoxelShadingSlack, in.ref);
  in.fragments = rs.volumes.count(st::kVoxelFragments) ? &rs.volumes.at(st::kVoxelFragments) : nullptr;
  in.test_fragments = ts.volumes.count(st::kVoxelFragments) ? &ts.volumes.at(st::kVoxelFragments) : nullptr;
  if (in.test_fragments && (!in.fragments || !same_size(*in.test_fragments, in.ref))) in.test_fragments = nullptr;
  // Voxels whose every fragment's light GL computes bit for bit (emission from constants, no light
  // in front, no bounce, no particles) reduce to the same integers and the same half: with the
  // fixed-point reduction and the same fragment count they must be identical (docs/compare.md,
  // "Exact voxels"). Needs the test's fragment counts.
  in.exact = same_sized(rs, st::kVoxelExact, in.ref);
  in.count_range = same_sized(rs, st::kVoxelFragmentCountRange, in.ref);
  if (!in.test_fragments || in.model.cas_interval) in.exact = nullptr;
  return in;
}

float channel0(const Volume* v, size_t i) { return v->data[i * size_t(v->channels)]; }

// A test count the reference's coverage ties admit (voxel.fragment_count_range): derived, so not
// counted against kFragmentCountTieCap. Without the range every differing count is counted.
bool count_within_ties(const RadianceInputs& in, size_t i) {
  if (!in.count_range || in.count_range->channels < 2) return false;
  const float n = channel0(in.test_fragments, i);
  const float* r = in.count_range->data.data() + i * size_t(in.count_range->channels);
  return n >= r[0] && n <= r[1];
}

// Voxel i's worst channel: within the model's bound at its fragment count plus its slack (0 at an
// exact voxel), or, with an interval, within [lo - abs - slack, hi + abs + slack]. A filled voxel
// (opaque with no fragments: solid voxelization, surface thickening) reduced no fragments, so the
// interval of the fragment orders says nothing about it (it holds 0): its value is the fill's, judged
// by the model's bound whatever the reduction (scenes/regressions/seed-27-small).
// `admitted_rgb` receives the sum over RGB of how far the bound lets the test's value lie from the
// reference's (the voxel's term of the energy bound, compare/bounce_frames.h).
WorstChannel radiance_worst(const RadianceInputs& in, size_t i, bool exact_voxel, double& se, double& max_abs,
                            double& admitted_rgb) {
  const double n = in.fragments ? std::max(1.0, double(channel0(in.fragments, i))) : 8.0;
  const bool filled = in.fragments && channel0(in.fragments, i) == 0.0f && in.ref.data[i * size_t(in.ref.channels) +
                                                                                         size_t(in.ref.channels - 1)] > 0.0f;
  const bool interval = in.lo && !filled;
  const VoxelModel& m = in.model;
  return worst_channel(std::min(in.ref.channels, in.test.channels), [&](int c) {
    const size_t k = i * size_t(in.ref.channels) + size_t(c);
    const double r = in.ref.data[k], t = in.test.data[i * size_t(in.test.channels) + size_t(c)];
    const double slack = in.slack && c < 3 ? double(channel0(in.slack, i)) : 0.0;
    double d = std::abs(t - r), bound = exact_voxel ? 0.0 : m.bound(r, n, slack);
    double admitted = bound;
    if (interval) {
      const double l = double(in.lo->data[k]) - m.abs - slack, h = double(in.hi->data[k]) + m.abs + slack;
      d = t < l ? l - t : t > h ? t - h : 0.0;
      bound = m.abs + slack;
      admitted = std::max(h - r, r - l);
    }
    if (c < 3) admitted_rgb += admitted;
    se += (t - r) * (t - r);
    max_abs = std::max(max_abs, std::abs(t - r));
    return ChannelDistance{d, bound, std::abs(t - r)};
  });
}

// The energy (sum of RGB over the base level, stages/multibounce.h total_energy) of both sides and
// how far apart the admitted voxels let them lie: each within-bound voxel its admitted width, each
// voxel a share or the occupancy stage admits its actual difference, each beyond voxel its width.
struct EnergyTally {
  double bound = 0.0;
  std::vector<std::pair<size_t, double>> beyond;  // voxel, its |t - r| over RGB minus its width
  nlohmann::json json(const RadianceInputs& in, const std::vector<Rule>& rules) const {
    double b = bound;
    for (const auto& [i, excess] : beyond)
      if (rules[i] != Rule::Beyond) b += excess;
    return {{"reference", total_energy(in.ref)}, {"test", total_energy(in.test)}, {"bound", b}};
  }
};

double rgb_difference(const Volume& r, const Volume& t, size_t i) {
  double d = 0.0;
  for (int c = 0; c < std::min({3, r.channels, t.channels}); ++c)
    d += std::abs(double(t.data[i * size_t(t.channels) + size_t(c)]) - double(r.data[i * size_t(r.channels) + size_t(c)]));
  return d;
}

struct RadianceCounts {
  size_t count_ties = 0, derived_count_ties = 0, shading_ties = 0, transparent_lit = 0, exact_checked = 0, exact_differ = 0;
  bool too_many_count_ties = false, shading_tolerated = false;
};

void radiance_note(StageVerdict& v, const RadianceInputs& in, const RadianceCounts& n, double share) {
  v.note += std::to_string(v.out_of_bound) + " of " + std::to_string(v.checked) + " voxels beyond the bound (" +
            std::to_string(v.checked - n.transparent_lit) + " occupied in both, " + std::to_string(n.transparent_lit) +
            " transparent with light)";
  if (in.test_fragments) {
    v.note += "; " + std::to_string(n.count_ties + n.derived_count_ties) + " with a different fragment count";
    if (n.derived_count_ties) v.note += " (" + std::to_string(n.derived_count_ties) + " within the coverage ties' count range)";
    if (n.count_ties)
      v.note += "; " + std::to_string(n.count_ties) + " outside it (counted" +
                std::string(n.too_many_count_ties ? ": more than 2%, not ties)" : ", judged within the slack)");
  }
  if (in.exact)
    v.note += "; " + std::to_string(n.exact_differ) + " of " + std::to_string(n.exact_checked) + " exact voxels differ";
  if (n.shading_ties)
    v.note += "; " + std::to_string(n.shading_ties) + " beyond the shading bound" +
              (share <= 0.0 ? std::string(" on the test's own shadow maps (no share: not ties)")
                            : " (shadow-test ties" + std::string(n.shading_tolerated ? ", tolerated up to " : ": more than ") +
                                  percent(share) + (n.shading_tolerated ? ")" : ", not ties)"));
  v.extra["transparent_lit"] = n.transparent_lit;
  v.extra["fragment_count_ties"] = n.count_ties;
  v.extra["fragment_count_ties_derived"] = n.derived_count_ties;
  v.extra["exact_voxels"] = n.exact_checked;
  v.extra["exact_voxels_differing"] = n.exact_differ;
  v.extra["shading_ties"] = n.shading_ties;
}

// The counting policy: shading ties (beyond the bound at a voxel that is not exact) up to the
// context's share (compare/counted_shares.h), fragment-count ties up to their cap.
void decide_radiance(StageVerdict& v, std::vector<Rule>& rules, RadianceCounts& n, double share) {
  n.shading_tolerated = double(n.shading_ties) <= share * double(std::max<size_t>(v.checked, 1));
  n.too_many_count_ties = double(n.count_ties) > kFragmentCountTieCap.fraction * double(std::max<size_t>(v.checked, 1));
  if (!n.shading_tolerated)
    for (Rule& r : rules)
      if (r == Rule::ShadingShare) r = Rule::Beyond;
  for (Rule r : rules) v.admitted.add(r);
  v.allowed = v.admitted[Rule::ShadingShare];
  v.verdict = v.out_of_bound > v.allowed || n.too_many_count_ties ? Verdict::Fail
              : v.allowed                                           ? Verdict::Warn
                                                                    : Verdict::Pass;
}

}  // namespace

StageVerdict compare_radiance(const StageSet& rs, const StageSet& ts, const CompareOptions& opt,
                              const JudgeContext& ctx, Taint& taint) {
  StageVerdict v;
  v.stage = st::kVoxelRadiance;
  const RadianceInputs in = radiance_inputs(rs, ts);
  if (!same_size(in.ref, in.test)) {
    v.verdict = Verdict::Fail;
    v.note = "grid sizes differ";
    return v;
  }
  v.model = in.model.name;
  v.bound = bound_text(in.model);
  if (in.model.cas_interval && !in.lo)
    v.note = "no cas_lo/cas_hi interval in the reference (render it with reduction " + ts.reduction +
             "): judged with +-" + std::to_string(in.model.abs) + " only; ";
  RadianceCounts n;
  const auto ro = occupancy(in.ref), to = occupancy(in.test);
  taint.assign(ro.size(), 0);
  std::vector<Rule> rules(ro.size(), Rule::RadianceWithinBound);
  std::vector<Offender> offenders;
  const size_t explained_index = explained_voxel(opt, in.ref);
  WorstChannel explained;
  double se = 0;
  EnergyTally energy;
  for (size_t i = 0; i < ro.size(); ++i) {
    if (ro[i] != to[i]) {  // occupied on one side only: the occupancy stage judges it
      energy.bound += rgb_difference(in.ref, in.test, i);
      continue;
    }
    // Transparent voxels holding light (the particles' additive light has opacity 0) are judged
    // like occupied ones: a backend that loses that light must fail here, not one stage later.
    if (!ro[i] && !carries_light(in.ref, i) && !carries_light(in.test, i)) continue;
    n.transparent_lit += !ro[i];
    // Different fragment counts: MSAA sample-coverage ties at triangle edges changed the set of
    // fragments averaged. The mean of any set those ties admit is inside the reference's slack
    // (freedoms/coverage_ties.h), so a voxel beyond it is no tie; the count is still capped.
    const bool count_tie = in.test_fragments && channel0(in.fragments, i) != channel0(in.test_fragments, i);
    const bool exact_voxel = in.exact && !count_tie && channel0(in.exact, i) > 0.0f;
    n.exact_checked += exact_voxel;
    double width = 0.0;
    const WorstChannel w = radiance_worst(in, i, exact_voxel, se, v.max_abs, width);
    energy.bound += width;
    if (i == explained_index) explained = w;
    ++v.checked;
    if (count_tie) {
      taint[i] = 1;
      ++(count_within_ties(in, i) ? n.derived_count_ties : n.count_ties);
    }
    if (w.within()) continue;
    energy.beyond.push_back({i, std::max(0.0, rgb_difference(in.ref, in.test, i) - width)});
    ++v.out_of_bound;
    (exact_voxel ? n.exact_differ : n.shading_ties)++;  // an exact voxel has no freedom: never a tie
    rules[i] = exact_voxel ? Rule::Beyond : Rule::ShadingShare;
    taint[i] = 1;
    offenders.push_back(voxel_offender(in.ref, in.test, i, w.error, w.bound));
  }
  v.rms = std::sqrt(se / double(std::max<size_t>(1, v.checked * size_t(std::max(std::min(in.ref.channels, in.test.channels), 1)))));
  decide_radiance(v, rules, n, ctx.shading_tie_fraction);
  radiance_note(v, in, n, ctx.shading_tie_fraction);
  v.extra["energy"] = energy.json(in, rules);
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  explain_voxel(v, in.ref, in.test, explained_index, rules, explained);
  write_volume_rule_mask(opt, v, in.ref, rules);
  return v;
}

}  // namespace vct::cmp
