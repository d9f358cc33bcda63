// Every multibounce frame judged (issue 34 item 3; docs/compare.md, "Every multibounce frame is
// judged"). Frame k's voxels hold restitution x albedo x the diffuse cones traced in frame k-1's
// mips, so a frame can only be judged on the test's own previous frame (as the last frame's
// voxel.radiance already is, compare/isolated_stages.h). Each frame before the last is the stage
// voxel.frame.<k>: the reference injects frame k again on the test's own shadow maps and, k >= 2,
// with the bounce light traced in mips built from the test's own frame k-1, and judges the test's
// frame k against it by voxel.radiance's rules (compare/radiance_judge.cpp). The energy sequence
// (run.json's multibounce_energy) is the stage voxel.energy: per frame, the test's energy against
// that re-injected frame's, within the sum of the frame's per-voxel admitted widths.
#pragma once

#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "compare/verdict.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::cmp {

/// What the first pass (no scene, no test frame) says of voxel.frame.<k> and voxel.energy.
inline constexpr char kBounceFramesNeedTheScene[] =
    "judged on the test's own previous frame only (needs the scene: vct validate, vct compare --scene)";

/// The double sums' own rounding in a frame's energy: both sides sum n = 3 x voxels non-negative
/// floats in double, each within (n - 1) u (u = 2^-53) of its exact sum (Higham, Accuracy and
/// Stability of Numerical Algorithms, eq. 4.4), so the two differ by at most that x both sums.
double energy_summation_allowance(size_t voxels, double reference, double test);

/// Pass 3's multibounce part (after voxel.radiance was re-judged on the test's own bounce input):
/// replaces voxel.frame.<k> (k = 1 .. frames - 1, the frames `test` holds) and voxel.energy in
/// `end_to_end`. Nothing to do with one frame; with the running-mean reduction the frames keep the
/// first pass's verdict (its interval is computed beside the reference's own frame).
void judge_bounce_frames(Report& end_to_end, const Scene& scene, const FrameResult& test, const VctSettings& s,
                         const StageSet& test_set, const CompareOptions& opt);

}  // namespace vct::cmp
