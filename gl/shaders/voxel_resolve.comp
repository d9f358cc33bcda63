// Resolve pass: per voxel, the mean of its fragments (fixed-point sums / count, or the unpacked
// CAS RGBA8 value), opacity 1 where any fragment landed, plus the additive particle light.
#include "voxel_fixed.glsl"
#include "half_round.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, r32ui) uniform readonly uimage3D u_sum_r;
layout(binding = 1, r32ui) uniform readonly uimage3D u_sum_g;
layout(binding = 2, r32ui) uniform readonly uimage3D u_sum_b;
layout(binding = 3, r32ui) uniform readonly uimage3D u_count;
layout(binding = 4, r32ui) uniform readonly uimage3D u_particle_r;
layout(binding = 5, r32ui) uniform readonly uimage3D u_particle_g;
layout(binding = 6, r32ui) uniform readonly uimage3D u_particle_b;
layout(binding = 7) uniform writeonly image3D u_out;
uniform int u_grid;
uniform int u_reduction;  // 0 fixed point, 1 CAS RGBA8
uniform int u_storage_format;  // 0 RGBA16F, 1 RGBA8 (half_round.glsl)

void main() {
  ivec3 c = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(c, ivec3(u_grid)))) return;
  uint count = imageLoad(u_count, c).r;
  vec4 v = vec4(0.0f);
  if (count > 0u) {
    if (u_reduction == 1) {
      uint p = imageLoad(u_sum_r, c).r;
      v.rgb = vec3(float(p & 0xFFu), float((p >> 8u) & 0xFFu), float((p >> 16u) & 0xFFu)) / 255.0f;
    } else {
      uvec3 s = uvec3(imageLoad(u_sum_r, c).r, imageLoad(u_sum_g, c).r, imageLoad(u_sum_b, c).r);
      v.rgb = voxel_fixed_decode_mean(s, count);
    }
    v.a = 1.0f;
  }
  uvec3 ps = uvec3(imageLoad(u_particle_r, c).r, imageLoad(u_particle_g, c).r, imageLoad(u_particle_b, c).r);
  v.rgb += vec3(ps) * FIXED_POINT_INV_SCALE;
  imageStore(u_out, c, storage_value(v, u_storage_format));
}
