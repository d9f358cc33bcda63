// GL's cube-map addressing on the CPU (stages/cube_map.h) against values worked out by hand from
// GL 4.5 §8.13 Table 8.19 and equation 8.6, the faces the point light's cube renders, and the PCF
// across a face seam (stages/shadow_map.h, cube_shadow_visibility) on a hand-made cube.
#include <gtest/gtest.h>

#include "core/settings.h"
#include "stage_test_scene.h"
#include "stages/cube_map.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

TEST(CubeMap, FaceIsTheLargestMagnitudeCoordinate) {
  EXPECT_EQ(cube_face(vec3(1, 0, 0)), 0);
  EXPECT_EQ(cube_face(vec3(-1, 0.5f, 0.2f)), 1);
  EXPECT_EQ(cube_face(vec3(0.1f, 2, -0.5f)), 2);
  EXPECT_EQ(cube_face(vec3(0, -3, 1)), 3);
  EXPECT_EQ(cube_face(vec3(0.2f, 0.3f, 1)), 4);
  EXPECT_EQ(cube_face(vec3(0, 0, -1)), 5);
}

TEST(CubeMap, TiesOnEdgesAndCornersGoToXThenY) {
  // The spec lets the implementation choose on equal magnitudes; ours (and lights.glsl's) is
  // x over y over z, the sign of the winner picking the face.
  EXPECT_EQ(cube_face(vec3(1, 1, 0)), 0);
  EXPECT_EQ(cube_face(vec3(-1, 1, 0)), 1);
  EXPECT_EQ(cube_face(vec3(1, 0, -1)), 0);
  EXPECT_EQ(cube_face(vec3(0, 1, 1)), 2);
  EXPECT_EQ(cube_face(vec3(0, -1, -1)), 3);
  EXPECT_EQ(cube_face(vec3(1, 1, 1)), 0);
  EXPECT_EQ(cube_face(vec3(-1, -1, -1)), 1);
  // On the edge the face coordinate is exactly 1 (or 0): the edge of the chosen face.
  EXPECT_EQ(cube_face_st(0, vec3(1, 0, -1)), vec2(1.0f, 0.5f));
  EXPECT_EQ(cube_face_st(2, vec3(0, 1, 1)), vec2(0.5f, 1.0f));
}

TEST(CubeMap, FaceCoordinatesFollowTable8_19) {
  // s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2 with sc, tc, ma from the table's row.
  EXPECT_EQ(cube_face_st(0, vec3(1, 0.5f, -0.25f)), vec2(0.625f, 0.25f));  // sc = -rz, tc = -ry
  EXPECT_EQ(cube_face_st(1, vec3(-2, 1, 1)), vec2(0.75f, 0.25f));  // sc = rz, tc = -ry, |ma| = 2
  EXPECT_EQ(cube_face_st(2, vec3(0.5f, 1, -0.5f)), vec2(0.75f, 0.25f));   // sc = rx, tc = rz
  EXPECT_EQ(cube_face_st(3, vec3(0.5f, -1, -0.5f)), vec2(0.75f, 0.75f));  // sc = rx, tc = -rz
  EXPECT_EQ(cube_face_st(4, vec3(0.5f, 0.5f, 1)), vec2(0.75f, 0.25f));    // sc = rx, tc = -ry
  EXPECT_EQ(cube_face_st(5, vec3(0.5f, 0.5f, -1)), vec2(0.25f, 0.25f));   // sc = -rx, tc = -ry
}

TEST(CubeMap, DirectionIsTheInverseOfTheFaceCoordinates) {
  for (int f = 0; f < 6; ++f)
    for (float s : {0.1f, 0.5f, 0.8f})
      for (float t : {0.2f, 0.5f, 0.9f}) {
        const vec3 d = cube_face_direction(f, vec2(s, t));
        EXPECT_EQ(cube_face(d), f);
        const vec2 st = cube_face_st(f, d);
        EXPECT_NEAR(st.x, s, 1e-6f);
        EXPECT_NEAR(st.y, t, 1e-6f);
      }
}

TEST(CubeMap, FaceProjectionPutsEachDirectionAtItsFaceCoordinate) {
  // Window (x, y) of a face's view-projection must be its (s, t): the cube is rendered with these
  // matrices and sampled with cube_face_st.
  const vec3 c(0.3f, -0.2f, 0.5f);
  for (int f = 0; f < 6; ++f)
    for (float s : {0.1f, 0.5f, 0.8f})
      for (float t : {0.2f, 0.6f}) {
        const vec3 p = c + 2.0f * cube_face_direction(f, vec2(s, t));
        const vec4 clip = cube_face_view_proj(f, c, 0.1f, 10.0f) * vec4(p, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        EXPECT_NEAR(clip.x / clip.w * 0.5f + 0.5f, s, 1e-5f) << f;
        EXPECT_NEAR(clip.y / clip.w * 0.5f + 0.5f, t, 1e-5f) << f;
        const float z = clip.z / clip.w;
        EXPECT_GT(z, -1.0f);
        EXPECT_LT(z, 1.0f);
      }
}

TEST(CubeMap, RenderedFacesSeeAlongTheirAxes) {
  // A small square in direction (1, -0.5, -0.5) from the light: on +x at sc = 0.5, tc = 0.5, so
  // s = t = 0.75; no other face sees it, and the mirrored texel on +x is empty.
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.5f));
  test::add_quad(s, {2, -1.2f, -1.2f}, {2, -0.8f, -1.2f}, {2, -0.8f, -0.8f}, {2, -1.2f, -0.8f},
                 {-1, 0, 0}, m);
  test::add_quad(s, {-3, -3, -3}, {-2.9f, -3, -3}, {-2.9f, -2.9f, -3}, {-3, -2.9f, -3}, {0, 0, 1},
                 m);  // bounds only
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.0f);
  s.lights.push_back(l);
  s.volume = fit_volume(s.bounds);
  VctSettings st;
  st.shadow_map_size = 16;
  const std::vector<ShadowMap> maps = render_shadow_maps(s, st);
  ASSERT_EQ(maps.size(), 1u);
  ASSERT_TRUE(maps[0].is_cube());
  EXPECT_TRUE(maps[0].depth.empty());
  const int n = 16;
  // GL texel (12, 12) (s = t = 0.78) is image row n - 1 - 12.
  EXPECT_LT(maps[0].cube[0].at(12, n - 1 - 12, 0), 1.0f);
  EXPECT_EQ(maps[0].cube[0].at(3, n - 1 - 3, 0), 1.0f);
  for (int f = 1; f < 6; ++f) {
    float lo = 1.0f;
    for (float v : maps[0].cube[size_t(f)].data) lo = std::min(lo, v);
    if (f == 1 || f == 3 || f == 5) continue;  // the bounds square lies toward -x, -y, -z
    EXPECT_EQ(lo, 1.0f) << "face " << f;
  }
  EXPECT_EQ(shadow_map_layers(s), 6);
}

// A cube of 4x4 faces cleared to 1 (nothing), one texel made an occluder at depth 0.
ShadowMap empty_cube(const vec3& light, int size) {
  ShadowMap m;
  for (int f = 0; f < 6; ++f) {
    m.cube[size_t(f)] = Image(size, size, 1, 1.0f);
    m.cube_view_proj[size_t(f)] = cube_face_view_proj(f, light, 0.1f, 10.0f);
  }
  return m;
}

TEST(CubeMap, PcfTapPastTheEdgeReadsTheNeighbouringFace) {
  // Worked by hand for 4x4 faces, k = 3: p - light = (1, 0, -0.9) x 2 selects +x (face 0) at
  // sc = 0.9, tc = 0: s = 0.95, t = 0.5, texel coordinate (3.8, 2.0). Taps x = floor(3.8 + i - 1)
  // = 2, 3, 4 and y = 1, 2, 3. Tap (4, 1) is past the edge: its virtual centre (4.5, 1.5)/4 gives
  // sc' = 1.25, tc' = -0.25, direction (1, 0, 0) + 1.25 (0, 0, -1) - 0.25 (0, -1, 0) = (1, 0.25,
  // -1.25): face -z (5), sc = -rx = -1, tc = -ry = -0.25, |ma| = 1.25, so s = 0.1, t = 0.4: texel
  // (0, 1) of face 5.
  const vec3 light(0.0f);
  const vec3 p = light + 2.0f * vec3(1.0f, 0.0f, -0.9f);
  VctSettings st;
  st.pcf_kernel = 3;
  const int n = 4;
  ShadowMap m = empty_cube(light, n);
  EXPECT_EQ(cube_shadow_visibility(m, light, p, st), 1.0f);
  m.cube[5].at(0, n - 1 - 1, 0) = 0.0f;  // face 5, GL texel (0, 1)
  EXPECT_FLOAT_EQ(cube_shadow_visibility(m, light, p, st), 8.0f / 9.0f);
  m.cube[5].at(0, n - 1 - 1, 0) = 1.0f;
  m.cube[5].at(1, n - 1 - 1, 0) = 0.0f;  // its neighbour: no tap reads it
  EXPECT_EQ(cube_shadow_visibility(m, light, p, st), 1.0f);
  m.cube[5].at(1, n - 1 - 1, 0) = 1.0f;
  m.cube[0].at(3, n - 1 - 2, 0) = 0.0f;  // the home texel (3, 2) of face 0
  EXPECT_FLOAT_EQ(cube_shadow_visibility(m, light, p, st), 8.0f / 9.0f);
  m.cube[0].at(3, n - 1 - 2, 0) = 1.0f;
  // k = 1 reads the home texel only.
  st.pcf_kernel = 1;
  m.cube[5].at(0, n - 1 - 1, 0) = 0.0f;
  EXPECT_EQ(cube_shadow_visibility(m, light, p, st), 1.0f);
}

}  // namespace
}  // namespace vct
