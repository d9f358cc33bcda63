// Indirect light for every covered G-buffer pixel: the diffuse cone set and the specular cone
// (docs/pipeline.md, "Diffuse cones", "Specular cone"). One pixel is one independent work item.
#pragma once

#include <vector>

#include "core/image.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/cone_sets.h"
#include "stages/stage_types.h"

namespace vct {

struct IndirectImages {
  Image diffuse;   // 3: weighted diffuse cone radiance (cosine mode: E/pi estimate)
  Image specular;  // 3: specular cone radiance
  std::vector<Image> diffuse_cones;  // one per cone of the set (diffuse_cone_count), 4 each: (rgb, opacity)
};

/// Disabled cone sets (settings.diffuse_cones / specular_cones false) give zero images.
/// `march_end`: MarchParams::march_end of every cone (the march-end tie's alternatives).
IndirectImages trace_indirect(const Scene& scene, const GBuffer& gbuffer, const VoxelMips& mips,
                              const VctSettings& s, int march_end = 0);

/// The view vector (unit, surface -> eye) of a world point.
vec3 view_vector(const Scene& scene, const vec3& p);

}  // namespace vct
