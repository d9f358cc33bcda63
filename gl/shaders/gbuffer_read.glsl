// Reading the G-buffer of this pixel (bindings 12..17).
layout(binding = 12) uniform sampler2D u_g_position;  // w = coverage
layout(binding = 13) uniform sampler2D u_g_normal;
layout(binding = 14) uniform sampler2D u_g_albedo;
layout(binding = 15) uniform sampler2D u_g_material;
layout(binding = 16) uniform sampler2D u_g_specular_color;
layout(binding = 17) uniform sampler2D u_g_emission;
#include "camera.glsl"
uniform vec3 u_volume_origin;
uniform float u_volume_size;

struct GSample {
  bool covered;
  vec3 position;
  vec3 normal;
  SurfacePbr pbr;
  vec3 emission;
};

GSample read_gbuffer(ivec2 px) {
  GSample g;
  vec4 p = texelFetch(u_g_position, px, 0);
  g.covered = p.w > 0.0f;
  g.position = p.xyz;
  g.normal = texelFetch(u_g_normal, px, 0).xyz;
  vec4 m = texelFetch(u_g_material, px, 0);
  g.pbr = surface_pbr(texelFetch(u_g_albedo, px, 0).rgb, m.x, m.y, m.z, texelFetch(u_g_specular_color, px, 0).rgb);
  g.emission = texelFetch(u_g_emission, px, 0).rgb;
  return g;
}

vec3 to_volume(vec3 world) { return (world - u_volume_origin) / u_volume_size; }
