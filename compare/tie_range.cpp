#include "compare/tie_range.h"

#include <algorithm>
#include <optional>

#include "freedoms/gbuffer_ties.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {
int channel_named(const Image& im, const std::string& name) {
  const auto it = std::find(im.channel_names.begin(), im.channel_names.end(), name);
  return it == im.channel_names.end() ? -1 : int(it - im.channel_names.begin());
}

// The range row of a judged shadow-map family (the same member numbering), or nullptr.
const char* light_space_range_row(const std::string& stage) {
  const std::optional<StageRef> ref = find_stage(stage);
  if (!ref || ref->row->role != StageRole::Judged) return nullptr;
  const std::string family = ref->row->name;
  if (family == stage_names::kShadowMap) return stage_names::kShadowMapTieRange;
  if (family == stage_names::kShadowMapCube) return stage_names::kShadowMapCubeTieRange;
  return nullptr;
}
}  // namespace

std::string tie_range_stage(const std::string& stage) {
  const char* row = light_space_range_row(stage);
  return row ? stage_name(stage_row(row), find_stage(stage)->index) : std::string(stage_names::kGbufferTieRange);
}

TieRangeChannels tie_range_channels(const std::string& stage, const Image& range, int channels) {
  const std::string prefix = "gbuffer.";
  TieRangeChannels out;
  // G-buffer stages by their attachment's name (freedoms/gbuffer_ties.h), the shading stages judged
  // on the test's own inputs by their stage name (freedoms/direct_ties.h), shadow maps as "depth"
  // (freedoms/shadow_map_ties.h).
  const bool gbuffer = stage.compare(0, prefix.size(), prefix) == 0;
  const bool light_space = light_space_range_row(stage) != nullptr;
  if (!gbuffer && !light_space && stage != stage_names::kImageDirect && stage != stage_names::kImageEmission)
    return out;
  const std::string group = gbuffer ? stage.substr(prefix.size()) : light_space ? "depth" : stage;
  for (int c = 0; c < channels; ++c) {
    const int lo = channel_named(range, tie_range_channel_name(group, c, false));
    const int hi = channel_named(range, tie_range_channel_name(group, c, true));
    if (lo < 0 || hi < 0) return {};
    out.lo.push_back(lo);
    out.hi.push_back(hi);
  }
  return out;
}

Image without_tie_range_group(const Image& range, const std::string& group) {
  std::vector<int> kept;
  for (int c = 0; c < range.channels && size_t(c) < range.channel_names.size(); ++c)
    if (range.channel_names[size_t(c)].rfind(group + ".", 0) != 0) kept.push_back(c);
  Image out(range.width, range.height, int(kept.size()));
  out.channel_names.clear();
  for (int k : kept) out.channel_names.push_back(range.channel_names[size_t(k)]);
  for (int y = 0; y < range.height; ++y)
    for (int x = 0; x < range.width; ++x)
      for (size_t i = 0; i < kept.size(); ++i) out.at(x, y, int(i)) = range.at(x, y, kept[i]);
  return out;
}

bool within_tie_range(const Image& range, const TieRangeChannels& ch, int x, int y, int c, double test,
                      double bound) {
  const double lo = range.at(x, y, ch.lo[size_t(c)]), hi = range.at(x, y, ch.hi[size_t(c)]);
  return test >= lo - bound && test <= hi + bound;
}

}  // namespace vct::cmp
