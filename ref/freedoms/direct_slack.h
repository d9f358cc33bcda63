// How far the direct light may legitimately move at a pixel: the reference's own direct_radiance
// (stages/direct.h) shaded from every material a correct GL G-buffer may hold there (the texture
// slack's sample shifts x admissible LODs, freedoms/texture_slack.h), at the shifted positions and
// the same shadow maps. image.direct's bound adds it (docs/compare.md, "Texture LOD"): a
// normal-mapped surface's admissible normals move n.l and the specular lobe by more than the
// shading bound alone allows; on any surface the snapped sample point moves the interpolated
// normal and may flip a PCF tap at a shadow-map texel edge.
#pragma once

#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/raster.h"  // VisibilityBuffer
#include "stages/stage_types.h"

namespace vct {

/// How far one light's PCF visibility may move under GL LINEAR compare on a shadow sampler (an
/// engine's shadow_compare = linear): 8 sub-texel bits per weight, 2^-8 per axis, 2^-7 in all
/// (docs/compare.md, the engine's PCF row). The direct and voxel slacks add this times each
/// light's unshadowed light.
constexpr float kLinearCompareWeightStep = 1.0f / 128.0f;

/// Fills channel kSlackDirect of g.texture_slack: per covered pixel, the
/// largest |direct(candidate) - direct| over RGB, with `direct` the reference's image.direct.
/// Every combination of the base colour, metallic-roughness and normal slots' LOD candidates is
/// shaded at each shifted sample point. `camera`: the G-buffer's raster (render_gbuffer's
/// visibility), read instead of rasterizing again where masks cannot change it.
void add_direct_texture_slack(const Scene& scene, const std::vector<ShadowMap>& maps,
                              const VctSettings& settings, const Image& direct, GBuffer& g,
                              const VisibilityBuffer* camera = nullptr);

}  // namespace vct
