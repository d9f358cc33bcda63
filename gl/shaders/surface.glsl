// The textured material at a surface point: the GLSL twin of ref/scene/surface.cpp's
// evaluate_material (same factors, same glTF channel use, same normal-map frame). Texture
// filtering itself is GL's: SRGB8_ALPHA8 decode before filtering, the glTF sampler's filters, and
// in fragment shaders the implicit LOD from the quad's derivatives (GL 4.5 §8.14) over the mip
// chain the CPU built and gl_scene.cpp uploaded.
uniform vec4 u_base_color_factor;
uniform float u_metallic_factor;
uniform float u_roughness_factor;
uniform float u_normal_scale;
uniform int u_normal_two_channel;
uniform vec3 u_emission;           // emissive_factor * emissive_strength
uniform float u_specular_factor;
uniform vec3 u_specular_color;
// Texture slots: 0 base colour, 1 metallic-roughness, 2 normal, 3 emissive.
uniform int u_vertex_colors;  // the scene has COLOR_0 (gl_scene.cpp bind_material)
uniform int u_tex_present[4];
uniform int u_tex_coord[4];
uniform mat3 u_tex_transform[4];
layout(binding = 0) uniform sampler2D u_tex_base;
layout(binding = 1) uniform sampler2D u_tex_mr;
layout(binding = 2) uniform sampler2D u_tex_normal;
layout(binding = 3) uniform sampler2D u_tex_emissive;

struct SurfaceMaterial {
  vec3 albedo;
  float metallic;
  float roughness;
  float specular_factor;
  vec3 specular_color;
  vec3 emission;
  vec3 shading_normal;
};

#ifdef VCT_UV_GRADIENTS
// Set by a shader that evaluates the material away from its fragment's own interpolated point
// (the conservative voxelizer shades each voxel at the triangle's point closest to the voxel
// centre, voxelize_conservative.frag): per texture coordinate set, (d/dx, d/dy) of the UV per
// window pixel of the voxel raster, i.e. what the quad's derivatives would be on the triangle
// (GL 4.5 §8.14.1), passed to textureGrad so the LOD is the voxel grid's footprint as the CPU's
// stages/voxel_lod.h computes it.
vec4 g_uv_grad[2];
#endif

vec4 material_texture(sampler2D s, int slot, vec2 uv) {
#ifdef VCT_FAULT_TEXTURE_LEVEL_ZERO
  return textureLod(s, uv, 0.0f);  // fault: every lookup at level 0, minified textures alias
#elif defined(VCT_UV_GRADIENTS)
  vec4 g = g_uv_grad[u_tex_coord[slot] == 1 ? 1 : 0];
  mat2 t = mat2(u_tex_transform[slot]);  // the transform's linear part moves the gradient
  return textureGrad(s, uv, t * g.xy, t * g.zw);
#else
  return texture(s, uv);
#endif
}

// An sRGB slot's decoded lookup (base colour, emissive). The srgb_decode_step fault decodes one
// step of the 8-bit encoding high: twice the precision GL's decode is allowed (core/precision.h,
// srgb-decode: half a step), so voxel.radiance must fail (IEC 61966-2-1 transfer functions).
vec4 srgb_slot(vec4 v) {
#ifdef VCT_FAULT_SRGB_DECODE_STEP
  vec3 c = clamp(v.rgb, 0.0f, 1.0f);
  vec3 e = mix(c * 12.92f, 1.055f * pow(c, vec3(1.0f / 2.4f)) - 0.055f, greaterThan(c, vec3(0.0031308f)));
  e = clamp(e + 1.0f / 255.0f, 0.0f, 1.0f);
  v.rgb = mix(e / 12.92f, pow((e + 0.055f) / 1.055f, vec3(2.4f)), greaterThan(e, vec3(0.04045f)));
#endif
  return v;
}

vec2 slot_uv(int slot, vec2 uv0, vec2 uv1) {
  vec2 uv = u_tex_coord[slot] == 1 ? uv1 : uv0;
  return (u_tex_transform[slot] * vec3(uv, 1.0f)).xy;
}

vec3 apply_normal_map(vec3 normal, vec4 tangent, vec3 tn, float scale) {
  tn.x *= scale;
  tn.y *= scale;
  vec3 t = tangent.xyz - normal * dot(normal, tangent.xyz);
  float tl = length(t);
  if (tl < 1e-8f) return normal;
  t /= tl;
  vec3 b = cross(normal, t) * (tangent.w < 0.0f ? -1.0f : 1.0f);
  vec3 n = t * tn.x + b * tn.y + normal * tn.z;
  float nl = length(n);
  return nl > 1e-8f ? n / nl : normal;
}

// `normal` is the interpolated vertex normal (already unit), `tangent` the interpolated tangent,
// `color` the interpolated COLOR_0 (white without it).
SurfaceMaterial evaluate_material(vec3 normal, vec4 tangent, vec2 uv0, vec2 uv1, vec4 color) {
  SurfaceMaterial s;
  vec4 base = u_base_color_factor;
  if (u_tex_present[0] != 0) base *= srgb_slot(material_texture(u_tex_base, 0, slot_uv(0, uv0, uv1)));
  if (u_vertex_colors != 0) base *= color;  // glTF 2.0 §3.9.2: factor x texture x COLOR_0
  s.albedo = base.rgb;
  s.metallic = u_metallic_factor;
  s.roughness = u_roughness_factor;
  if (u_tex_present[1] != 0) {
    vec4 mr = material_texture(u_tex_mr, 1, slot_uv(1, uv0, uv1));
    s.roughness *= mr.g;
    s.metallic *= mr.b;
  }
  s.specular_factor = u_specular_factor;
  s.specular_color = u_specular_color;
  s.emission = u_emission;
  if (u_tex_present[3] != 0) s.emission *= srgb_slot(material_texture(u_tex_emissive, 3, slot_uv(3, uv0, uv1))).rgb;
  s.shading_normal = normal;
  if (u_tex_present[2] != 0) {
    vec4 texel = material_texture(u_tex_normal, 2, slot_uv(2, uv0, uv1));
    vec3 tn = texel.xyz * 2.0f - 1.0f;
    if (u_normal_two_channel != 0) tn.z = sqrt(max(0.0f, 1.0f - tn.x * tn.x - tn.y * tn.y));
    s.shading_normal = apply_normal_map(normal, tangent, tn, u_normal_scale);
  }
  return s;
}
