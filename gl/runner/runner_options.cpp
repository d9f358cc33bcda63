#include "runner_options.h"

#include <nlohmann/json.hpp>

#include "gl/gl_context.h"

namespace vct::gl {

int max_settable_samples(const GlContext& context) {
  const int max = context.max_framebuffer_samples();
  return max >= 8 ? 8 : max >= 4 ? 4 : 1;
}

Settings runner_settings(const RunnerOptions& o) {
  Settings s;
  if (!o.config.empty()) s = load_settings_file(o.config, s);
  nlohmann::json j = s.vct, patch = nlohmann::json::object();
  if (o.width) patch["width"] = *o.width;
  if (o.height) patch["height"] = *o.height;
  if (o.grid) patch["grid"] = *o.grid;
  if (o.msaa) patch["msaa_samples"] = *o.msaa;
  if (o.shadow_map_size) patch["shadow_map_size"] = *o.shadow_map_size;
  if (o.bounces) patch["bounces"] = *o.bounces;
  if (o.reduction) patch["reduction"] = *o.reduction;
  if (o.storage) patch["storage"] = *o.storage;
  if (o.voxelizer) patch["voxelizer"] = *o.voxelizer;
  if (o.conservative_raster) patch["conservative_raster"] = *o.conservative_raster;
  if (o.aniso) patch["anisotropic"] = true;
  if (o.no_depth_prepass) patch["depth_prepass"] = false;
  j.merge_patch(patch);
  from_json(j, s.vct);
  validate_settings(s);
  return s;
}

}  // namespace vct::gl
