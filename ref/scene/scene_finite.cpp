#include "scene/scene_finite.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "core/error.h"

namespace vct {
namespace {

bool finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool all_finite(std::initializer_list<float> values) {
  for (float v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

void check_lights(const Scene& scene, const std::string& file) {
  for (const Light& l : scene.lights) {
    const std::string owner = std::string(light_kind_name(l.kind)) + " light '" + l.name + "'";
    if (!finite(l.position) || !finite(l.direction)) {
      throw InputError(file, owner + ": its node's world transform is not finite (it overflows float)");
    }
    // The renderers multiply intensity by colour (and by 1/d², cone and BRDF terms below 1):
    // the product itself must be a float.
    const float peak = l.intensity * std::max({l.color.x, l.color.y, l.color.z});
    if (!all_finite({l.intensity, l.range, l.inner_cone_angle, l.outer_cone_angle, peak}) || !finite(l.color)) {
      throw InputError(file, owner + ": intensity " + std::to_string(l.intensity) +
                                 " x colour is not a finite float (at most ~3.4e38)");
    }
  }
}

void check_camera(const Camera& c, const std::string& file) {
  if (!finite(c.position) || !finite(c.forward) || !finite(c.up)) {
    throw InputError(file, "the camera's node world transform is not finite (it overflows float)");
  }
  if (!all_finite({c.yfov, c.ymag, c.znear, c.zfar})) {
    throw InputError(file, "the camera has a non-finite yfov, ymag, znear or zfar");
  }
}

void check_emitters(const Scene& scene, const std::string& file) {
  for (const ParticleEmitter& e : scene.emitters) {
    const bool ok = finite(e.origin) && finite(e.spawn_extent) && finite(e.velocity_min) && finite(e.velocity_max) &&
                    finite(e.acceleration) && finite(e.color_start) && finite(e.color_end) &&
                    all_finite({e.lifetime, e.size_start, e.size_end});
    if (!ok) throw InputError(file, "particle emitter '" + e.name + "' has a non-finite value after its node transform");
  }
}

}  // namespace

void check_scene_finite(const Scene& scene, const std::string& file) {
  check_lights(scene, file);
  if (scene.camera.from_file) check_camera(scene.camera, file);
  check_emitters(scene, file);
}

}  // namespace vct
