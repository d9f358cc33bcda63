// The judge's images beside the camera G-buffer (docs/compare.md, "G-buffer" and "Raster
// alternatives"): per pixel, how far each textured value may move (texture_slack), the range of
// every value a correct rasterizer may show (tie_range) and where the alpha test may go either
// way. The oracle's own work: render_gbuffer (stages/gbuffer.h) computes none of it.
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/raster.h"
#include "stages/stage_types.h"

namespace vct {

/// Fills g.texture_slack (freedoms/texture_slack.h; kSlackDirect stays zero until
/// freedoms/direct_slack.h fills it) and g.tie_range (freedoms/gbuffer_ties.h) for the G-buffer
/// `g` that render_gbuffer made from the visibility buffer `vb`.
void add_gbuffer_freedoms(const Scene& scene, const VctSettings& settings, const VisibilityBuffer& vb, GBuffer& g);

/// render_gbuffer and add_gbuffer_freedoms: the G-buffer as the judge reads it.
GBuffer render_gbuffer_with_freedoms(const Scene& scene, const VctSettings& settings);

}  // namespace vct
