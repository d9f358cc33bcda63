// One punctual light seen from a surface point, for every CPU stage that shades (direct light,
// injection, soft shadows, explain): the direction toward the light and the irradiance it delivers,
// both from the shared definitions of vct_shared.h so the GL shaders compute the same numbers.
#pragma once

#include "core/settings.h"
#include "scene/scene.h"

namespace vct {

struct LightSample {
  vec3 l{0.0f, 0.0f, 1.0f};  // unit, from the point toward the light
  float distance = 0.0f;     // to the light's position; +infinity for a directional light
  vec3 irradiance{0.0f};     // on a surface facing the light, before n.l and shadowing
};

/// The LIGHT_MODEL_* constant of vct_shared.h for a settings value.
int shared_light_model(LightModel model);

/// The light as seen from p: sh::to_light_direction and sh::punctual_irradiance.
LightSample sample_light(const Light& light, LightModel model, const vec3& p);

}  // namespace vct
