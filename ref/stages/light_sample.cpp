#include "stages/light_sample.h"

#include <cmath>
#include <limits>

#include "shared/vct_shared.h"

namespace vct {

int shared_light_model(LightModel model) {
  return model == LightModel::Seed ? sh::LIGHT_MODEL_SEED : sh::LIGHT_MODEL_GLTF;
}

namespace {
// std::cos of a cone angle, the last one remembered per thread and call site: a frame's lookups ask
// for the same light's angles millions of times (the same bits: std::cos is a function).
struct CosMemo {
  float angle = std::numeric_limits<float>::quiet_NaN(), value = 0.0f;
  float operator()(float a) {
    if (!(a == angle)) angle = a, value = std::cos(a);
    return value;
  }
};
}  // namespace

LightSample sample_light(const Light& light, LightModel model, const vec3& p) {
  thread_local CosMemo inner_cos, outer_cos;
  LightSample out;
  const int kind = int(light.kind);
  out.l = sh::to_light_direction(kind, light.position, light.direction, p);
  out.distance = light.is_directional() ? std::numeric_limits<float>::infinity()
                                        : glm::length(light.position - p);
  const float cos_axis = glm::dot(-out.l, glm::normalize(light.direction));
  out.irradiance = sh::punctual_irradiance(
      shared_light_model(model), kind, light.color, light.intensity, out.distance, cos_axis,
      inner_cos(light.inner_cone_angle), outer_cos(light.outer_cone_angle), light.range);
  return out;
}

}  // namespace vct
