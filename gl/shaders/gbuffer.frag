// Camera pass: the G-buffer (layout of vct::GBuffer). Normals face the camera: back faces flip the
// interpolated normal and tangent frame before normal mapping. Alpha-masked fragments are discarded (alpha_mask.glsl).
#include "surface.glsl"
#include "alpha_mask.glsl"
in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv0;
in vec2 v_uv1;
in vec4 v_color;  // COLOR_0

layout(location = 0) out vec4 o_position;  // xyz, w = coverage
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_albedo;
layout(location = 3) out vec4 o_material;  // metallic, roughness, specular_factor, 0
layout(location = 4) out vec4 o_specular_color;
layout(location = 5) out vec4 o_emission;

void main() {
  if (alpha_masked(v_uv0, v_uv1, v_color.a)) discard;
  float len = length(v_normal);
  vec3 n = len > 0.0f ? v_normal / len : vec3(0.0f, 0.0f, 1.0f);
  // A back face turns its whole tangent frame, as the reference negates the shading normal
  // (ref/stages/gbuffer.cpp) and the Khronos sample viewer flips t, b and n: flipping n alone
  // would mirror the normal map's tangent-direction tilt (scenes/regressions/seed-66-small).
  vec4 t = v_tangent;
  if (!gl_FrontFacing) {
    n = -n;
    t = -t;  // xyz and the handedness w: b = cross(n, t) w turns with them
  }
  SurfaceMaterial m = evaluate_material(n, t, v_uv0, v_uv1, v_color);
  o_position = vec4(v_position, 1.0f);
  o_normal = vec4(m.shading_normal, 0.0f);
  o_albedo = vec4(m.albedo, 0.0f);
  o_material = vec4(m.metallic, m.roughness, m.specular_factor, 0.0f);
  o_specular_color = vec4(m.specular_color, 0.0f);
  o_emission = vec4(m.emission, 0.0f);
}
