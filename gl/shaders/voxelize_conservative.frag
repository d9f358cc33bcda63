// Conservative voxelization, per pixel (docs/gl_backend.md, "Conservative voxelization"): the
// triangle is clipped to the pixel's closed square grown by u_clip_dilation (0 for the gs mode;
// the hardware's stated over-estimation for nv / intel), and every voxel of the pixel's column
// between floor(min depth) and floor(max depth) of the clipped polygon is written: exactly the
// voxels the triangle meets in that column (a point of the triangle in voxel (i, j, k) lies in
// pixel (i, j)'s square with depth in [k, k+1)). Each voxel is one fragment of this triangle,
// shaded at the triangle's point closest to the voxel centre, as ref/stages/voxelize_conservative.cpp
// places its fragments. A pixel whose grown square misses the triangle is discarded (gs: the
// bounding quad's corners), or, for hardware, writes one voxel at the triangle's mean depth so
// that a fragment beyond the extension's stated bound shows in the occupancy judge.
#define VCT_UV_GRADIENTS 1
#include "voxel_value.glsl"
#include "alpha_mask.glsl"
#include "voxel_write.glsl"

flat in dvec3 c_voxel[3];
flat in vec3 c_position[3];
flat in vec3 c_normal[3];
flat in vec4 c_tangent[3];
flat in vec4 c_uv[3];
flat in vec4 c_color[3];
flat in vec4 c_uv_grad[2];
flat in int c_axis;
flat in vec3 c_geometric_normal;

uniform vec3 u_volume_origin;
uniform float u_volume_size;
uniform float u_clip_dilation;
uniform int u_keep_outside;

const int kMaxPolygon = 9;  // a triangle clipped by 4 half-planes has at most 7 vertices

// In-plane axes of the projection: (u, v) = window (x, y), d = depth along the axis.
dvec3 to_uvd(dvec3 p) {
  if (c_axis == 2) return p;
  if (c_axis == 0) return dvec3(p.y, p.z, p.x);
  return dvec3(p.x, p.z, p.y);
}
ivec3 voxel_of(ivec2 px, int d) {
  if (c_axis == 2) return ivec3(px, d);
  if (c_axis == 0) return ivec3(d, px.x, px.y);
  return ivec3(px.x, d, px.y);
}

// Sutherland-Hodgman against the closed half-plane sign * (p[c] - bound) >= 0.
int clip(inout dvec3 poly[kMaxPolygon], int n, int c, double bound, double sign) {
  dvec3 out_poly[kMaxPolygon];
  int m = 0;
  for (int k = 0; k < n; ++k) {
    dvec3 a = poly[k], b = poly[(k + 1) % n];
    double da = sign * (a[c] - bound), db = sign * (b[c] - bound);
    if (da >= 0.0lf && m < kMaxPolygon) out_poly[m++] = a;
    if ((da >= 0.0lf) != (db >= 0.0lf) && m < kMaxPolygon) out_poly[m++] = a + (b - a) * (da / (da - db));
  }
  for (int k = 0; k < m; ++k) poly[k] = out_poly[k];
  return m;
}

// Barycentrics (b1, b2) of the triangle's point closest to p (Ericson, Real-Time Collision
// Detection §5.1.5: Voronoi regions of the vertices, edges and face), in double.
dvec2 closest_barycentrics(dvec3 p) {
  dvec3 a = c_voxel[0], b = c_voxel[1], c = c_voxel[2];
  dvec3 ab = b - a, ac = c - a, ap = p - a;
  double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0lf && d2 <= 0.0lf) return dvec2(0.0lf);
  dvec3 bp = p - b;
  double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0lf && d4 <= d3) return dvec2(1.0lf, 0.0lf);
  double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0lf && d1 >= 0.0lf && d3 <= 0.0lf) return dvec2(d1 / (d1 - d3), 0.0lf);
  dvec3 cp = p - c;
  double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0lf && d5 <= d6) return dvec2(0.0lf, 1.0lf);
  double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0lf && d2 >= 0.0lf && d6 <= 0.0lf) return dvec2(0.0lf, d2 / (d2 - d6));
  double va = d3 * d6 - d5 * d4;
  if (va <= 0.0lf && (d4 - d3) >= 0.0lf && (d5 - d6) >= 0.0lf) {
    double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return dvec2(1.0lf - w, w);
  }
  double denom = 1.0lf / (va + vb + vc);
  return dvec2(vb * denom, vc * denom);
}

// One fragment of this triangle in voxel c: the surface at the point closest to c's centre.
void voxel_fragment(ivec3 c) {
  dvec2 bd = closest_barycentrics(dvec3(c) + 0.5lf);
  float b1 = float(bd.x), b2 = float(bd.y), b0 = 1.0f - b1 - b2;
  vec4 uv = b0 * c_uv[0] + b1 * c_uv[1] + b2 * c_uv[2];
  vec4 color = b0 * c_color[0] + b1 * c_color[1] + b2 * c_color[2];
#ifndef VCT_FAULT_ALPHA_VOXEL
  if (alpha_masked(uv.xy, uv.zw, color.a)) return;  // tested where the CPU tests it: the same point
#endif
  vec3 position = b0 * c_position[0] + b1 * c_position[1] + b2 * c_position[2];
  vec3 normal = b0 * c_normal[0] + b1 * c_normal[1] + b2 * c_normal[2];
  vec4 tangent = b0 * c_tangent[0] + b1 * c_tangent[1] + b2 * c_tangent[2];
  vec3 tex = (position - u_volume_origin) / u_volume_size;
  vec3 value = voxel_radiance(position, normal, tangent, uv.xy, uv.zw, color, tex);
  write_voxel_fragment(c, value, c_axis, c_geometric_normal);
}

void main() {
  g_uv_grad[0] = c_uv_grad[0];
  g_uv_grad[1] = c_uv_grad[1];
  ivec2 px = ivec2(gl_FragCoord.xy);
  double r = double(u_clip_dilation);
  dvec3 poly[kMaxPolygon];
  for (int k = 0; k < 3; ++k) poly[k] = to_uvd(c_voxel[k]);
  int n = 3;
  n = clip(poly, n, 0, double(px.x) - r, 1.0lf);
  if (n > 0) n = clip(poly, n, 0, double(px.x + 1) + r, -1.0lf);
  if (n > 0) n = clip(poly, n, 1, double(px.y) - r, 1.0lf);
  if (n > 0) n = clip(poly, n, 1, double(px.y + 1) + r, -1.0lf);
  // With no dilation the square is half-open as the CPU's voxel boxes are: a polygon that only
  // touches the pixel's upper u or v edge belongs to the next pixel (docs/pipeline.md, "Voxelizers").
  if (n > 0 && r == 0.0lf) {
    double umin = poly[0].x, vmin = poly[0].y;
    for (int k = 1; k < n; ++k) {
      umin = min(umin, poly[k].x);
      vmin = min(vmin, poly[k].y);
    }
    if (umin >= double(px.x + 1) || vmin >= double(px.y + 1)) n = 0;
  }
  int last = u_grid - 1;
  if (n == 0) {
    if (u_keep_outside == 0) discard;
    double mean = (to_uvd(c_voxel[0]).z + to_uvd(c_voxel[1]).z + to_uvd(c_voxel[2]).z) / 3.0lf;
    voxel_fragment(voxel_of(px, int(clamp(floor(mean), 0.0lf, double(last)))));
    return;
  }
  double lo = poly[0].z, hi = poly[0].z;
  for (int k = 1; k < n; ++k) {
    lo = min(lo, poly[k].z);
    hi = max(hi, poly[k].z);
  }
#ifdef VCT_FAULT_HALF_TEXEL
  lo += 0.5lf;  // fault: voxel depth coordinate offset by half a voxel
  hi += 0.5lf;
#endif
  int k0 = int(clamp(floor(lo), 0.0lf, double(last))), k1 = int(clamp(floor(hi), 0.0lf, double(last)));
  for (int k = k0; k <= k1; ++k) voxel_fragment(voxel_of(px, k));
}
