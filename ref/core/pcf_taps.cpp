#include "core/pcf_taps.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace vct {

namespace {

// Limits that keep a lookup cheap and inside a shadow map's neighbourhood; an engine's kernel is
// a few texels wide (the seed's 3x3, gidemo's 4x4 at +-1).
constexpr size_t kMaxTaps = 256;
constexpr float kMaxOffset = 16.0f;

float parse_offset(const std::string& text, const std::string& pair, const std::string& name) {
  size_t used = 0;
  float v = 0.0f;
  try {
    v = std::stof(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v) || std::abs(v) > kMaxOffset)
    throw InputError("", name + ": '" + pair + "' is not a pair dx,dy of offsets within +-16");
  return v;
}

}  // namespace

std::vector<vec2> parse_pcf_taps(const std::string& text, const std::string& name) {
  std::vector<vec2> taps;
  std::istringstream in(text);
  std::string pair;
  while (in >> pair) {
    const size_t comma = pair.find(',');
    if (comma == std::string::npos)
      throw InputError("", name + ": '" + pair + "' is not a pair dx,dy of offsets within +-16");
    taps.emplace_back(parse_offset(pair.substr(0, comma), pair, name),
                      parse_offset(pair.substr(comma + 1), pair, name));
  }
  if (taps.size() > kMaxTaps) throw InputError("", name + ": more than 256 taps");
  return taps;
}

std::vector<vec2> pcf_tap_offsets(const VctSettings& settings) {
  std::vector<vec2> taps = parse_pcf_taps(settings.pcf_taps);
  if (!taps.empty()) return taps;
  const int k = std::max(1, settings.pcf_kernel);
  const float half = 0.5f * float(k - 1);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) taps.emplace_back(float(i) - half, float(j) - half);
  return taps;
}

VctSettings voxel_pass_settings(const VctSettings& settings) {
  VctSettings out = settings;
  if (!settings.voxel_pcf_taps.empty()) out.pcf_taps = settings.voxel_pcf_taps;
  if (settings.voxel_pcf == VoxelPcf::Oracle) {
    const VctSettings oracle;
    out.pcf_taps = oracle.pcf_taps;
    out.shadow_compare = oracle.shadow_compare;
    out.shadow_filter_order = oracle.shadow_filter_order;
    out.pcf_tap_unit = oracle.pcf_tap_unit;
    out.pcf_tap_scale = oracle.pcf_tap_scale;
    out.shadow_border = oracle.shadow_border;
  }
  return out;
}

bool filters_depth_first(const VctSettings& settings) {
  return settings.shadow_compare == ShadowCompare::Linear &&
         settings.shadow_filter_order == ShadowFilterOrder::FilterThenCompare;
}

}  // namespace vct
