// The final VCT frame from its components (docs/pipeline.md, "Final composite"):
// final = direct + kd*albedo*indirect_diffuse + F*indirect_specular + emission + particles,
// with F = fresnel_schlick(f0, f90, n.v) and kd = (1-F)(1-metallic) from vct_shared.h; an
// engine's Fresnel for the indirect terms is settings.indirect_fresnel (issue 21).
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// Fills images.diffuse_term, specular_term, emission and final_image from images.direct,
/// indirect_diffuse, indirect_specular and particles (any of which may be empty = zero).
void composite_frame(const Scene& scene, const GBuffer& g, const VctSettings& s, FrameImages& images);

/// The Fresnel factor of the indirect terms at cosine n.v for a surface of perceptual roughness
/// `roughness`: sh::fresnel_schlick(f0, f90, cos) (Schlick), or with f90 = max(1 - r^2, f0) per
/// channel, r = roughness clamped to [0, 1] (SchlickRoughness; the source design's
/// FresnelSchlickRoughness(cos, f0, r^2)).
vec3 indirect_fresnel(IndirectFresnel kind, const vec3& f0, float f90, float roughness, float cos_theta);

}  // namespace vct
