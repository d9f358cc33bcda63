// GPU (or external) stage outputs against the CPU reference, stage by stage, with the tolerance
// models of tolerance.h; error masks written beside the run (docs/compare.md).
#pragma once

#include <string>

#include "compare/stage_set.h"
#include "compare/verdict.h"

namespace vct::cmp {

struct CompareOptions {
  size_t worst_n = 10;
  std::string mask_dir;     // absolute/relative directory for mask PNGs ("" = no masks)
  std::string mask_prefix;  // how masks are named in the verdicts (relative to the run dir)
  // Set by compare_stage_sets when voxel stages tolerated ties: cone-traced images may then
  // differ on up to this fraction of pixels (warn) before failing.
  double upstream_tie_fraction = 0.0;
  // Set by compare_stage_sets from the sets' settings: direct light was cone-traced.
  bool soft_shadows = false;
  // Set by compare_stage_sets for light-space depth stages from the reference's
  // shadow_depth_format: one UNORM step q = 1/(2^b - 1) (0 for float); the depth bound grows by
  // 2q (docs/compare.md, the shadow_depth_format row).
  double depth_quantum = 0.0;
  // Set by judge_cones_on_test_inputs (compare/isolated_stages.h) when the re-traced composite
  // added the test's display-encoded image.direct decoded through the declared transform:
  // image.final's display bound grows by one step of its bit depth (docs/compare.md, "Display
  // transform").
  bool direct_decoded_from_display = false;
  // voxel.radiance: voxels beyond bound + shading slack (shadow-test ties the slack does not
  // see) tolerated up to this fraction of the checked voxels (warn); 0: none (docs/compare.md,
  // "Voxel radiance on the test's own shadow maps", says why 0.5 % stays).
  double shading_tie_fraction = 0.005;
};

Report compare_stage_sets(const StageSet& reference, const StageSet& test, const CompareOptions& opt = {});

/// One image stage (also used for two bare images): `stage` selects the model.
/// Beyond-bound pixels are ties only when admissible: inside the reference's 3x3 range plus the
/// bound; any other value fails (docs/compare.md, "Ties are admissible values"). Shading stages
/// (image.direct, image.emission) keep the counted allowance until their inputs' freedom is in
/// their bound.
/// `display`: the engine's declared display transform of this stage (compare/display_transform.h):
/// the reference's linear colour is mapped through it and each pixel's bound carried into display
/// space; nullptr = linear.
/// `texture_slack`: the reference's GBuffer::texture_slack (stages/texture_slack.h), added to the
/// bound of the textured G-buffer stages; nullptr = none (bare images, external references).
/// `tie_range`: the reference's GBuffer::tie_range (stages/gbuffer_ties.h), or for a shadow map its
/// ShadowMap::tie_range / cube_tie_range face (stages/shadow_map_ties.h): a beyond-bound pixel
/// inside the range of the values a correct GL may show there (plus its bound) is admitted as a
/// raster alternative, at any count, and any other fails (compare/tie_range.h); nullptr = none.
StageVerdict compare_image_stage(const std::string& stage, const Image& ref, const Image& test,
                                 const Image* edge_hint, const CompareOptions& opt,
                                 const Image* texture_slack = nullptr,
                                 const DisplayTransform* display = nullptr,
                                 const Image* tie_range = nullptr);

/// Two bare volumes, element-wise with abs/rel bound (vct compare A.nrrd B.nrrd).
StageVerdict compare_volume_plain(const std::string& stage, const Volume& ref, const Volume& test, double abs,
                                  double rel, const CompareOptions& opt);

}  // namespace vct::cmp
