// `vct config-from-manifest`: the reference's settings (the `vct render --config` format) for a
// stage set, from what its manifest says it ran (issue 39): its VCT settings keys, its reduction and
// storage, its facts' MSAA sample count and its files' sizes. Conventions are judged by `vct
// compare`, not rendered, and the sample positions travel with `--facts-from`.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/stage_set.h"

namespace vct::app {

/// {"vct": {...}}, checked to load as settings (validate_settings); `notes` gets one line per
/// manifest entry that is not carried over and why. Throws InputError naming the manifest when
/// the result is not valid settings.
nlohmann::json config_from_manifest(const cmp::StageSet& set, std::vector<std::string>& notes);

}  // namespace vct::app
