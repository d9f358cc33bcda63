// The seed's dominant-axis projection, verbatim in its decisions: the axis of the largest
// |component| of the triangle's normal, with ties going to
// x-or-y as the seed's strict comparisons do; z -> (x, y), x -> (y, z), y -> (x, z).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vg_position[];
in vec3 vg_normal[];
in vec4 vg_tangent[];
in vec2 vg_uv0[];
in vec2 vg_uv1[];
in vec4 vg_color[];
in vec3 vg_tex[];

out vec3 v_position;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;
out vec3 v_tex;
flat out int v_axis;
flat out vec3 v_geometric_normal;
// Depth along the projection axis, as the CPU computes it: the vertices' voxel-space coordinate
// in double, interpolated by the barycentrics (a plane lying on a voxel boundary then falls on
// the same side in both backends; float interpolation of a rounded coordinate did not).
flat out dvec3 v_axis_depth;
noperspective out vec3 v_bary;
uniform vec3 u_volume_origin;
uniform float u_volume_size;
uniform int u_grid;

void main() {
  vec3 pos[3] = vec3[3](gl_in[0].gl_Position.xyz, gl_in[1].gl_Position.xyz, gl_in[2].gl_Position.xyz);
  // On world positions, as ref/stages/voxelize.cpp's dominant_axis (the [-1,1] mapping is a
  // uniform scale, so only rounding at exact ties could differ from the seed's clip-space test).
  vec3 p = abs(cross(vg_position[1] - vg_position[0], vg_position[2] - vg_position[0]));
#ifdef VCT_FAULT_WRONG_AXIS
  int axis = (p.z > p.x && p.z > p.y) ? 2 : (p.y > p.x ? 0 : 1);  // fault: x/y test swapped
#else
  int axis = (p.z > p.x && p.z > p.y) ? 2 : (p.x > p.y ? 0 : 1);
#endif
  vec3 gn = normalize(cross(vg_position[1] - vg_position[0], vg_position[2] - vg_position[0]));
  dvec3 depth;
  for (int i = 0; i < 3; ++i) {
    dvec3 vox = (dvec3(vg_position[i]) - dvec3(u_volume_origin)) / double(u_volume_size) * double(u_grid);
    depth[i] = vox[axis];
  }
  for (int i = 0; i < 3; ++i) {
    if (axis == 2) gl_Position = vec4(pos[i].x, pos[i].y, 0.0f, 1.0f);
    else if (axis == 0) gl_Position = vec4(pos[i].y, pos[i].z, 0.0f, 1.0f);
    else gl_Position = vec4(pos[i].x, pos[i].z, 0.0f, 1.0f);
    v_position = vg_position[i];
    v_normal = vg_normal[i];
    v_tangent = vg_tangent[i];
    v_uv0 = vg_uv0[i];
    v_uv1 = vg_uv1[i];
    v_color = vg_color[i];
    v_tex = vg_tex[i];
    v_axis = axis;
    v_geometric_normal = gn;
    v_axis_depth = depth;
    v_bary = vec3(i == 0 ? 1.0f : 0.0f, i == 1 ? 1.0f : 0.0f, i == 2 ? 1.0f : 0.0f);
    EmitVertex();
  }
  EndPrimitive();
}
