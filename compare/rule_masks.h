// Error masks painted by admission rule (compare/admission.h): one legend for images and volumes.
// Red = beyond every rule (a failure); each other rule its table colour; elements within their
// bound show the reference dimmed (images) or its occupied voxels dim grey (volumes), as context.
#pragma once

#include <string>
#include <vector>

#include "compare/admission.h"
#include "compare/stage_compare.h"
#include "core/image.h"
#include "core/volume.h"

namespace vct::cmp {

/// The mask PNG's file stem of a stage ("image.final" -> "image_final_mask").
std::string mask_stem(const std::string& stage);

/// Writes `v.stage`'s image mask (one Rule per pixel, row-major) into opt.mask_dir and names it in v.mask.
void write_image_rule_mask(const CompareOptions& opt, StageVerdict& v, const Image& ref, const std::vector<Rule>& rules);

/// Writes a volume stage's mask as a slice montage (at most 64 z slices, +y up), only when an
/// element is beyond its bound; the reference's occupied voxels (`context`) dim grey, as context.
void write_volume_rule_mask(const CompareOptions& opt, StageVerdict& v, const Volume& context,
                            const std::vector<Rule>& rules);

/// The legend, for the report: [{rule, colour: [r, g, b]}] of every rule that paints a colour.
nlohmann::json mask_legend();

}  // namespace vct::cmp
