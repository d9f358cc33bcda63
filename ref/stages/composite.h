// The final VCT frame from its components (docs/pipeline.md, "Final composite"):
// final = direct + kd*albedo*indirect_diffuse + F*indirect_specular + emission + particles,
// with F = fresnel_schlick(f0, f90, n.v) and kd = (1-F)(1-metallic) from vct_shared.h.
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// Fills images.diffuse_term, specular_term, emission and final_image from images.direct,
/// indirect_diffuse, indirect_specular and particles (any of which may be empty = zero).
void composite_frame(const Scene& scene, const GBuffer& g, FrameImages& images);

}  // namespace vct
