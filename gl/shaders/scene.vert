// World-space vertex attributes in, camera (or light) clip space out. `invariant` keeps the depth
// of the depth pre-pass and of the G-buffer pass bit-identical (GL_LEQUAL relies on it).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;  // COLOR_0, white without it

uniform mat4 u_view_proj;

out vec3 v_position;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;
invariant gl_Position;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_tangent = a_tangent;
  v_uv0 = a_uv0;
  v_uv1 = a_uv1;
  v_color = a_color;
  gl_Position = u_view_proj * vec4(a_position, 1.0f);
}
