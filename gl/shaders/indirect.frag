// Indirect light and the final composition: diffuse cone set (rotated per pixel with the shared
// hash), specular cone along reflect(-v, n); final = direct + kd*albedo*diffuse + F*specular +
// emission (particles are added afterwards by their own additive pass).
#include "cone.glsl"
#include "gbuffer_read.glsl"
layout(binding = 18) uniform sampler2D u_direct;
uniform int u_diffuse_cones;
uniform int u_specular_cones;
uniform int u_random_rotation;
uniform uint u_frame;
uniform int u_image_height;
uniform float u_indirect_diffuse_gain;  // an engine's gain on the indirect diffuse (settings.h)

layout(location = 0) out vec4 o_indirect_diffuse;
layout(location = 1) out vec4 o_indirect_specular;
layout(location = 2) out vec4 o_diffuse_term;
layout(location = 3) out vec4 o_specular_term;
layout(location = 4) out vec4 o_final;

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  GSample g = read_gbuffer(px);
  o_indirect_diffuse = vec4(0.0f);
  o_indirect_specular = vec4(0.0f);
  o_diffuse_term = vec4(0.0f);
  o_specular_term = vec4(0.0f);
  o_final = vec4(0.0f);
  if (!g.covered) return;
  vec3 origin = to_volume(g.position);
  vec3 v = to_eye(g.position);
  vec3 diffuse = vec3(0.0f);
  if (u_diffuse_cones != 0) {
    // The hash takes the pixel's row counted from the top, as the CPU's images do.
    float rotation = u_random_rotation != 0
                         ? diffuse_cone_rotation(uint(px.x), uint(u_image_height - 1 - px.y), u_frame, u_diffuse_set)
                         : 0.0f;
    diffuse = trace_diffuse(origin, g.normal, rotation, 0.0f) * u_indirect_diffuse_gain;
  }
  vec3 specular = vec3(0.0f);
  if (u_specular_cones != 0) {
    vec3 dir = normalize(reflect(-v, g.normal));
    float aperture = specular_cone_aperture(max(g.pbr.roughness, MIN_ROUGHNESS));
    specular = trace_cone(origin + g.normal * u_cone_normal_offset, dir, aperture, u_cone_start, u_cone_max_distance, 0.0f).rgb;
  }
  vec3 f = fresnel_schlick(g.pbr.f0, g.pbr.f90, max(dot(g.normal, v), 0.0f));
  vec3 diffuse_term = diffuse_weight(g.pbr, f) * g.pbr.albedo * diffuse;
  vec3 specular_term = f * specular;
  o_indirect_diffuse = vec4(diffuse, 0.0f);
  o_indirect_specular = vec4(specular, 0.0f);
  o_diffuse_term = vec4(diffuse_term, 0.0f);
  o_specular_term = vec4(specular_term, 0.0f);
  o_final = vec4(texelFetch(u_direct, px, 0).rgb + diffuse_term + specular_term + g.emission, 0.0f);
}
