// Pictures of a component's budget (docs/attribution.md, "Reading the waterfall"): a waterfall
// chart (truth, then each term stacked on the running sum, then VCT) and a signed heat map per
// term. Drawn into an Image and written as PNG (no fonts: the numbers are in the table and in
// attribution.json, in the same order as the bars).
#pragma once

#include <string>

#include "attribution/ladder.h"
#include "core/image.h"

namespace vct::attr {

/// The waterfall of `b`: grey bars for truth and VCT (from 0), red for a term that raises the
/// estimate, blue for one that lowers it, each with a black +-1 SE whisker; a black zero line.
Image waterfall_image(const ComponentBudget& b, int width = 480, int height = 240);

/// Signed per-pixel luminance of a term, blue (negative) - white - red (positive), scaled by the
/// largest |value| inside the mask (`scale` receives it); black outside the mask.
Image term_heat_image(const RungImage& term, const Image& mask, float* scale = nullptr);

}  // namespace vct::attr
