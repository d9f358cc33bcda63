// The deterministic reduction's encoding, from the shared header ref/shared/voxel_fixed_point.h
// (the CPU's reduction uses the same functions, so sums and resolves agree bit for bit).
#include "voxel_fixed_point.h"
uvec3 voxel_fixed_encode(vec3 v) {
  return uvec3(fixed_point_encode(v.r), fixed_point_encode(v.g), fixed_point_encode(v.b));
}
vec3 voxel_fixed_decode_mean(uvec3 sum, uint count) {
  return vec3(fixed_point_resolve(sum.r, count), fixed_point_resolve(sum.g, count), fixed_point_resolve(sum.b, count));
}
