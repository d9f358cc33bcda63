// The per-component error budget of VCT against the path tracer (issue 17 item 1,
// docs/attribution.md): for indirect diffuse, indirect specular and direct light, a ladder of
// estimators on the same pixels, G-buffer and voxel field, each replacing one VCT approximation by
// its exact counterpart, so the differences between neighbouring rungs add up to the total bias.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "attribution/ladder.h"
#include "attribution/ladder_context.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::attr {

/// Component names, in the order the budget reports them.
const std::vector<std::string>& component_names();

struct AttributionOptions {
  int rays_per_pixel = 32;              // per rung, per pixel (the cone-set rung: per cone)
  std::vector<std::string> components;  // empty = all of component_names()
  PtCache* pt_cache = nullptr;          // shared path-traced runs (sweeps); null = own
};

struct Attribution {
  std::vector<ComponentBudget> components;
  bool sums_to_totals() const;  // every component's sum check
};

/// Checks option values against the lists; throws InputError naming `flag`.
void check_components(const std::vector<std::string>& names, const std::string& flag);

/// Throws InputError("settings", ...) for settings the ladders cannot split: an engine's
/// conventions (issue 21: a declared diffuse cone set or tangent frame, indirect_diffuse_gain,
/// indirect_fresnel, the specular cone's own settings), which vct compare judges instead.
/// `vct attribute` calls it before it creates its run directory.
void check_attributable(const VctSettings& s);

/// Renders the reference VCT frame of `settings` and runs the ladders (path tracer: settings.pt
/// spp and seed, at the VCT image size). Deterministic for any thread count.
Attribution attribute(const Scene& scene, const Settings& settings, const AttributionOptions& opt);
/// The same on a frame already rendered (render_ref_frame(scene, settings)).
Attribution attribute_frame(const Scene& scene, const Settings& settings, const FrameResult& frame,
                            const AttributionOptions& opt);

nlohmann::json to_json(const ComponentBudget& b);
nlohmann::json to_json(const Attribution& a);

}  // namespace vct::attr
