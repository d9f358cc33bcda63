#include "stages/cube_map.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vct {

namespace {

// GL 4.5 Table 8.19, one row per face: major axis direction, sc, tc.
//   +rx: sc = -rz, tc = -ry      -rx: sc = +rz, tc = -ry
//   +ry: sc = +rx, tc = +rz      -ry: sc = +rx, tc = -rz
//   +rz: sc = +rx, tc = -ry      -rz: sc = -rx, tc = -ry
const std::array<CubeFaceAxes, 6> kFaces = {{
    {vec3(1, 0, 0), vec3(0, 0, -1), vec3(0, -1, 0)},
    {vec3(-1, 0, 0), vec3(0, 0, 1), vec3(0, -1, 0)},
    {vec3(0, 1, 0), vec3(1, 0, 0), vec3(0, 0, 1)},
    {vec3(0, -1, 0), vec3(1, 0, 0), vec3(0, 0, -1)},
    {vec3(0, 0, 1), vec3(1, 0, 0), vec3(0, -1, 0)},
    {vec3(0, 0, -1), vec3(-1, 0, 0), vec3(0, -1, 0)},
}};

}  // namespace

const CubeFaceAxes& cube_face_axes(int face) {
  return kFaces[size_t(face)];
}

int cube_face(const vec3& r) {
  const float ax = std::abs(r.x), ay = std::abs(r.y), az = std::abs(r.z);
  if (ax >= ay && ax >= az) return r.x >= 0.0f ? 0 : 1;
  if (ay >= az) return r.y >= 0.0f ? 2 : 3;
  return r.z >= 0.0f ? 4 : 5;
}

vec2 cube_face_st(int face, const vec3& r) {
  const CubeFaceAxes& f = kFaces[size_t(face)];
  const float ma = std::abs(glm::dot(r, f.major_axis));
  const float sc = glm::dot(r, f.sc_axis), tc = glm::dot(r, f.tc_axis);
  return vec2(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f));
}

vec3 cube_face_direction(int face, const vec2& st) {
  const CubeFaceAxes& f = kFaces[size_t(face)];
  return f.major_axis + (2.0f * st.x - 1.0f) * f.sc_axis + (2.0f * st.y - 1.0f) * f.tc_axis;
}

CubeTexel cube_texel(int home, int x, int y, int size) {
  if (x >= 0 && y >= 0 && x < size && y < size) return {home, x, y};
  const vec3 d = cube_face_direction(home, (vec2(float(x), float(y)) + 0.5f) / float(size));
  const int face = cube_face(d);
  const vec2 st = cube_face_st(face, d);
  return {face, std::clamp(int(std::floor(st.x * float(size))), 0, size - 1),
          std::clamp(int(std::floor(st.y * float(size))), 0, size - 1)};
}

mat4 cube_face_view_proj(int face, const vec3& center, float near_plane, float far_plane) {
  const CubeFaceAxes& f = kFaces[size_t(face)];
  // View space: x = sc, y = tc, looking down -z = the major axis (each row triple is a rotation:
  // sc x tc = -major for all six faces). Column-major: element [col][row].
  mat4 view(1.0f);
  for (int c = 0; c < 3; ++c) {
    view[c][0] = f.sc_axis[c];
    view[c][1] = f.tc_axis[c];
    view[c][2] = -f.major_axis[c];
  }
  view = view * glm::translate(mat4(1.0f), -center);
  return glm::perspective(glm::radians(90.0f), 1.0f, near_plane, far_plane) * view;
}

}  // namespace vct
