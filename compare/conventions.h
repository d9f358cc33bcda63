// Conventions an engine may declare in its vct-stages.json ("conventions", docs/external_format.md):
// design choices that differ from the oracle's defaults and that the comparison reproduces or
// reports instead of failing them like a bug (issue 21). Reductions are declared by the manifest's
// "reduction" (e.g. "running_mean"); this object holds the rest.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "compare/display_transform.h"

namespace vct::cmp {

struct Conventions {
  // Each mip level is the box filter of the level below times this factor (1 = none). A declared
  // deviation: mip stages are still judged against the unscaled reference (a scaled mip is a real
  // bug), but their verdicts say whether the declared scale explains the difference; cone stages
  // judged with --scene use the engine's own mips, so they are not blamed for it.
  double mip_scale = 1.0;
  // How the engine wrote its image outputs (tone operator, exposure, gamma, bit depth): a
  // convention, reproduced on the reference's linear image before judging (display_transform.h).
  DisplayTransform display;

  bool empty() const { return mip_scale == 1.0 && !display.declared(); }
};

/// Reads the manifest's "conventions" object. Unknown keys and values out of range are an
/// InputError naming `manifest` and the key.
Conventions read_conventions(const std::string& manifest, const nlohmann::json& j);

nlohmann::json to_json(const Conventions& c);

}  // namespace vct::cmp
