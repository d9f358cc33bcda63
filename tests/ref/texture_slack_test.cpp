// The G-buffer's texture slack (freedoms/texture_slack.h) against hand-computed values: window
// barycentrics of a plane facing the camera, and the slack of a minified bilinear checkerboard.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>

#include "freedoms/gbuffer_freedoms.h"
#include "freedoms/texture_slack.h"
#include "io/srgb.h"
#include "scene/surface.h"
#include "stage_test_scene.h"
#include "stages/gbuffer.h"

namespace vct {
namespace {

// Camera at the origin looking down -z, yfov 1 rad, square view: at z = -2 the view spans
// +-2 tan(0.5) = +-1.0926 in x and y.
void look_down_z(Scene& s) {
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 10.0f;
}

TEST(TextureSlack, WindowBarycentricsOfAPlaneFacingTheCamera) {
  Scene s;
  test::add_triangle(s, {-1, -1, -2}, {1, -1, -2}, {-1, 1, -2}, test::add_material(s, vec3(1.0f)));
  look_down_z(s);
  const WindowBarycentrics wb(s.camera.projection(1.0f) * s.camera.view(), 16, 16);
  glm::dvec2 b;
  // Window (8, 8) is the view centre: the ray meets (0, 0, -2) = p0 + 0.5 e1 + 0.5 e2.
  ASSERT_TRUE(wb.at(s, 0, 8.0, 8.0, b));
  EXPECT_NEAR(b.x, 0.5, 1e-6);
  EXPECT_NEAR(b.y, 0.5, 1e-6);
  // Window (12, 4): NDC (0.5, -0.5), world (0.5463, -0.5463, -2): b = ((x+1)/2, (y+1)/2).
  const double h = 2.0 * std::tan(0.5);  // half extent of the view at z = -2
  ASSERT_TRUE(wb.at(s, 0, 12.0, 4.0, b));
  EXPECT_NEAR(b.x, (0.5 * h + 1.0) / 2.0, 1e-6);  // 0.77315
  EXPECT_NEAR(b.y, (-0.5 * h + 1.0) / 2.0, 1e-6);  // 0.22685
  // The view's corner (1.0926, 1.0926, -2) lies outside the triangle: extrapolated, b1 + b2 > 1.
  ASSERT_TRUE(wb.at(s, 0, 16.0, 16.0, b));
  EXPECT_NEAR(b.x, (h + 1.0) / 2.0, 1e-6);  // 1.04630
  EXPECT_NEAR(b.y, (h + 1.0) / 2.0, 1e-6);
}

// A quad at z = -2 wider than the view, u = (x + 2) / 4, with a 2x1 checkerboard (0, 255)
// repeated `repeats` times across it: bilinear filtering makes a triangle wave of slope 1 per
// texel between texel centres. Pixels are 2 tan(0.5) * 2 / 16 = 0.136576 world units wide, so
// rho = 0.136576 / 4 * 2 * repeats texels per pixel, and a shift of s = 2^-8 pixel changes the
// value by s * rho except within s * rho texels of a texel centre (the wave's kinks).
struct CheckerView {
  Scene scene;
  double rho = 0.0;
};

CheckerView checker_quad(int repeats, bool albedo) {
  CheckerView v;
  Scene& s = v.scene;
  const uint32_t m = test::add_material(s, vec3(1.0f));
  test::add_quad(s, {-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}, {0, 0, 1}, m);
  for (size_t i = 0; i < s.positions.size(); ++i) s.uv0[i] = vec2((s.positions[i].x + 2.0f) / 4.0f, 0.5f);
  Texture t;
  t.width = 2;
  t.height = 1;
  t.rgba8 = {0, 0, 0, 255, 255, 255, 255, 255};
  s.textures.push_back(t);
  TextureRef& r = albedo ? s.materials[m].base_color_texture : s.materials[m].metallic_roughness_texture;
  r.texture = 0;
  r.transform.scale = vec2(float(repeats), 1.0f);
  s.materials[m].metallic_factor = 1.0f;
  s.materials[m].roughness_factor = 1.0f;
  look_down_z(s);
  s.volume = fit_volume(s.bounds);
  v.rho = 2.0 * std::tan(0.5) * 2.0 / 16.0 / 4.0 * 2.0 * double(repeats);
  return v;
}

void check_checker(bool albedo) {
  const CheckerView v = checker_quad(64, albedo);  // rho = 4.37042 texels per pixel
  ASSERT_NEAR(v.rho, 4.37042, 1e-5);
  VctSettings st;
  st.width = st.height = 16;
  const GBuffer g = render_gbuffer_with_freedoms(v.scene, st);
  const int ch = albedo ? kSlackAlbedo : kSlackMaterial;
  const double expected = v.rho / 256.0;  // 0.0170720
  int away_from_kinks = 0;
  for (int row = 0; row < 16; ++row)
    for (int x = 0; x < 16; ++x) {
      ASSERT_EQ(g.coverage.at(x, row, 0), 1.0f);
      const float slack = g.texture_slack.at(x, row, ch);
      EXPECT_EQ(g.texture_slack.at(x, row, kSlackNormal), 0.0f);  // no normal map
      EXPECT_EQ(g.texture_slack.at(x, row, kSlackEmission), 0.0f);
      // Texel coordinate of the centre (minus the texel-centre offset): distance to the nearest kink.
      const double u = ((double(x) + 0.5) / 8.0 - 1.0) * std::tan(0.5) * 2.0;
      const double t = (u + 2.0) / 4.0 * 2.0 * 64.0 - 0.5;
      // sRGB base colour: GL may also decode after filtering (GL 4.5 §8.24): the encoded blend w
      // of 0 and 255 decodes to srgb_to_linear(w) instead of w. With w0 the G-buffer's own value
      // (the raster's centre: snapping moves it from t by up to 2^-8 pixel), the shifted samples
      // lie in [w0 - s rho, w0 + s rho] (the wave's slope is 1), so the slack is the larger of
      // s rho and |srgb_to_linear(w) - w0| at the ends and the centre of that interval.
      double want = expected;
      if (albedo) {
        const double w0 = g.albedo.at(x, row, 0);
        for (double w : {w0 - expected, w0, w0 + expected}) {
          const double wc = std::clamp(w, 0.0, 1.0);
          want = std::max(want, std::abs(double(srgb_to_linear(float(wc))) - w0));
        }
      }
      EXPECT_LE(slack, want * 1.001 + 1e-6) << x << "," << row;
      if (std::abs(t - std::round(t)) < 2.0 * expected) continue;
      ++away_from_kinks;
      EXPECT_NEAR(slack, want, want * 0.01) << x << "," << row;
    }
  EXPECT_GT(away_from_kinks, 16 * 12);
}

TEST(TextureSlack, MinifiedCheckerboardMovesByTheShiftTimesTexelsPerPixel) {
  check_checker(false);  // roughness = G of the linear metallic-roughness texture
  check_checker(true);   // sRGB base colour: the same wave, plus the decode-after-filter values
}

// A smooth-shaded untextured quad (the CheckerView quad, u = (x + 2) / 4) whose vertex normals
// lean +-k along x: the interpolated normal is ((2u - 1) k, 0, 1) normalised, an attribute GL reads
// at the snapped sample point like a texture coordinate. Its slack is the largest component change
// over a shift of 2^-8 pixel (du = 0.136576 / 4 / 256 per pixel of the 16^2 view).
TEST(TextureSlack, SmoothUntexturedNormalsMoveWithTheSamplePoint) {
  CheckerView v = checker_quad(1, true);
  v.scene.materials[0].base_color_texture.texture = -1;
  const float k = 0.8f;
  for (size_t i = 0; i < v.scene.positions.size(); ++i)
    v.scene.normals[i] = glm::normalize(vec3(v.scene.positions[i].x < 0.0f ? -k : k, 0.0f, 1.0f));
  VctSettings st;
  st.width = st.height = 16;
  const GBuffer g = render_gbuffer_with_freedoms(v.scene, st);
  const auto normal_at = [&](double u) {
    const double t = (2.0 * u - 1.0) * double(k);
    return glm::dvec3(t, 0.0, 1.0) / std::sqrt(1.0 + t * t);
  };
  const double du = 2.0 * std::tan(0.5) * 2.0 / 16.0 / 4.0 * double(kVertexSnapStep);
  for (int x = 0; x < 16; ++x) {
    const double u = (double(g.position.at(x, 8, 0)) + 2.0) / 4.0;
    double want = 0.0;
    for (double d : {-du, du}) {
      const glm::dvec3 c = glm::abs(normal_at(u + d) - normal_at(u));
      want = std::max(want, std::max(c.x, c.z));
    }
    EXPECT_NEAR(g.texture_slack.at(x, 8, kSlackNormal), want, 0.02 * want + 1e-7) << x;
    EXPECT_GT(want, 1e-4);
  }
}

TEST(TextureSlack, FlatUntexturedMaterialsHaveNone) {
  CheckerView v = checker_quad(64, true);
  v.scene.materials[0].base_color_texture.texture = -1;
  VctSettings st;
  st.width = st.height = 8;
  const GBuffer g = render_gbuffer_with_freedoms(v.scene, st);
  for (float s : g.texture_slack.data) EXPECT_EQ(s, 0.0f);
}

}  // namespace
}  // namespace vct
