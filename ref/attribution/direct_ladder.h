// The direct-light ladder (docs/attribution.md, "Direct light"):
//   truth              the path tracer's direct AOV (pt_direct: punctual lights, exact
//                      visibility, at the path tracer's own first hit)
//   exact_visibility   the frame's shading (stages/direct.h: the same lights and BRDF) at the
//                      G-buffer's points with an Embree shadow ray instead of the shadow map
//   vct                the frame's direct image (shadow map + PCF, or cone shadows)
// Terms: gbuffer_point (rasterized point and normal vs the path tracer's hit) and
// shadow_visibility (shadow map + PCF, or the soft-shadow cone, vs exact visibility).
#pragma once

#include "attribution/ladder.h"
#include "attribution/ladder_context.h"

namespace vct::attr {

std::vector<Rung> direct_rungs(const LadderContext& ctx);
const std::vector<std::string>& direct_term_names();

/// Direct light at every covered G-buffer point with exact (ray-traced) visibility.
RungImage direct_exact_visibility(const LadderContext& ctx);

}  // namespace vct::attr
