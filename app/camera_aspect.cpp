#include "camera_aspect.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace vct::app {

namespace {
int rounded_size(double v) { return std::clamp(int(std::lround(v)), 1, 16384); }
}  // namespace

Settings fit_image_to_camera(Settings s, const Scene& scene, const CommonOptions& o, std::string& warning) {
  warning.clear();
  const double aspect = scene.camera.aspect_ratio;
  if (!(aspect > 0.0) || scene.camera.orthographic) return s;
  if (o.width && o.height) {
    const double forced = double(*o.width) / double(*o.height);
    // One pixel of either side is the finest aspect an integer size can express.
    if (std::fabs(forced - aspect) * double(std::min(*o.width, *o.height)) > aspect)
      warning = fmt::format(
          "the camera's aspectRatio is {:.4g} but --width {} --height {} make {:.4g}: the framing changes (same "
          "vertical field of view, {} than the author framed it); give only --height or --width to keep it",
          aspect, *o.width, *o.height, forced, forced > aspect ? "wider" : "narrower");
    return s;
  }
  if (o.width) {
    s.vct.height = s.pt.height = rounded_size(double(s.vct.width) / aspect);
  } else {
    s.vct.width = rounded_size(double(s.vct.height) * aspect);
    s.pt.width = rounded_size(double(s.pt.height) * aspect);
  }
  return s;
}

Settings fit_image_to_camera_and_warn(const Settings& s, Scene& scene, const CommonOptions& o) {
  std::string warning;
  Settings out = fit_image_to_camera(s, scene, o, warning);
  if (!warning.empty()) {
    fmt::print(stderr, "vct: warning: {}: {}\n", scene.source, warning);
    scene.stats.warnings.push_back(warning);
  }
  validate_settings(out);
  return out;
}

}  // namespace vct::app
