// The indirect diffuse ladder (docs/attribution.md, "Indirect diffuse"):
//   truth            the path tracer's one-bounce diffuse AOV (pt_indirect_diffuse)
//   exact_gathering  cosine-distributed rays through the base voxel level, pi f_d(l) L(l):
//                    the same integral as the truth, on the voxel field instead of the scene
//   composite_kd     the same rays' mean radiance times the composite's kd(n.v) albedo
//   cone_set_rays    rays uniformly inside each cone of the set, weighted as the set is
//   cone_steps       each cone's own march (growing steps) reading the base level on its axis
//   vct              the frame's diffuse_term (the cones on the mips)
// Terms: voxel_field, kd_at_n_dot_v, cone_quadrature, cone_step_schedule, mip_lookups (the last
// two together are the cones' prefiltering).
#pragma once

#include "attribution/ladder.h"
#include "attribution/base_level_ray.h"
#include "attribution/ladder_context.h"

namespace vct::attr {

std::vector<Rung> diffuse_rungs(const LadderContext& ctx);
const std::vector<std::string>& diffuse_term_names();

/// The two gathering estimators, per pixel (exposed for the analytic tests).
RungImage gather_cosine_rays(const LadderContext& ctx, uint32_t stream, bool composite_kd);
RungImage gather_cone_set_rays(const LadderContext& ctx, uint32_t stream);
RungImage cone_set_base_level_steps(const LadderContext& ctx);

}  // namespace vct::attr
