// "Explain a pixel" (vct render --explain X,Y): every cone the final frame traced at one pixel,
// sample by sample, as JSON, and a picture of those cones over a slice of the voxel grid — the
// teaching view of cone tracing (docs/pipeline.md, "Explain").
#pragma once

#include <nlohmann/json.hpp>

#include "core/image.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

struct PixelExplanation {
  nlohmann::json json;  // pixel, surface, components, cones[] with samples[]
  Image picture;        // 3 channels in [0,1]: a base-level slice with the cones drawn over it
};

/// Re-traces pixel (x, y) (row 0 = top) of a finished ref frame with sample recording. Throws
/// InputError if the pixel is outside the image.
PixelExplanation explain_pixel(const Scene& scene, const FrameResult& frame, const VctSettings& s, int x, int y);

}  // namespace vct
