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

/// The offsets of `text` in order. Throws InputError("", "pcf_taps ...") for anything but
/// whitespace-separated "dx,dy" pairs of finite numbers within +-16 texels, or more than 256 taps.
std::vector<vec2> parse_pcf_taps(const std::string& text);

/// The taps a lookup uses: parse_pcf_taps(settings.pcf_taps), or the pcf_kernel square when empty.
std::vector<vec2> pcf_tap_offsets(const VctSettings& settings);

}  // namespace vct
