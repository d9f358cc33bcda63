// Conservative voxelization, candidates (docs/gl_backend.md, "Conservative voxelization"): the
// dominant-axis projection of voxelize.geom (same axis rule), then either
//  - u_emit_quad = 1 (mode gs, any GL 4.5): the triangle's window-space bounding box grown by half
//    a pixel plus a margin, as a quad. A pixel whose closed square meets the triangle meets its
//    bounding box, so the pixel's centre lies in the box grown by 1/2; the 1/16-pixel margin keeps
//    that centre strictly inside despite vertex snapping (2^-GL_SUBPIXEL_BITS <= 2^-4 px, GL 4.5
//    §14.6) and the fill rule. The fragment shader then clips the triangle to each pixel exactly
//    (the bounding-box cull of Hasselgren et al., GPU Gems 2 ch. 42, made exact);
//  - u_emit_quad = 0 (modes nv, intel): the triangle itself, for the driver's conservative
//    rasterizer.
// Every fragment gets the whole triangle as flat data: voxel-space vertices in double for the
// clip, the vertex attributes for shading at the point closest to each voxel's centre, and the
// UV gradients per window pixel for the texture LOD.
layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 vg_position[];
in vec3 vg_normal[];
in vec4 vg_tangent[];
in vec2 vg_uv0[];
in vec2 vg_uv1[];
in vec4 vg_color[];
in vec3 vg_tex[];

flat out dvec3 c_voxel[3];  // vertices in voxel space (x, y, z), as stages/voxelize.h to_voxel_space
flat out vec3 c_position[3];
flat out vec3 c_normal[3];
flat out vec4 c_tangent[3];
flat out vec4 c_uv[3];     // (uv0, uv1)
flat out vec4 c_color[3];
flat out vec4 c_uv_grad[2];  // per texture coordinate set: (du/dx, dv/dx, du/dy, dv/dy) per pixel
flat out int c_axis;
flat out vec3 c_geometric_normal;

uniform vec3 u_volume_origin;
uniform float u_volume_size;
uniform int u_grid;
uniform int u_emit_quad;

const float kQuadMargin = 1.0f / 16.0f;

// Window coordinates (pixels = voxels) of a voxel-space point projected along `axis`.
vec2 window_of(dvec3 v, int axis) {
  if (axis == 2) return vec2(v.xy);
  if (axis == 0) return vec2(v.yz);
  return vec2(v.xz);
}

// d(uv)/d(window) of the affine map the triangle defines (zero for a window-degenerate one).
vec4 uv_gradient(vec2 w0, vec2 w1, vec2 w2, vec2 t0, vec2 t1, vec2 t2) {
  mat2 m = mat2(w1 - w0, w2 - w0);
  float det = determinant(m);
  if (abs(det) < 1e-20f) return vec4(0.0f);
  mat2 g = mat2(t1 - t0, t2 - t0) * inverse(m);  // columns: d uv / dx, d uv / dy
  return vec4(g[0], g[1]);
}

// Outputs are undefined after each EmitVertex (GLSL 4.50 §8.16), so every vertex writes all of them.
dvec3 t_voxel[3];
vec4 t_uv_grad[2];
int t_axis = 0;
vec3 t_geometric_normal = vec3(0.0f);

void emit(vec2 w) {
  for (int i = 0; i < 3; ++i) {
    c_voxel[i] = t_voxel[i];
    c_position[i] = vg_position[i];
    c_normal[i] = vg_normal[i];
    c_tangent[i] = vg_tangent[i];
    c_uv[i] = vec4(vg_uv0[i], vg_uv1[i]);
    c_color[i] = vg_color[i];
  }
  c_uv_grad[0] = t_uv_grad[0];
  c_uv_grad[1] = t_uv_grad[1];
  c_axis = t_axis;
  c_geometric_normal = t_geometric_normal;
  gl_Position = vec4(w / float(u_grid) * 2.0f - 1.0f, 0.0f, 1.0f);
  EmitVertex();
}

void main() {
  vec3 p = abs(cross(vg_position[1] - vg_position[0], vg_position[2] - vg_position[0]));
  t_axis = (p.z > p.x && p.z > p.y) ? 2 : (p.x > p.y ? 0 : 1);
  vec2 w[3];
  for (int i = 0; i < 3; ++i) {
    t_voxel[i] = (dvec3(vg_position[i]) - dvec3(u_volume_origin)) / double(u_volume_size) * double(u_grid);
    w[i] = window_of(t_voxel[i], t_axis);
  }
  t_uv_grad[0] = uv_gradient(w[0], w[1], w[2], vg_uv0[0], vg_uv0[1], vg_uv0[2]);
  t_uv_grad[1] = uv_gradient(w[0], w[1], w[2], vg_uv1[0], vg_uv1[1], vg_uv1[2]);
  t_geometric_normal = normalize(cross(vg_position[1] - vg_position[0], vg_position[2] - vg_position[0]));
  if (u_emit_quad == 1) {
    vec2 lo = min(w[0], min(w[1], w[2])) - (0.5f + kQuadMargin);
    vec2 hi = max(w[0], max(w[1], w[2])) + (0.5f + kQuadMargin);
    emit(lo);
    emit(vec2(hi.x, lo.y));
    emit(vec2(lo.x, hi.y));
    emit(hi);
  } else {
    for (int i = 0; i < 3; ++i) emit(w[i]);
  }
  EndPrimitive();
}
