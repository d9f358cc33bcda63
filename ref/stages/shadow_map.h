// Spot-light shadow maps: depth rendered from each spot light with the depth-only path of the
// software rasterizer (stages/depth_raster.h), and the PCF lookup used by direct lighting and
// light injection (docs/pipeline.md, "Shadow maps").
#pragma once

#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// World -> light clip space for one spot: glm::lookAt from the light along its direction with a
/// robust up vector (+z unless the direction is within ~8 degrees of it, then +x: the seed's
/// rule), and a square perspective whose full field of view is twice the outer cone angle
/// (clamped to [1, 170] degrees). far = distance to the farthest corner of `scene_bounds` (x1.01),
/// near = far / 20 (keeps the constant NDC depth bias meaningful; see docs).
mat4 spot_light_view_proj(const SpotLight& light, const Bounds3& scene_bounds);

/// One depth map per spot light (settings.shadow_map_size squared, GL_LESS, cleared to 1).
std::vector<ShadowMap> render_shadow_maps(const Scene& scene, const VctSettings& settings);

/// PCF visibility in [0,1] (1 = lit) of a world point for one light: settings.pcf_kernel^2 taps at
/// texel offsets (i - (k-1)/2), nearest texel, clamp to edge; a tap is lit when the point's
/// window depth <= stored depth + settings.shadow_bias. Points outside the light's frustum are lit
/// (the spot falloff is zero there anyway).
float shadow_visibility(const ShadowMap& map, const vec3& world_pos, const VctSettings& settings);

}  // namespace vct
