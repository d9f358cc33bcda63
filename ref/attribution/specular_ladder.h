// The indirect specular ladder (docs/attribution.md, "Indirect specular"):
//   truth           the path tracer's one-bounce specular AOV (pt_indirect_specular)
//   ggx_lobe_rays   rays importance-sampled from the GGX lobe (visible normals) through the base
//                   voxel level, f_s(l) cos L(l) / pdf: the same integral on the voxel field
//   cone_rays       rays uniformly inside the specular cone through the base level, mean
//                   radiance times the composite's F(n.v)
//   cone_steps      the cone's own march (growing steps) on its axis, base level, x F(n.v)
//   vct             the frame's specular_term (the cone on the mips)
// Terms: voxel_field, cone_for_lobe (the cone's axis, aperture and F stand in for the lobe),
// cone_step_schedule, mip_lookups.
#pragma once

#include "attribution/base_level_ray.h"
#include "attribution/ladder.h"
#include "attribution/ladder_context.h"

namespace vct::attr {

std::vector<Rung> specular_rungs(const LadderContext& ctx);
const std::vector<std::string>& specular_term_names();

RungImage gather_ggx_rays(const LadderContext& ctx, uint32_t stream);
RungImage gather_specular_cone_rays(const LadderContext& ctx, uint32_t stream);
RungImage specular_cone_base_level_steps(const LadderContext& ctx);

}  // namespace vct::attr
