// Direct light: Cook–Torrance (vct_shared.h) from every light (spot, point, directional), visibility from the PCF
// shadow map or (soft shadows) from a cone toward the light through the voxels.
#include "lights.glsl"
#include "cone.glsl"
#include "gbuffer_read.glsl"
uniform int u_soft_shadows;
uniform int u_nv_mode;  // the setting n_dot_v as sh::NV_ZERO / NV_ABS / NV_CLAMP (issue 39)
uniform float u_shadow_aperture;  // radians

layout(location = 0) out vec4 o_direct;
layout(location = 1) out vec4 o_soft_shadow;

// The soft-shadow cone toward light i: up to a spot or point light's position; against a
// directional light's direction until it leaves the volume (ref/stages/cone_sets.cpp).
float cone_visibility(int i, vec3 p) {
  vec3 origin = to_volume(p);
#ifdef VCT_FAULT_SOFT_SHADOW_DIRECTION
  // The fault: the cone is traced away from the light (gl_faults.h).
  vec3 away = u_light_kind[i] == LIGHT_KIND_DIRECTIONAL ? normalize(u_light_direction[i])
                                                        : origin - to_volume(u_light_position[i]);
  return 1.0f - trace_cone(origin, normalize(away), u_shadow_aperture, u_shadow_cone_start, u_cone_max_distance, 0.0f).a;
#endif
  if (u_light_kind[i] == LIGHT_KIND_DIRECTIONAL) {
    return 1.0f - trace_cone(origin, -normalize(u_light_direction[i]), u_shadow_aperture, u_shadow_cone_start, u_cone_max_distance, 0.0f).a;
  }
  vec3 to_light = to_volume(u_light_position[i]) - origin;
  float dist = length(to_light);
  if (dist <= 0.0f) return 1.0f;
  return 1.0f - trace_cone(origin, to_light / dist, u_shadow_aperture, u_shadow_cone_start, min(u_cone_max_distance, dist), 0.0f).a;
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  GSample g = read_gbuffer(px);
  o_direct = vec4(0.0f);
  o_soft_shadow = vec4(1.0f);  // as the CPU: 1 where nothing is covered, else the mean over lights
  if (!g.covered) return;
  float vis_sum = 0.0f;
  vec3 v = to_eye(g.position);
  vec3 sum = vec3(0.0f);
  for (int i = 0; i < u_light_count; ++i) {
    vec3 l = light_vector(i, g.position);
    float n_dot_l = dot(g.normal, l);
    float vis;
    if (u_soft_shadows != 0) {
      vis = cone_visibility(i, g.position);
      vis_sum += vis;
    } else {
      vis = surface_visibility(i, g.position, g.normal);
    }
    if (n_dot_l <= 0.0f) continue;
    sum += cook_torrance_nv(g.pbr, g.normal, v, l, u_nv_mode) * light_irradiance(i, g.position) * n_dot_l * vis;
  }
  o_direct = vec4(sum, 0.0f);
  if (u_soft_shadows != 0 && u_light_count > 0) o_soft_shadow = vec4(vis_sum / float(u_light_count));
}
