// Isotropic mip level l from level l-1: the box filter over the 2x2x2 children.
#include "half_round.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
uniform int u_storage_format;  // 0 RGBA16F, 1 RGBA8: rounded here (half_round.glsl)
layout(binding = 0) uniform sampler3D u_src;
layout(binding = 0) uniform writeonly image3D u_dst;
uniform int u_src_level;
uniform int u_dst_size;

void main() {
  ivec3 c = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(c, ivec3(u_dst_size)))) return;
  vec4 sum = vec4(0.0f);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
#ifdef VCT_FAULT_WRONG_MIP
      // fault: reads level l-2 (the grandchildren's level) at the children's coordinates
      for (int i = 0; i < 2; ++i) sum += texelFetch(u_src, 2 * c + ivec3(i, j, k), max(u_src_level - 1, 0));
#else
      for (int i = 0; i < 2; ++i) sum += texelFetch(u_src, 2 * c + ivec3(i, j, k), u_src_level);
#endif
  vec4 r = sum * 0.125f;
  imageStore(u_dst, c, storage_value(r, u_storage_format));
}
