// Voxelization: world position to voxel texture space [0,1]^3, then to [-1,1]^3 for the geometry
// shader's dominant-axis projection.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;  // COLOR_0, white without it

uniform vec3 u_volume_origin;
uniform float u_volume_size;

out vec3 vg_position;
out vec3 vg_normal;
out vec4 vg_tangent;
out vec2 vg_uv0;
out vec2 vg_uv1;
out vec4 vg_color;
out vec3 vg_tex;

void main() {
  vg_position = a_position;
  vg_normal = a_normal;
  vg_tangent = a_tangent;
  vg_uv0 = a_uv0;
  vg_uv1 = a_uv1;
  vg_color = a_color;
  vg_tex = (a_position - u_volume_origin) / u_volume_size;
  gl_Position = vec4(vg_tex * 2.0f - 1.0f, 1.0f);
}
