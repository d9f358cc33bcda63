// The shading stages' ties on the test's own inputs (docs/compare.md, "Shading stages on the
// test's own inputs"): image.direct re-shaded by the reference from the test's G-buffer and shadow
// maps leaves only the shading arithmetic (the stage's bound) and the PCF taps that the lookup's
// float arithmetic may flip (freedoms/shadow_ties.h). Direct light is a sum over lights of a
// non-negative term times that light's visibility, so it lies in [sum c_i lo_i, sum c_i hi_i].
// image.emission is the G-buffer's emission as the final pass adds it: on the test's own G-buffer
// it has no alternative (its range is its value).
#pragma once

#include <vector>

#include "core/image.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/light_sample.h"
#include "stages/stage_types.h"

namespace vct {

/// Float rounding of a spot's cos_axis on either backend (docs/compare.md, "Hard spots"): 2^-20.
inline constexpr float kHardSpotCosTie = 1.0f / 1048576.0f;

/// A hard spot's step tie: where p's cos_axis lies within kHardSpotCosTie of the cone's edge, the
/// light's sample with the step taken as lit (a correct GL may light p, or not); else a sample with
/// zero irradiance (no alternative). image.direct's ranges and the voxel fragments' shading slack
/// (freedoms/fragment_slack.h) read it.
LightSample hard_spot_lit_sample(const Light& light, LightModel model, const vec3& p);

/// Per pixel, the lower and upper end of image.direct and image.emission a correct GL may give
/// from G-buffer `g` and shadow maps `maps` (with their matrices), as channels
/// tie_range_channel_name("image.direct" | "image.emission", c, lo/hi) (freedoms/gbuffer_ties.h),
/// read by compare/tie_range.h. `direct` and `emission`: the reference's own values there,
/// which the ranges include.
Image shading_tie_range(const Scene& scene, const GBuffer& g, const std::vector<ShadowMap>& maps,
                        const VctSettings& settings, const Image& direct, const Image& emission);

}  // namespace vct
