// What one voxel fragment writes (both voxelization programs): the fragment count, the facing
// bit (solid voxelization / thickening), then either fixed-point sums (deterministic) or the
// OpenGL Insights ch. 22 compare-and-swap running average on packed RGBA8.
#include "voxel_fixed.glsl"
uniform int u_reduction;  // 0 fixed point, 1 CAS RGBA8
layout(binding = 0, r32ui) uniform coherent volatile uimage3D u_sum_r;  // CAS: the packed value
layout(binding = 1, r32ui) uniform coherent volatile uimage3D u_sum_g;
layout(binding = 2, r32ui) uniform coherent volatile uimage3D u_sum_b;
layout(binding = 3, r32ui) uniform coherent volatile uimage3D u_count;
// Solid voxelization and thickening only (bound when either is on): per voxel, one bit per facing
// direction of its triangles (ref/stages/voxel_fill.h facing_direction).
layout(binding = 4, r32ui) uniform coherent volatile uimage3D u_facing;
uniform int u_surface_thickening_voxels;
uniform int u_solid_voxelization;

uint pack_rgba8(vec4 v) {
  uvec4 b = uvec4(clamp(v, vec4(0.0f), vec4(255.0f)));  // truncation, as in the chapter's code
  return b.x | (b.y << 8u) | (b.z << 16u) | (b.w << 24u);
}
vec4 unpack_rgba8(uint v) {
  return vec4(float(v & 0xFFu), float((v >> 8u) & 0xFFu), float((v >> 16u) & 0xFFu), float(v >> 24u));
}

void cas_average(ivec3 c, vec3 value) {
  vec4 add = vec4(value * 255.0f, 1.0f);
#ifdef VCT_FAULT_LOST_UPDATE
  imageStore(u_sum_r, c, uvec4(pack_rgba8(add)));  // fault: the race's outcome, every update lost
  return;
#endif
#ifdef VCT_FAULT_RACY_AVERAGE
  {  // fault: plain load / average / store; concurrent fragments overwrite each other
    vec4 r = unpack_rgba8(imageLoad(u_sum_r, c).x);
    r.rgb *= r.a;
    vec4 sum = r + add;
    sum.rgb /= sum.a;
    imageStore(u_sum_r, c, uvec4(pack_rgba8(sum)));
    return;
  }
#endif
  uint next = pack_rgba8(add);
  uint prev = 0u;
  uint cur;
  int guard = 0;
  while ((cur = imageAtomicCompSwap(u_sum_r, c, prev, next)) != prev && guard < 65536) {
    prev = cur;
    vec4 r = unpack_rgba8(cur);
    r.rgb *= r.a;  // de-normalize the running mean
    vec4 sum = r + add;
    sum.rgb /= sum.a;
    next = pack_rgba8(sum);
    ++guard;
  }
}

// `axis`: the triangle's dominant axis, `gn` its geometric normal (the GS's float cross product).
void write_voxel_fragment(ivec3 c, vec3 value, int axis, vec3 gn) {
  imageAtomicAdd(u_count, c, 1u);
  if (u_surface_thickening_voxels > 0 || u_solid_voxelization != 0) {
    // The dominant axis and its sign, from the geometry shader's cross product (the CPU's float
    // cross product: the sign of the largest component cannot differ).
    uint facing = uint(2 * axis + (gn[axis] < 0.0f ? 1 : 0));
    imageAtomicOr(u_facing, c, 1u << facing);
  }
  if (u_reduction == 1) {
    cas_average(c, clamp(value, vec3(0.0f), vec3(1.0f)));
  } else {
    uvec3 q = voxel_fixed_encode(value);
#if defined(VCT_FAULT_LOST_UPDATE)
    // fault: the race's outcome made deterministic: last writer wins, earlier fragments lost
    imageStore(u_sum_r, c, uvec4(q.r));
    imageStore(u_sum_g, c, uvec4(q.g));
    imageStore(u_sum_b, c, uvec4(q.b));
#elif defined(VCT_FAULT_RACY_AVERAGE)
    // fault: non-atomic read-modify-write of the sums
    imageStore(u_sum_r, c, imageLoad(u_sum_r, c) + uvec4(q.r));
    imageStore(u_sum_g, c, imageLoad(u_sum_g, c) + uvec4(q.g));
    imageStore(u_sum_b, c, imageLoad(u_sum_b, c) + uvec4(q.b));
#else
    imageAtomicAdd(u_sum_r, c, q.r);
    imageAtomicAdd(u_sum_g, c, q.g);
    imageAtomicAdd(u_sum_b, c, q.b);
#endif
  }
}
