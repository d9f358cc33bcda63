// voxel.occupancy and voxel.holes (compare/volume_judges.h): exact under the GPU's coverage rule
// except the ties the admission table names (docs/compare.md, the voxel.occupancy row).
#include <algorithm>
#include <cstdio>

#include "compare/counted_shares.h"
#include "compare/fill_ties.h"
#include "compare/rule_masks.h"
#include "compare/volume_judges.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {
namespace st = stage_names;

bool face_neighbour_in(const Volume& v, const std::vector<uint8_t>& set, size_t i) {
  int x, y, z;
  xyz_of(v, i, x, y, z);
  // 26-neighbourhood: a sample on a voxel edge or corner moves diagonally.
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int xx = x + dx, yy = y + dy, zz = z + dz;
        if (v.contains(xx, yy, zz) && set[(size_t(zz) * size_t(v.ny) + size_t(yy)) * size_t(v.nx) + size_t(xx)]) return true;
      }
  return false;
}

// Both sides' occupancy and what differs, with what the rules read.
struct OccupancyDiff {
  explicit OccupancyDiff(const Volume& reference) : ref(reference) {}
  const Volume& ref;
  std::vector<uint8_t> missing, extra;
  const Volume *ref_fragments = nullptr, *test_fragments = nullptr;
  const Volume* coverage_ties = nullptr;  // the reference's voxel.occupancy_tie, when it has one
  std::vector<uint8_t> surface_differs;  // fill_ties.h; empty without both fragment counts
  bool conservative_ref = false;
  size_t occupied = 0;
};

OccupancyDiff diff_of(const StageSet& rs, const StageSet& ts) {
  OccupancyDiff d{rs.volumes.at(st::kVoxelRadiance)};
  const auto ro = occupancy(d.ref), to = occupancy(ts.volumes.at(st::kVoxelRadiance));
  d.missing.assign(ro.size(), 0);
  d.extra.assign(ro.size(), 0);
  for (size_t i = 0; i < ro.size(); ++i) {
    d.occupied += ro[i];
    d.missing[i] = ro[i] && !to[i];
    d.extra[i] = to[i] && !ro[i];
  }
  auto frag_of = [&](const StageSet& s) -> const Volume* {
    auto it = s.volumes.find(st::kVoxelFragments);
    return it != s.volumes.end() && same_size(it->second, d.ref) ? &it->second : nullptr;
  };
  d.ref_fragments = frag_of(rs);
  const auto ties = rs.volumes.find(st::kVoxelOccupancyTie);
  if (ties != rs.volumes.end() && same_size(ties->second, d.ref)) d.coverage_ties = &ties->second;
  d.test_fragments = frag_of(ts);
  // A sample-rule fragment lies on a triangle inside its voxel, so where the counts agree the two
  // sides hold the same triangles (hence the same facing), also against a conservative reference.
  if (d.ref_fragments && d.test_fragments) d.surface_differs = surface_differences(*d.ref_fragments, *d.test_fragments);
  // A conservative reference: the GPU's sample rule must give a SUBSET of it (every covered sample
  // lies on the triangle inside its voxel); missing voxels are holes.
  const auto vz = rs.settings.is_object() ? rs.settings.find("voxelizer") : rs.settings.end();
  d.conservative_ref = vz != rs.settings.end() && *vz == "conservative";
  return d;
}

// The first rule admitting a voxel occupied on one side only. Voxels tie where the reference's
// coverage ties say the voxel's fragments may all drop or one may be added, or (with surface
// thickening alone) that its thickening may change with them (freedoms/coverage_ties.h,
// freedoms/fill_ties.h). Other filled voxels (opaque without fragments: solid interior,
// thickening) have their own rule (compare/fill_ties.h); other surface voxels tie when the side
// that has them held at most 2 fragments (samples on a triangle edge, decided by the fill rule) or
// a voxel differing the other way is among their 26 neighbours (a sample on a face); those three
// are counted (kOccupancyTieCap).
Rule occupancy_rule(const OccupancyDiff& d, size_t i) {
  const bool missing = d.missing[i];
  const Volume* fr = missing ? d.ref_fragments : d.test_fragments;
  const float fragments = fr ? fr->data[i * size_t(fr->channels)] : -1.0f;
  if (d.coverage_ties && d.coverage_ties->data[i * size_t(d.coverage_ties->channels)] > 0.0f) return Rule::CoverageTie;
  if (!d.surface_differs.empty() && fragments == 0.0f)
    return ray_meets(d.ref, d.surface_differs, i) ? Rule::FillRay : Rule::Beyond;
  if (fr && fragments <= 2.0f) return Rule::EdgeFragmentsTie;
  if (face_neighbour_in(d.ref, missing ? d.extra : d.missing, i)) return Rule::FaceNeighbourTie;
  return d.conservative_ref && missing ? Rule::ConservativeHole : Rule::Beyond;
}

std::string occupancy_bound_text(bool conservative_ref) {
  return std::string(conservative_ref
                         ? "no voxel outside the conservative set (except boundary ties); missing voxels are holes (warn)"
                         : "exact, except ties (warn): a voxel the reference's coverage ties let differ "
                           "(voxel.occupancy_tie), and up to 1% of occupied voxels more: a missing voxel with an extra one "
                           "among its 26 neighbours (sample on a voxel face), or a voxel of <= 2 fragments (sample on a "
                           "triangle edge); any other missing or extra voxel fails") +
         "; a filled voxel (opaque, no fragments: solid/thickening) may differ only where an axis ray through it "
         "crosses a surface difference";
}

void occupancy_note(StageVerdict& v, const OccupancyDiff& d, const std::string& backend, size_t missing_n,
                    size_t extra_n, bool too_many_ties) {
  v.note = std::to_string(d.occupied) + " occupied in the reference; " + std::to_string(missing_n) + " missing, " +
           std::to_string(extra_n) + " extra in " + backend + " (" + std::to_string(v.allowed) +
           (d.conservative_ref ? " holes/ties" : " boundary ties") + ")";
  if (too_many_ties) v.note += "; too many to be ties (a shifted grid?)";
}

}  // namespace

StageVerdict compare_occupancy(const StageSet& rs, const StageSet& ts, const CompareOptions& opt, Taint& taint) {
  StageVerdict v;
  v.stage = st::kVoxelOccupancy;
  const Volume& ref = rs.volumes.at(st::kVoxelRadiance);
  const Volume& test = ts.volumes.at(st::kVoxelRadiance);
  if (!same_size(ref, test)) {
    v.verdict = Verdict::Fail;
    v.note = "grid sizes differ: " + std::to_string(ref.nx) + " vs " + std::to_string(test.nx);
    return v;
  }
  const OccupancyDiff d = diff_of(rs, ts);
  v.model = d.conservative_ref ? "subset-of-conservative" : "gpu-rule-exact";
  v.bound = occupancy_bound_text(d.conservative_ref);
  std::vector<Rule> rules(d.missing.size(), Rule::VolumeWithinBound);
  std::vector<Offender> offenders;
  size_t missing_n = 0, extra_n = 0, fill_differences = 0;
  taint.assign(rules.size(), 0);
  for (size_t i = 0; i < rules.size(); ++i) {
    if (!d.missing[i] && !d.extra[i]) continue;
    (d.missing[i] ? missing_n : extra_n)++;
    const Volume* fr = d.missing[i] ? d.ref_fragments : d.test_fragments;
    fill_differences += !d.surface_differs.empty() && fr->data[i * size_t(fr->channels)] == 0.0f;
    taint[i] = 1;
    rules[i] = occupancy_rule(d, i);
    if (rules[i] == Rule::Beyond) offenders.push_back(voxel_offender(ref, test, i, 1.0f, 0.0f));
  }
  for (Rule r : rules) v.admitted.add(r);
  v.checked = rules.size();
  v.out_of_bound = missing_n + extra_n;
  v.allowed = v.out_of_bound - v.admitted[Rule::Beyond];
  v.max_abs = v.out_of_bound ? 1.0 : 0.0;
  // The cap (compare/counted_shares.h): more counted ties than a share of the occupied voxels is a
  // shift. The coverage ties are derived voxel by voxel and not counted.
  const size_t counted = v.allowed - v.admitted[Rule::CoverageTie];
  const bool too_many_ties =
      double(counted) > kOccupancyTieCap.fraction * double(std::max<size_t>(d.occupied, 1)) && !d.conservative_ref;
  v.verdict = v.admitted[Rule::Beyond] || too_many_ties ? Verdict::Fail : v.allowed ? Verdict::Warn : Verdict::Pass;
  occupancy_note(v, d, ts.backend, missing_n, extra_n, too_many_ties);
  if (too_many_ties) {  // every differing voxel fails, and the pairs are listed: the evidence of a shift
    for (size_t i = 0; i < rules.size(); ++i)
      if (d.missing[i] || d.extra[i]) rules[i] = Rule::Beyond;
    for (size_t i = 0; i < rules.size() && offenders.size() < 4 * opt.worst_n; ++i)
      if (d.missing[i] || d.extra[i]) offenders.push_back(voxel_offender(ref, test, i, 1.0f, 0.0f));
    v.admitted = RuleTally();
    for (Rule r : rules) v.admitted.add(r);
  }
  if (fill_differences) v.note += "; " + std::to_string(fill_differences) + " of them filled voxels (solid/thickening)";
  v.extra = {{"occupied_reference", d.occupied}, {"missing", missing_n}, {"extra", extra_n}, {"ties", v.allowed},
             {"fill_differences", fill_differences}};
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  explain_voxel(v, ref, test, explained_voxel(opt, ref), rules, WorstChannel{});
  write_volume_rule_mask(opt, v, ref, rules);
  return v;
}

StageVerdict compare_holes(const StageSet& rs, const StageSet& ts, const CompareOptions& opt) {
  StageVerdict v;
  v.stage = st::kVoxelHoles;
  v.model = "conservative-holes-reported";
  v.bound = "reported, never failed: holes are a property of sample-based voxelization";
  const Volume* cons = rs.volumes.count(st::kVoxelConservative) ? &rs.volumes.at(st::kVoxelConservative) : nullptr;
  if (!cons) cons = ts.volumes.count(st::kVoxelConservative) ? &ts.volumes.at(st::kVoxelConservative) : nullptr;
  if (!cons || !ts.volumes.count(st::kVoxelRadiance)) return missing_stage(v.stage, "no conservative occupancy or no test voxels");
  const Volume& test = ts.volumes.at(st::kVoxelRadiance);
  if (!same_size(*cons, test)) return missing_stage(v.stage, "conservative and test grids differ in size");
  const auto to = occupancy(test);
  std::vector<Rule> rules(to.size(), Rule::VolumeWithinBound);
  size_t holes = 0, cons_n = 0;
  for (size_t i = 0; i < to.size(); ++i) {
    const bool c = cons->data[i * size_t(cons->channels)] > 0.0f;
    cons_n += c;
    if (c && !to[i]) ++holes, rules[i] = Rule::ConservativeHole;
  }
  v.admitted.add(Rule::ConservativeHole, holes);
  v.checked = cons_n;
  v.out_of_bound = holes;
  v.allowed = holes;
  v.verdict = Verdict::Pass;
  char b[160];
  std::snprintf(b, sizeof b, "%zu holes: %.2f%% of the %zu conservatively covered voxels are not occupied in %s", holes,
                cons_n ? 100.0 * double(holes) / double(cons_n) : 0.0, cons_n, ts.backend.c_str());
  v.note = b;
  v.extra = {{"holes", holes}, {"conservative_voxels", cons_n}};
  write_volume_rule_mask(opt, v, *cons, rules);
  return v;
}

}  // namespace vct::cmp
