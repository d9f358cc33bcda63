// glTF alphaMode MASK in the path tracer: Embree's filter functions reject hits on cut-away points
// (ref/pt/embree_scene.cpp). The hand-computed half-masked card (tests/ref/alpha_card_scene.h)
// stops only rays through its right half, for closest-hit and occlusion queries, from either
// side; and a striped mask with a transmitted share of exactly 1/4 in front of a large emitter
// lights a Lambertian receiver with a quarter of the unmasked irradiance (statistical test).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../ref/alpha_card_scene.h"
#include "core/parallel.h"
#include "pt/accumulator.h"
#include "pt/embree_scene.h"
#include "pt/path_tracer.h"
#include "scene/surface.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

using vct::test::card_side;
using vct::test::CardSide;

TEST(PtAlphaMask, RaysPassOnlyThroughTheCutAwayHalf) {
  const Scene s = vct::test::half_masked_card(true);
  const EmbreeScene rt(s);
  int kept = 0, cut = 0;
  for (int j = 0; j < 21; ++j)
    for (int i = 0; i < 21; ++i) {
      const float x = -1.25f + 2.5f * float(i) / 20.0f + 0.013f,
                  y = -1.25f + 2.5f * float(j) / 20.0f + 0.007f;
      const CardSide side = card_side(x, y, 1e-3f);
      if (side == CardSide::Undecided) continue;
      for (float from : {2.0f, -0.5f}) {  // in front of the card, and between it and the backdrop
        const vec3 org(x, y, from), dir(0.0f, 0.0f, from > 0.0f ? -1.0f : 1.0f);
        const Hit h = rt.intersect(org, dir, 0.0f, 10.0f);
        const bool through_card_plane = from > 0.0f;  // from behind, only the card lies ahead
        if (side == CardSide::Kept) {
          ASSERT_TRUE(h.hit);
          EXPECT_LT(h.triangle, 2u) << "the card's own triangles";
          EXPECT_NEAR(h.t, std::abs(from), 1e-4f);
          const vec3 p = interpolate_surface(s, h.triangle, h.b1, h.b2).position;
          EXPECT_NEAR(p.x, x, 1e-4f);
          EXPECT_NEAR(p.y, y, 1e-4f);
        } else if (through_card_plane) {
          ASSERT_TRUE(h.hit);  // the backdrop behind the cut-away half
          EXPECT_GE(h.triangle, 2u);
          EXPECT_NEAR(h.t, 3.0f, 1e-4f);
        } else {
          EXPECT_FALSE(h.hit) << x << "," << y;
        }
        // Occlusion of the segment up to just before the backdrop: the card alone decides.
        const float to_card = std::abs(from);
        EXPECT_EQ(rt.occluded(org, dir, 0.0f, to_card + 0.5f), side == CardSide::Kept)
            << x << "," << y;
      }
      (side == CardSide::Kept ? kept : cut) += 1;
    }
  EXPECT_GT(kept, 60);
  EXPECT_GT(cut, 200);
}

// Howell's catalogue B-3: view factor from a differential area to a parallel a x b rectangle with
// one corner on its normal at distance c.
double corner_view_factor(double a, double b, double c) {
  const double x = a / c, y = b / c, sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
  return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * M_PI);
}

TEST(PtAlphaMask, StripedCardTransmitsItsShareOfAnEmittersLight) {
  // Emitter: z = -1, half-size 20, Le = 1, facing +z, black. Card: z = 0, half-size 10, black,
  // double-sided, MASK at 1/2 with a 4 x 1 texture of alphas (0, 1, 1, 1), REPEAT, period 4 cm
  // along x: bilinear alpha is below 1/2 within half a texel of texel 0's centre, i.e. on exactly
  // 1/4 of the card. Receiver: z = 0.5, 0.4 m square facing -z, Lambertian rho = 0.5, filling
  // the camera's view. Every receiver-to-emitter ray crosses the card (at most 20/3 m off axis),
  // so L = rho * Le * F * 1/4 with F the emitter's view factor; the stripes are 25x finer than
  // the receiver's distance to them, so their average over the cosine lobe is their share.
  Scene s;
  const uint32_t emitter = test::add_material(s, test::lambertian(vec3(0.0f), vec3(1.0f), false));
  test::add_quad(s, vec3(-20, -20, -1), vec3(40, 0, 0), vec3(0, 40, 0), emitter);  // front +z
  Material card = test::lambertian(vec3(0.0f), vec3(0.0f), true);
  card.alpha_mode = AlphaMode::Mask;
  card.alpha_cutoff = 0.5f;
  card.base_color_texture.texture = 0;
  const uint32_t card_mat = test::add_material(s, card);
  const size_t first_card_vertex = s.positions.size();
  test::add_quad(s, vec3(-10, -10, 0), vec3(20, 0, 0), vec3(0, 20, 0), card_mat);
  constexpr float kPeriod = 0.04f;
  for (size_t v = first_card_vertex; v < s.positions.size(); ++v)
    s.uv0[v] = vec2(s.positions[v].x / kPeriod, 0.5f);
  Texture stripes;
  stripes.width = 4;
  stripes.height = 1;
  stripes.rgba8 = {0, 0, 0, 0, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255};
  s.textures.push_back(stripes);
  const uint32_t receiver = test::add_material(s, test::lambertian(vec3(0.5f), vec3(0.0f), false));
  test::add_quad(s, vec3(-0.2f, -0.2f, 0.5f), vec3(0, 0.4f, 0), vec3(0.4f, 0, 0),
                 receiver);  // front -z
  s.camera = test::look_at(vec3(0.0f, 0.0f, 0.3f), vec3(0.0f, 0.0f, 1.0f), vec3(0, 1, 0), 0.5f);
  test::finish(s);

  PtSettings ps;
  ps.width = ps.height = 16;
  ps.max_depth = 4;
  ps.seed = 3;
  set_thread_count(0);
  const PathTracer pt(s, ps);
  Accumulator acc(ps.width, ps.height);
  pt.render(acc, 128);
  const Image mean = acc.mean(kFull), var = acc.variance(kFull);
  double sum = 0.0, variance = 0.0;
  const double n = double(ps.width) * ps.height;
  for (int y = 0; y < ps.height; ++y)
    for (int x = 0; x < ps.width; ++x) {
      sum += double(mean.at(x, y, 1));
      variance += double(var.at(x, y, 1));
    }
  const double got = sum / n, sigma = std::sqrt(variance) / n;
  const double view_factor = 4.0 * corner_view_factor(20.0, 20.0, 1.5);
  const double expected = 0.5 * 1.0 * view_factor * 0.25;
  std::printf(
      "[striped mask] receiver radiance %.5f, expected %.5f (F = %.5f), %.2f sigma, sigma %.5f\n",
      got, expected, view_factor, (got - expected) / sigma, sigma);
  EXPECT_LT(sigma, 0.02 * expected);  // power: an unmasked (4x) or a half-open card (2x) fails
  EXPECT_NEAR(got, expected, 4.0 * sigma);
}

}  // namespace
}  // namespace vct::pt
