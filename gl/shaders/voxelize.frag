// One fragment = one surface sample in one voxel: the in-plane voxel indices are the pixel's, the
// depth index is floor of the interpolated voxel-space coordinate along the projection axis
// (clamped to the grid).
// Writes through voxel_write.glsl (count, facing, fixed-point sums or the CAS average). Alpha-
// masked fragments are discarded first (alpha_mask.glsl).
#include "voxel_value.glsl"
#include "voxel_fixed.glsl"
#include "alpha_mask.glsl"
#include "voxel_write.glsl"
in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv0;
in vec2 v_uv1;
in vec4 v_color;  // COLOR_0
in vec3 v_tex;
flat in int v_axis;
flat in vec3 v_geometric_normal;
flat in dvec3 v_axis_depth;
noperspective in vec3 v_bary;

ivec3 voxel_coords() {
  int n = u_grid;
  ivec2 px = ivec2(gl_FragCoord.xy);
  // Relative to vertex 0, so a triangle of constant depth (a wall lying exactly on a voxel
  // boundary, e.g. a plane through the volume's centre) gets exactly that depth whatever the
  // barycentrics' rounding: b0*d0 + b1*d1 + b2*d2 splits such a wall between two layers.
  double depth = v_axis_depth.x + double(v_bary.y) * (v_axis_depth.y - v_axis_depth.x) +
                 double(v_bary.z) * (v_axis_depth.z - v_axis_depth.x);
#ifdef VCT_FAULT_HALF_TEXEL
  depth += 0.5lf;  // fault: voxel coordinate offset by half a voxel
#endif
  int d = int(clamp(floor(depth), 0.0lf, double(n - 1)));
  if (v_axis == 2) return ivec3(px.x, px.y, d);
  if (v_axis == 0) return ivec3(d, px.x, px.y);
  return ivec3(px.x, d, px.y);
}

void main() {
#ifndef VCT_FAULT_ALPHA_VOXEL
  // A masked fragment adds neither opacity (count) nor light, tested at the pixel centre as the
  // CPU's GPU-rule voxelizer tests it (ref/stages/voxelize_gpu.cpp).
  if (alpha_masked(v_uv0, v_uv1, v_color.a)) discard;
#endif
  ivec3 c = voxel_coords();
  vec3 value = voxel_radiance(v_position, v_normal, v_tangent, v_uv0, v_uv1, v_color, v_tex);
  write_voxel_fragment(c, value, v_axis, v_geometric_normal);
}
