// Cone marching through the voxel mips with GL's own filtering: textureLod on 3D textures with
// LINEAR_MIPMAP_LINEAR and CLAMP_TO_BORDER (border 0). The loop follows docs/pipeline.md
// ("Cone marching"); the CPU's ref/stages/cone_trace.cpp is the independent twin.
layout(binding = 5) uniform sampler3D u_voxels;
layout(binding = 6) uniform sampler3D u_aniso_px;
layout(binding = 7) uniform sampler3D u_aniso_nx;
layout(binding = 8) uniform sampler3D u_aniso_py;
layout(binding = 9) uniform sampler3D u_aniso_ny;
layout(binding = 10) uniform sampler3D u_aniso_pz;
layout(binding = 11) uniform sampler3D u_aniso_nz;
uniform int u_anisotropic;
uniform int u_grid;
uniform float u_cone_start;     // texture units (MarchParams::start_offset)
uniform float u_shadow_cone_start;  // texture units (MarchParams::shadow_from_settings)
// cone_start = normal: diffuse and specular origins move this far along the surface normal
// (MarchParams::normal_offset, texture units; 0 for cone_start = axis).
uniform float u_cone_normal_offset;
uniform float u_cone_max_distance;
uniform float u_cone_quality;
uniform int u_opacity_step_correction;

// A directional chain is [shared base level, aniso level 0 (= mip 1), ...].
vec4 sample_direction(int d, vec3 uvw, float lod) {
  vec4 upper;
  float l = max(lod - 1.0f, 0.0f);
  if (d == 0) upper = textureLod(u_aniso_px, uvw, l);
  else if (d == 1) upper = textureLod(u_aniso_nx, uvw, l);
  else if (d == 2) upper = textureLod(u_aniso_py, uvw, l);
  else if (d == 3) upper = textureLod(u_aniso_ny, uvw, l);
  else if (d == 4) upper = textureLod(u_aniso_pz, uvw, l);
  else upper = textureLod(u_aniso_nz, uvw, l);
  if (lod >= 1.0f) return upper;
  vec4 base = textureLod(u_voxels, uvw, 0.0f);
  float f = max(lod, 0.0f);
  return f == 0.0f ? base : (1.0f - f) * base + f * upper;
}

vec4 sample_voxels(vec3 uvw, float lod, vec3 dir) {
  if (u_anisotropic == 0) return textureLod(u_voxels, uvw, lod);
  vec3 w = dir * dir;
  vec4 r = vec4(0.0f);
  if (w.x > 0.0f) r += w.x * sample_direction(dir.x >= 0.0f ? 0 : 1, uvw, lod);
  if (w.y > 0.0f) r += w.y * sample_direction(dir.y >= 0.0f ? 2 : 3, uvw, lod);
  if (w.z > 0.0f) r += w.z * sample_direction(dir.z >= 0.0f ? 4 : 5, uvw, lod);
  return r;
}

bool inside_unit_cube(vec3 p) { return all(greaterThanEqual(p, vec3(0.0f))) && all(lessThanEqual(p, vec3(1.0f))); }

// Returns (radiance, opacity) accumulated front to back (rgb premultiplied); the first sample at
// distance t0 (u_cone_start, or u_shadow_cone_start for the soft-shadow cones).
vec4 trace_cone(vec3 origin, vec3 dir, float aperture, float t0, float max_distance, float min_lod) {
  float voxel = 1.0f / float(u_grid);
  float tan_half = tan(0.5f * aperture);
  vec3 color = vec3(0.0f);
  float alpha = 0.0f;
  float t = t0;
#ifdef VCT_FAULT_CONE_STEP
  t += max(voxel, 2.0f * t * tan_half) * u_cone_quality;  // fault: the march starts one step late
#endif
  while (alpha < 1.0f && t < max_distance) {
    vec3 pos = origin + dir * t;
    if (!inside_unit_cube(pos)) break;
    float diameter = max(voxel, 2.0f * t * tan_half);
    float lod = max(log2(diameter / voxel), min_lod);
    float step = max(diameter * u_cone_quality, 1e-6f);
    vec4 s = sample_voxels(pos, lod, dir);
    // dt0 = the side of a voxel of the level sampled (vct_shared.h step_corrected_sample).
    if (u_opacity_step_correction != 0) s = step_corrected_sample(s, step / (voxel * exp2(lod)));
    float transmit = 1.0f - alpha;
    color += transmit * s.rgb;
    alpha += transmit * s.a;
    t += step;
  }
  return vec4(color, min(alpha, 1.0f));
}

uniform float u_diffuse_aperture;  // radians
// The cone set as the host computed it (stages/cone_sets.h, diffuse_cone_block): count, sin/cos
// of the tilt, azimuth step and weights are the CPU's floats.
layout(std140, binding = 1) uniform DiffuseConeUbo { DiffuseConeBlock u_diffuse_set; };

// The diffuse cone set at texture-space point `origin` with unit normal n.
vec3 trace_diffuse(vec3 origin, vec3 n, float rotation, float min_lod) {
  Frame f = frame_from_normal(n);
  origin += n * u_cone_normal_offset;
  vec3 sum = vec3(0.0f);
  int count = diffuse_cone_count(u_diffuse_set);
  for (int i = 0; i < count; ++i) {
    vec3 dir = normalize(frame_to_world(f, diffuse_cone_direction(i, rotation, u_diffuse_set)));
    vec4 c = trace_cone(origin, dir, u_diffuse_aperture, u_cone_start, u_cone_max_distance, min_lod);
    sum += diffuse_cone_weight(i, u_diffuse_set) * c.rgb;
  }
  return sum;
}
