// The volume stages' judges (voxel.occupancy, voxel.radiance, voxel.holes, mips, plain volumes), as
// compare_stage_sets dispatches to them. Each records the admission rule of every voxel
// (compare/admission.h). Internal to compare/.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compare/element_loop.h"
#include "compare/judge_context.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "compare/verdict.h"
#include "core/volume.h"

namespace vct::cmp {

// Voxels where the two sides may legitimately differ (ties); mips above them inherit the freedom.
using Taint = std::vector<uint8_t>;

bool same_size(const Volume& a, const Volume& b);
/// Occupancy = alpha > 0 (or the single channel > 0).
std::vector<uint8_t> occupancy(const Volume& v);
void xyz_of(const Volume& v, size_t i, int& x, int& y, int& z);
Offender voxel_offender(const Volume& ref, const Volume& test, size_t i, float err, float bound);
/// The linear index of the voxel opt.explain names, or size_t(-1) (none, or not in `v`).
size_t explained_voxel(const CompareOptions& opt, const Volume& v);
/// extra["explain"] for voxel i (nothing when i is size_t(-1)).
void explain_voxel(StageVerdict& v, const Volume& ref, const Volume& test, size_t i, const std::vector<Rule>& rules,
                   const WorstChannel& worst);

/// Element-wise abs + rel (+ per-voxel `extra_abs`) bound; voxels in `tolerated` (upstream ties)
/// are admitted at any value.
StageVerdict compare_volume_masked(const std::string& stage, const Volume& ref, const Volume& test, double abs,
                                   double rel, const CompareOptions& opt, const Taint* tolerated,
                                   const std::vector<float>* extra_abs = nullptr);

/// voxel.occupancy; `taint` receives the voxels that differ (ties included).
StageVerdict compare_occupancy(const StageSet& rs, const StageSet& ts, const CompareOptions& opt, Taint& taint);
/// voxel.holes: reported, never failed.
StageVerdict compare_holes(const StageSet& rs, const StageSet& ts, const CompareOptions& opt);
/// voxel.radiance; `taint` receives the voxels whose fragment counts differ or that are beyond the bound.
StageVerdict compare_radiance(const StageSet& rs, const StageSet& ts, const CompareOptions& opt,
                              const JudgeContext& ctx, Taint& taint);
/// A mip level (mip.<dir>.<level>), its bound propagated from the base model; `taint`: the base
/// voxels that tie.
StageVerdict compare_mip(const std::string& stage, const StageSet& rs, const StageSet& ts, const CompareOptions& opt,
                         const Taint& taint);

}  // namespace vct::cmp
