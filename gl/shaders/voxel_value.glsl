// Light leaving a voxelized surface point: albedo/pi x each light's irradiance x n.l x shadow + emission,
// plus (multibounce frames) restitution x albedo x the diffuse cones of the previous frame.
#include "surface.glsl"
#include "lights.glsl"
#include "cone.glsl"
uniform int u_bounce;          // 0 = first frame (no indirect term)
uniform float u_restitution;

vec3 voxel_radiance(vec3 position, vec3 normal, vec4 tangent, vec2 uv0, vec2 uv1, vec4 color, vec3 tex) {
  float len = length(normal);
  vec3 n0 = len > 0.0f ? normal / len : vec3(0.0f, 0.0f, 1.0f);
  SurfaceMaterial m = evaluate_material(n0, tangent, uv0, uv1, color);
  vec3 n = m.shading_normal;
  vec3 irradiance = vec3(0.0f);
  for (int i = 0; i < u_light_count; ++i) {
    vec3 l = light_vector(i, position);
    float n_dot_l = dot(n, l);
    vec3 e = light_irradiance(i, position);
    if (n_dot_l <= 0.0f || e == vec3(0.0f)) continue;
    irradiance += e * n_dot_l * surface_visibility(i, position, n);
  }
  vec3 radiance = m.albedo * irradiance * SH_INV_PI + m.emission;
  if (u_bounce > 0) radiance += u_restitution * m.albedo * trace_diffuse(tex, n, 0.0f, 1.0f);
  return radiance;
}
