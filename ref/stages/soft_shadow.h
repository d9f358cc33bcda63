// Cone-traced soft shadows (docs/pipeline.md, "Soft shadows"): with settings.soft_shadows the
// direct light of each light is weighted by 1 - the opacity a cone toward the light gathers,
// instead of the shadow map's PCF visibility.
#pragma once

#include "core/image.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "stages/gbuffer.h"  // gbuffer_material
#include "stages/stage_types.h"

namespace vct {

/// Unshadowed radiance reflected toward v from one light of any kind (BRDF x irradiance x n.l), from the
/// shared definitions in vct_shared.h.
vec3 light_radiance(const Light& light, const VctSettings& s, const vec3& p, const vec3& n, const vec3& v,
                         const SurfaceMaterial& m);

/// Direct light of every covered pixel with cone visibility; `visibility` (1 channel) receives the
/// mean visibility over the lights (1 where no light or no surface).
Image shade_direct_soft(const Scene& scene, const GBuffer& g, const VoxelMips& mips, const VctSettings& s,
                        Image* visibility);

}  // namespace vct
