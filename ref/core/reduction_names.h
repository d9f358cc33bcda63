// One vocabulary for the voxel reduction (issue 39): the settings table's names (`--reduction`,
// --config, run.json) and the stage-set manifest's (`"reduction"`, docs/external_format.md) name the
// same four reductions. Both spellings are read everywhere; each is written where it always was,
// so existing run directories, configs and manifests keep their meaning.
#pragma once

#include <optional>
#include <string>

#include "core/settings.h"

namespace vct {

struct ReductionName {
  Reduction value;
  const char* setting;   // settings table, run.json
  const char* manifest;  // vct-stages.json
};

inline constexpr ReductionName kReductionNames[] = {
    {Reduction::ExactMean, "exact", "exact_mean"},
    {Reduction::FixedPoint, "fixed", "fixed_point"},
    {Reduction::CasRgba8, "cas", "cas_rgba8"},
    {Reduction::RunningMeanHalf, "running_mean", "running_mean"},
};

/// The reduction either spelling names; nullopt for anything else.
inline std::optional<Reduction> reduction_from_name(const std::string& name) {
  for (const ReductionName& r : kReductionNames)
    if (name == r.setting || name == r.manifest) return r.value;
  return std::nullopt;
}

/// The manifest's spelling of a reduction.
inline std::string manifest_reduction_name(Reduction r) {
  for (const ReductionName& n : kReductionNames)
    if (n.value == r) return n.manifest;
  return "exact_mean";
}

}  // namespace vct
