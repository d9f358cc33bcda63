#include "compare/bounce_frames.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "compare/isolated_stages.h"
#include "compare/volume_judges.h"
#include "stages/multibounce.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {
namespace st = stage_names;

StageVerdict* find_verdict(Report& r, const std::string& stage) {
  for (StageVerdict& v : r.stages)
    if (v.stage == stage) return &v;
  return nullptr;
}

std::string frame_stage(int k) { return stage_name(stage_row(st::kVoxelFrame), k); }

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// The test's side of one frame: its header (storage, reduction, facts), the frame's base level and
// its fragment counts (the voxelization is the same in every frame).
StageSet test_frame_set(const StageSet& test_set, const Volume& frame) {
  StageSet ts = stage_set_without_stages(test_set);  // no copy of the stages it drops
  ts.volumes[st::kVoxelRadiance] = frame;
  const auto fragments = test_set.volumes.find(st::kVoxelFragments);
  if (fragments != test_set.volumes.end()) ts.volumes[st::kVoxelFragments] = fragments->second;
  return ts;
}

// Frame k of `frames` judged by voxel.radiance's rules against the reference's frame k injected on
// the test's own inputs (`bounce_input`: the test's frame k - 1, none for frame 1).
StageVerdict judge_frame(int k, int frames, const VoxelInjection& injection, const Volume* bounce_input,
                         const Volume& test_frame, const FrameResult& test, const VctSettings& s,
                         const StageSet& test_set, const CompareOptions& opt) {
  FrameResult r;
  r.backend = "ref-on-" + test.backend + "-frame-" + std::to_string(k);
  r.facts = test.facts;  // the reduction the test declares, as voxel.radiance's re-judgement has it
  r.voxels = injection.frame(bounce_input);
  Taint taint;
  StageVerdict v = compare_radiance(stage_set_from_frame(r, s), test_frame_set(test_set, test_frame), opt,
                                    voxels_on_own_inputs_context(s), taint);
  v.stage = frame_stage(k);
  v.note = "frame " + std::to_string(k) + " of " + std::to_string(frames) + " on the test's own shadow maps" +
           (k >= 2 ? " and its own frame " + std::to_string(k - 1) : std::string(" (no bounce light yet)")) + ": " +
           v.note;
  v.extra["frame"] = k;
  return v;
}

struct FrameEnergy {
  int frame = 0;
  double test = 0.0, reference = 0.0, bound = 0.0;
  size_t voxels = 0;
};

// A frame's energies from its radiance verdict (extra["energy"], compare/radiance_judge.cpp); the
// test's as it reported it when it did (run.json's multibounce_energy), else its volume's sum.
std::optional<FrameEnergy> frame_energy(const StageVerdict& v, int k, const FrameResult& test, size_t frames,
                                        size_t voxels) {
  if (!v.extra.contains("energy")) return std::nullopt;
  const nlohmann::json& e = v.extra["energy"];
  FrameEnergy f{k, e.value("test", 0.0), e.value("reference", 0.0), e.value("bound", 0.0), voxels};
  if (test.multibounce_energy.size() == frames) f.test = test.multibounce_energy[size_t(k) - 1];
  return f;
}

StageVerdict judge_energy(const std::vector<FrameEnergy>& frames) {
  StageVerdict v;
  v.stage = st::kVoxelEnergy;
  v.model = "energy-sum-of-voxel-bounds";
  v.bound = "per frame |E_test - E_ref| <= the sum over the voxels of their admitted widths + the double sums' "
            "rounding (E: total RGB of the base level; ref: the frame re-injected on the test's own previous frame)";
  v.extra["frames"] = nlohmann::json::array();
  std::string first_beyond, listed;
  for (const FrameEnergy& f : frames) {
    const double d = std::abs(f.test - f.reference);
    const double bound = f.bound + energy_summation_allowance(f.voxels, f.reference, f.test);
    const bool within = d <= bound;
    ++v.checked;
    v.admitted.add(within ? Rule::EnergyWithinBound : Rule::Beyond);
    v.max_abs = std::max(v.max_abs, d);
    if (!within) {
      ++v.out_of_bound;
      if (first_beyond.empty()) first_beyond = std::to_string(f.frame);
    }
    listed += (listed.empty() ? "" : "; ") + std::string("frame ") + std::to_string(f.frame) + ": " + number(f.test) +
              " vs " + number(f.reference) + " (bound " + number(bound) + (within ? ")" : ", beyond)");
    v.extra["frames"].push_back({{"frame", f.frame},
                                 {"test", f.test},
                                 {"reference_on_test_inputs", f.reference},
                                 {"bound", bound},
                                 {"within", within}});
  }
  v.verdict = v.checked == 0 ? Verdict::Missing : v.out_of_bound > 0 ? Verdict::Fail : Verdict::Pass;
  v.note = (first_beyond.empty() ? "" : "first frame beyond its bound: " + first_beyond + "; ") + listed;
  if (!first_beyond.empty()) v.extra["first_failing_frame"] = std::stoi(first_beyond);
  return v;
}

void replace(Report& rep, StageVerdict v) {
  if (StageVerdict* slot = find_verdict(rep, v.stage)) *slot = std::move(v);
}

}  // namespace

double energy_summation_allowance(size_t voxels, double reference, double test) {
  const double n = 3.0 * double(voxels);
  return n > 1.0 ? (n - 1.0) * std::ldexp(1.0, -53) * (std::abs(reference) + std::abs(test)) : 0.0;
}

namespace {
// voxel.radiance's voxel count: the test set's, where validate moved the frame's grid into it
// (compare/stage_set.h, stage_set_taking_voxels); the frame's otherwise. Both are the same grid.
size_t radiance_voxels(const FrameResult& test, const StageSet& test_set) {
  const auto it = test_set.volumes.find(st::kVoxelRadiance);
  return it != test_set.volumes.end() ? it->second.voxel_count() : test.voxels.radiance.voxel_count();
}
}  // namespace

void judge_bounce_frames(Report& end_to_end, const Scene& scene, const FrameResult& test, const VctSettings& s,
                         const StageSet& test_set, const CompareOptions& opt) {
  const size_t frames = test.multibounce_frames.size() + 1;
  if (frames < 2 || s.bounces < 2) return;
  if (s.reduction == Reduction::RunningMeanHalf) {
    const std::string why = "not judged: the running mean's interval is computed beside the reference's own frame";
    for (StageVerdict& v : end_to_end.stages)
      if (v.model.empty() && (v.stage == st::kVoxelEnergy || v.stage.rfind(st::kVoxelFrame, 0) == 0)) v.note = why;
    return;
  }
  const VoxelInjection injection(scene, test, s);
  std::vector<FrameEnergy> energies;
  for (size_t k = 1; k < frames; ++k) {
    const Volume* bounce = k >= 2 ? &test.multibounce_frames[k - 2] : nullptr;
    StageVerdict v = judge_frame(int(k), int(frames), injection, bounce, test.multibounce_frames[k - 1], test, s,
                                 test_set, opt);
    if (auto e = frame_energy(v, int(k), test, frames, test.multibounce_frames[k - 1].voxel_count())) energies.push_back(*e);
    replace(end_to_end, std::move(v));
  }
  // The last frame: voxel.radiance, re-judged on the test's own bounce input (isolated_stages.cpp).
  const StageVerdict* last = find_verdict(end_to_end, st::kVoxelRadiance);
  if (last && last->extra.contains("end_to_end"))
    if (auto e = frame_energy(*last, int(frames), test, frames, radiance_voxels(test, test_set))) energies.push_back(*e);
  replace(end_to_end, judge_energy(energies));
}

}  // namespace vct::cmp
