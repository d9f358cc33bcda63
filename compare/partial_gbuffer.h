// A partial G-buffer (issue 21): engines rarely keep seven G-buffer stages, but every deferred or
// forward+ renderer has a depth buffer and normals. With those, `vct compare --scene` can still
// judge the engine's cone marcher on its own mips: the position is reconstructed from depth
// through the scene camera's inverse view-projection, and the stages the cones need but the engine
// did not dump (coverage, material, albedo, direct light...) are taken from the reference. The
// indirect radiance stages (image.indirect_diffuse, image.indirect_specular) do not multiply by
// albedo, so they are judged on the engine's geometry and mips alone.
#pragma once

#include <string>
#include <vector>

#include "compare/stage_set.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::cmp {

/// True when `set` has gbuffer.depth and gbuffer.normal but no gbuffer.position of any kind (one
/// listed as a volume is a wrong input, named as missing, not a partial G-buffer).
bool is_partial_gbuffer(const StageSet& set);

/// `set` completed for the cone re-trace: gbuffer.coverage (depth < 1) when absent,
/// gbuffer.position from depth, and every other missing image stage of `needed` copied from
/// `reference` (when it has it; otherwise left missing, for the caller to name). The stages filled
/// in are listed in info["partial_gbuffer"].
StageSet complete_partial_gbuffer(const StageSet& set, const Scene& scene, const StageSet* reference,
                                  const std::vector<std::string>& needed);

/// World position of window point (px, py) (pixel units, row 0 = top, pixel centres at +0.5) at
/// GL window depth `depth` in [0,1] (depth range 0..1), through the camera of `scene` for a
/// w x h image.
vec3 position_from_depth(const Scene& scene, int w, int h, float px, float py, float depth);

/// Per covered pixel and world axis, how far the engine's own position may lie from the one
/// position_from_depth reconstructs (docs/compare.md, "The start-face tie"): its depth's
/// precision along the pixel's ray (4 x 2^-24 of window depth: the engine's interpolation and
/// store, float or 24-bit, and our 2 d - 1), the 2^-8 pixel its vertices snap by (its attributes
/// are those of a surface point up to 2^-8 pixel from the pixel centre on each window axis, as
/// freedoms/fragment_slack.h), found on the plane through the position with the engine's normal,
/// and 4 roundings of the position. Capped at the volume's size (anywhere). From g.depth,
/// g.normal, g.coverage and g.position.
Image position_margin_from_depth(const Scene& scene, const GBuffer& g);

}  // namespace vct::cmp
