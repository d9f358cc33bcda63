// An engine's PCF tap pattern (setting pcf_taps, issue 21): texel offsets from the point's
// shadow-map position, "dx,dy dx,dy ..." -- fractional offsets allowed (gidemo's taps sit at
// +-1/3 and +-1 texel). Empty text is the oracle's own pattern, the pcf_kernel x pcf_kernel
// square at offsets i - (k-1)/2 (docs/pipeline.md, "Shadow maps").
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "core/settings.h"

namespace vct {

/// The offsets of `text` in order. Throws InputError("", "<name> ...") for anything but
/// whitespace-separated "dx,dy" pairs of finite numbers within +-16 (in the declared
/// pcf_tap_unit), or more than 256 taps.
std::vector<vec2> parse_pcf_taps(const std::string& text, const std::string& name = "pcf_taps");

/// The taps a lookup uses, in the declared unit: parse_pcf_taps(settings.pcf_taps), or the
/// pcf_kernel square (in texels) when empty.
std::vector<vec2> pcf_tap_offsets(const VctSettings& settings);

/// The settings the voxelizer's lookups (light injection, voxel.radiance, and its freedoms) run
/// with (issue 39): `settings` with pcf_taps replaced by voxel_pcf_taps where one is declared, and
/// with voxel_pcf = oracle the oracle's PCF (the pcf_kernel square, nearest, texel, unscaled,
/// clamped to edge) whatever the frame declares.
/// Taken once per stage (a copy), not per fragment.
VctSettings voxel_pass_settings(const VctSettings& settings);

/// Whether a tap filters its four depths and compares once (shadow_compare = linear with
/// shadow_filter_order = filter_then_compare); else each texel it reads is compared.
bool filters_depth_first(const VctSettings& settings);

}  // namespace vct
