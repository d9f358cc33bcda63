#include "scene_warnings.h"

#include <fmt/core.h>

#include "scene/exposure.h"

namespace vct::app {

Scene load_scene_and_warn(const std::string& path_or_empty, const SceneLoadOptions& options) {
  Scene scene = load_scene(path_or_empty, options);
  for (const std::string& w : scene.stats.warnings) fmt::print(stderr, "vct: warning: {}: {}\n", scene.source, w);
  return scene;
}

Scene load_scene_and_warn(const std::string& path_or_empty, const SceneLoadOptions& options, const VctSettings& s) {
  Scene scene = load_scene_and_warn(path_or_empty, options);
  expose_scene(scene, s);
  return scene;
}

void expose_scene(Scene& scene, const VctSettings& s) {
  const ExposureApplied e = resolve_exposure(scene, s.exposure, s.exposure_ev100);
  pre_expose(scene, e);
  if (e.scale == 1.0f) return;
  fmt::print(stderr, "vct: exposure: {}: {} (meter at the scene's centre: {:.4g} lux), every light and emission x {:.6g}\n",
             scene.source, e.mode == "auto" ? fmt::format("auto, {:+d} stops", e.stops) : fmt::format("EV100 {:g}", e.ev100),
             e.key_illuminance, e.scale);
}

}  // namespace vct::app
