// glTF alphaMode MASK in every CPU pass, on the hand-computable half-masked card
// (alpha_card_scene.h: texture alpha 0 on the left half, 1 on the right): the alpha itself, the
// shared test (BLEND as MASK at 1/2), then the shadow map's depth, the G-buffer's visible surface
// and both voxelizers' occupancy each see only the right half.
#include <gtest/gtest.h>

#include <cmath>

#include "alpha_card_scene.h"
#include "scene/alpha_mask.h"
#include "shared/vct_shared.h"
#include "stages/depth_raster.h"
#include "stages/gbuffer.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

namespace vct {
namespace {

using test::card_side;
using test::CardSide;
using test::half_masked_card;

// Barycentrics (b1, b2) of (x, y) on the card's first triangle (-1,-1), (1,-1), (1,1).
vec2 first_triangle_bary(float x, float y) {
  const float b2 = (y + 1.0f) * 0.5f;
  return vec2((x + 1.0f) * 0.5f - b2, b2);
}

TEST(AlphaMask, AlphaIsTheBilinearRampOfTheTwoTexels) {
  const Scene s = half_masked_card(false);
  // u = (x+1)/2; texel centres at u = 1/4 (alpha 0) and 3/4 (alpha 1), clamped beyond.
  const float xs[] = {-0.9f, -0.5f, -0.2f, 0.0f, 0.2f, 0.5f, 0.9f};
  const float expected[] = {0.0f, 0.0f, 0.3f, 0.5f, 0.7f, 1.0f, 1.0f};
  for (int i = 0; i < 7; ++i) {
    const vec2 b = first_triangle_bary(xs[i], -0.95f);
    EXPECT_NEAR(base_color_alpha(s, 0, b.x, b.y), expected[i], 1e-6f) << "x = " << xs[i];
  }
  EXPECT_TRUE(surface_masked(s, 0, first_triangle_bary(-0.01f, -0.95f).x,
                             first_triangle_bary(-0.01f, -0.95f).y));
  EXPECT_FALSE(surface_masked(s, 0, first_triangle_bary(0.01f, -0.95f).x,
                              first_triangle_bary(0.01f, -0.95f).y));
}

TEST(AlphaMask, OneSharedTestBlendIsMaskAtOneHalfOpaqueNeverDiscards) {
  EXPECT_TRUE(sh::alpha_discards(sh::ALPHA_MODE_MASK, 0.59f, 0.6f));
  EXPECT_FALSE(sh::alpha_discards(sh::ALPHA_MODE_MASK, 0.6f, 0.6f));  // glTF: alpha < cutoff
  EXPECT_FALSE(sh::alpha_discards(sh::ALPHA_MODE_BLEND, 0.59f, 0.6f));
  EXPECT_TRUE(sh::alpha_discards(sh::ALPHA_MODE_BLEND, 0.49f, 0.0f));
  EXPECT_FALSE(sh::alpha_discards(sh::ALPHA_MODE_OPAQUE, 0.0f, 0.5f));
  // The card: alpha 0.7 at x = 0.2 is cut away by MASK at 0.9, kept by BLEND (0.5), OPAQUE.
  const vec2 b = first_triangle_bary(0.2f, -0.95f);
  EXPECT_TRUE(surface_masked(half_masked_card(false, AlphaMode::Mask, 0.9f), 0, b.x, b.y));
  EXPECT_FALSE(surface_masked(half_masked_card(false, AlphaMode::Blend, 0.9f), 0, b.x, b.y));
  EXPECT_FALSE(surface_masked(half_masked_card(false, AlphaMode::Opaque, 0.9f), 0, b.x, b.y));
  // The factor's alpha multiplies the texture's.
  Scene s = half_masked_card(false);
  s.materials[0].base_color_factor.a = 0.5f;
  EXPECT_NEAR(base_color_alpha(s, 0, b.x, b.y), 0.35f, 1e-6f);
  EXPECT_TRUE(surface_masked(s, 0, b.x, b.y));
}

// Where the ray through window point (wx, wy) of `view_proj` meets the plane z = plane_z.
vec3 ray_on_plane(const mat4& view_proj, int width, int height, float wx, float wy, float plane_z) {
  const mat4 inv = glm::inverse(view_proj);
  const float nx = wx / float(width) * 2.0f - 1.0f, ny = wy / float(height) * 2.0f - 1.0f;
  const vec4 a = inv * vec4(nx, ny, -1.0f, 1.0f), b = inv * vec4(nx, ny, 1.0f, 1.0f);
  const vec3 pa = vec3(a) / a.w, pb = vec3(b) / b.w;
  return pa + (pb - pa) * ((plane_z - pa.z) / (pb.z - pa.z));
}

// The world z of the surface a depth texel holds (window depth unprojected).
float depth_to_world_z(const mat4& view_proj, int width, int height, float wx, float wy,
                       float depth) {
  const vec4 ndc(wx / float(width) * 2.0f - 1.0f, wy / float(height) * 2.0f - 1.0f,
                 depth * 2.0f - 1.0f, 1.0f);
  const vec4 w = glm::inverse(view_proj) * ndc;
  return w.z / w.w;
}

TEST(AlphaMask, ShadowMapDepthSeesOnlyTheRightHalf) {
  Scene s = half_masked_card(true);
  Light l;
  l.position = vec3(0.3f, 0.2f, 3.0f);
  l.direction = vec3(0.0f, 0.0f, -1.0f);
  l.outer_cone_angle = 0.6f;
  s.lights.push_back(l);
  VctSettings st;
  st.shadow_map_size = 64;
  const ShadowMap m = render_shadow_maps(s, st).at(0);
  int kept = 0, cut = 0;
  for (int row = 0; row < 64; ++row)
    for (int x = 0; x < 64; ++x) {
      const float wx = float(x) + 0.5f, wy = float(63 - row) + 0.5f;
      const vec3 q = ray_on_plane(m.view_proj, 64, 64, wx, wy, 0.0f);
      const vec3 behind = ray_on_plane(m.view_proj, 64, 64, wx, wy, -1.0f);
      if (std::abs(behind.x) > 2.9f || std::abs(behind.y) > 2.9f) continue;  // beyond the backdrop
      const CardSide side = card_side(q.x, q.y, 0.02f);
      const float z = depth_to_world_z(m.view_proj, 64, 64, wx, wy, m.depth.at(x, row, 0));
      if (side == CardSide::Kept) {
        EXPECT_NEAR(z, 0.0f, 1e-3f) << "texel " << x << "," << row << " should hold the card";
        ++kept;
      } else if (side == CardSide::CutAway) {
        EXPECT_NEAR(z, -1.0f, 1e-3f) << "texel " << x << "," << row << " should hold the backdrop";
        ++cut;
      }
    }
  EXPECT_GT(kept, 300);
  EXPECT_GT(cut, 600);
  // The masked path gives the same bits as the visibility buffer's masked depth.
  EXPECT_EQ(render_depth(s.positions, s.triangles, m.view_proj, 64, 64, &s),
            render_visibility(s.positions, s.triangles, m.view_proj, 64, 64, &s).depth);
}

TEST(AlphaMask, GbufferShowsTheBackdropThroughTheLeftHalf) {
  const Scene s = half_masked_card(true);
  VctSettings st;
  st.width = st.height = 48;
  const GBuffer g = render_gbuffer(s, st);
  const mat4 view_proj = s.camera.projection(1.0f) * s.camera.view();
  int kept = 0, cut = 0;
  for (int row = 0; row < 48; ++row)
    for (int x = 0; x < 48; ++x) {
      const vec3 q = ray_on_plane(view_proj, 48, 48, float(x) + 0.5f, float(47 - row) + 0.5f, 0.0f);
      const CardSide side = card_side(q.x, q.y, 0.02f);
      if (side == CardSide::Undecided) continue;
      EXPECT_EQ(g.coverage.at(x, row, 0), 1.0f);  // the backdrop fills the view
      const float z = g.position.at(x, row, 2);
      if (side == CardSide::Kept) {
        EXPECT_NEAR(z, 0.0f, 1e-4f) << x << "," << row;
        EXPECT_NEAR(g.albedo.at(x, row, 0), 0.2158605f, 1e-3f);  // sRGB 128 decoded
        ++kept;
      } else {
        EXPECT_NEAR(z, -1.0f, 1e-4f) << x << "," << row;
        ++cut;
      }
    }
  EXPECT_GT(kept, 150);
  EXPECT_GT(cut, 300);
}

// Per voxel column (x, y) along z: does any voxel hold a fragment?
bool column_occupied(const Voxelization& v, int x, int y) {
  for (int z = 0; z < v.n; ++z)
    if (*v.occupancy.voxel(x, y, z) > 0.0f) return true;
  return false;
}

TEST(AlphaMask, GpuRuleVoxelsHoldOnlyTheRightHalf) {
  const Scene s = half_masked_card(false);
  const int n = 16;
  const Voxelization v = voxelize_gpu_rule(s, n, 1);
  const float step = s.volume.size / float(n);
  int kept = 0, cut = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      // One sample at the pixel centre, i.e. the column's centre; tested there.
      const float cx = s.volume.origin.x + (float(x) + 0.5f) * step,
                  cy = s.volume.origin.y + (float(y) + 0.5f) * step;
      const CardSide side = card_side(cx, cy, 1e-3f);
      if (side == CardSide::Undecided) continue;
      EXPECT_EQ(column_occupied(v, x, y), side == CardSide::Kept) << "column " << x << "," << y;
      (side == CardSide::Kept ? kept : cut) += 1;
    }
  EXPECT_GT(kept, 40);
  EXPECT_GT(cut, 100);
}

TEST(AlphaMask, ConservativeVoxelsHoldOnlyTheRightHalf) {
  const Scene s = half_masked_card(false);
  const int n = 16;
  const Voxelization v = voxelize_conservative(s, n);
  const float step = s.volume.size / float(n);
  int kept = 0, cut = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float x0 = s.volume.origin.x + float(x) * step, x1 = x0 + step;
      const float y0 = s.volume.origin.y + float(y) * step, y1 = y0 + step;
      if (x0 < 0.0f && x1 > 0.0f)
        continue;  // straddles the alpha edge: tested at the closest point
      const bool on_card = x0 < 1.0f && x1 > -1.0f && y0 < 1.0f && y1 > -1.0f;
      const bool expected = on_card && x0 >= 0.0f;
      EXPECT_EQ(column_occupied(v, x, y), expected) << "column " << x << "," << y;
      (expected ? kept : cut) += 1;
    }
  EXPECT_GT(kept, 40);
  EXPECT_GT(cut, 100);
}

TEST(AlphaMask, OpaqueCardKeepsBothHalves) {
  // The control: the same card with alphaMode OPAQUE fills its whole square in every pass.
  const Scene s = half_masked_card(false, AlphaMode::Opaque);
  const Voxelization v = voxelize_gpu_rule(s, 16, 1);
  const float step = s.volume.size / 16.0f;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const float cx = s.volume.origin.x + (float(x) + 0.5f) * step,
                  cy = s.volume.origin.y + (float(y) + 0.5f) * step;
      if (std::abs(cx) < 0.999f && std::abs(cy) < 0.999f) {
        EXPECT_TRUE(column_occupied(v, x, y)) << x << "," << y;
      }
    }
}

}  // namespace
}  // namespace vct
