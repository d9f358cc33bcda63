// Anisotropic mip level for one march direction: along the direction's axis the two children are
// composited front to back (front = the one a cone marching that way meets first), and the four
// such pairs across the other two axes are averaged. Alpha is clamped to 1.
#include "half_round.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
uniform int u_storage_format;  // 0 RGBA16F, 1 RGBA8: rounded here (half_round.glsl)
layout(binding = 0) uniform sampler3D u_src;
layout(binding = 0) uniform writeonly image3D u_dst;
uniform int u_src_level;
uniform int u_dst_size;
uniform int u_axis;      // 0 x, 1 y, 2 z
uniform int u_positive;  // 1: marching toward +axis (front = lower index)

void main() {
  ivec3 c = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(c, ivec3(u_dst_size)))) return;
  ivec3 along = ivec3(0);
  along[u_axis] = 1;
  int u_axis1 = (u_axis + 1) % 3, u_axis2 = (u_axis + 2) % 3;
  vec4 sum = vec4(0.0f);
  for (int b = 0; b < 2; ++b) {
    for (int a = 0; a < 2; ++a) {
      ivec3 o = ivec3(0);
      o[u_axis1] = a;
      o[u_axis2] = b;
      ivec3 lo = 2 * c + o;
      vec4 near_v = texelFetch(u_src, u_positive != 0 ? lo : lo + along, u_src_level);
      vec4 far_v = texelFetch(u_src, u_positive != 0 ? lo + along : lo, u_src_level);
      vec4 comp;
      comp.rgb = near_v.rgb + (1.0f - near_v.a) * far_v.rgb;
#ifdef VCT_FAULT_ALPHA_UNCLAMPED
      comp.a = near_v.a + far_v.a;  // fault: opacities added, not composited, and never clamped
#else
      comp.a = near_v.a + (1.0f - near_v.a) * far_v.a;
#endif
      sum += comp;
    }
  }
  vec4 r = sum * 0.25f;
#ifndef VCT_FAULT_ALPHA_UNCLAMPED
  r.a = min(r.a, 1.0f);
#endif
  imageStore(u_dst, c, storage_value(r, u_storage_format));
}
