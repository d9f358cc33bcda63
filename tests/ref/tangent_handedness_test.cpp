// Tangent handedness ties (freedoms/tangent_handedness.h; issue 34's false-alarm hunt,
// scenes/regressions/seed-348-small): on a triangle whose vertices' tangents disagree on the
// bitangent's sign, GL may shade with either bitangent (it interpolates w and takes its sign, the
// reference takes vertex 0's), so the voxel shading slack and the camera's normal slack carry the
// light and the normal of the other sign; a tangent-direction fault (t mirrored) stays beyond.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

#include "freedoms/fragment_slack.h"
#include "freedoms/gbuffer_freedoms.h"
#include "freedoms/tangent_handedness.h"
#include "freedoms/texture_slack.h"
#include "stage_test_scene.h"
#include "stages/gbuffer.h"
#include "stages/inject.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

float largest(const vec3& v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); }

// A 1.6 m triangle on y = 0 facing up, tangent +x everywhere, w = -1 at vertex 0 and +1 at the
// others; a 1x1 normal map tilting the normal 0.6 along t and 0.25 along the bitangent
// cross(n, t) w = -z w; a sun from (0.8, 1, 0.2), nothing casting shadows. The bitangent's sign
// moves n.l by 2 x 0.247 x 0.154 = 0.076, a mirrored tangent by 2 x 0.6 x 0.617 = 0.74.
Scene mixed_handedness_triangle() {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.6f));
  test::add_triangle(s, {-0.8f, 0, -0.8f}, {-0.8f, 0, 0.8f}, {0.8f, 0, 0.0f}, m);
  s.tangents = {vec4(1, 0, 0, -1), vec4(1, 0, 0, 1), vec4(1, 0, 0, 1)};
  Texture t;
  t.width = t.height = 1;
  t.rgba8 = {204, 159, 224, 255};  // (0.6, 0.247, 0.757) in [-1, 1]
  s.textures.push_back(t);
  s.materials[m].normal_texture.texture = 0;
  s.materials[m].double_sided = false;
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = -glm::normalize(vec3(0.8f, 1.0f, 0.2f));
  sun.intensity = 3.0f;
  s.lights.push_back(sun);
  s.volume = fit_volume(s.bounds);
  return s;
}

TEST(TangentHandedness, MixedSignsAreFoundOnlyWhereTheVerticesDisagree) {
  Scene s = mixed_handedness_triangle();
  EXPECT_TRUE(tangent_handedness_mixed(s, 0));
  EXPECT_TRUE(handedness_may_flip(s, 0));
  s.tangents[0].w = 1.0f;
  EXPECT_FALSE(tangent_handedness_mixed(s, 0));
  s.tangents[0].w = -1.0f;
  s.materials[0].normal_texture.texture = -1;  // no normal map: the bitangent is never read
  EXPECT_FALSE(handedness_may_flip(s, 0));
}

struct Voxels {
  Voxelization vox;
  std::vector<vec3> values;
  std::vector<float> slack;
  std::vector<ShadowMap> maps;
  VctSettings settings;
};

Voxels voxels(const Scene& s) {
  Voxels v;
  v.settings.grid = 16;
  v.maps = render_shadow_maps(s, v.settings);
  v.vox = voxelize_gpu_rule(s, v.settings.grid, 4);
  v.values = fragment_radiance(s, v.vox, v.maps, v.settings);
  v.slack = fragment_shading_slack(s, v.vox, v.maps, v.settings);
  return v;
}

// The light a GL computes at fragment f with the tangent frame `p` (its own sign of w).
vec3 light_with(const Scene& s, const Voxels& v, const VoxelFragment& f, const SurfacePoint& p) {
  return light_leaving(s, f, evaluate_material(s, p, {}), v.maps, v.settings, nullptr);
}

TEST(TangentHandedness, VoxelSlackCarriesTheOtherBitangentNotAMirroredTangent) {
  const Scene s = mixed_handedness_triangle();
  const Voxels v = voxels(s);
  ASSERT_GT(v.vox.fragments.size(), 50u);
  int flipped = 0;
  for (size_t i = 0; i < v.vox.fragments.size(); ++i) {
    const VoxelFragment& f = v.vox.fragments[i];
    const SurfacePoint p = interpolate_surface(s, f.triangle, f.b1, f.b2);
    ASSERT_EQ(p.tangent.w, -1.0f);  // the reference: vertex 0's sign
    // A GL interpolating w: its sign flips where vertices 1 and 2 outweigh vertex 0 (b0 < 1/2).
    const vec3 other = light_with(s, v, f, with_other_handedness(p));
    const float d = largest(other - v.values[i]);
    EXPECT_GT(d, 0.015f) << i;  // 0.0196 at every fragment (n.l moves by 0.076): the sign matters
    EXPECT_LE(d, v.slack[i] * (1.0f + 1e-5f)) << i;
    flipped += 1.0f - f.b1 - f.b2 < 0.5f;
    // A GL whose tangent direction is mirrored (t -> -t, w kept: the seed-66 class of bug) turns
    // the 0.5 tilt along t: beyond the slack.
    SurfacePoint mirrored = p;
    mirrored.tangent = vec4(-vec3(p.tangent), p.tangent.w);
    EXPECT_GT(largest(light_with(s, v, f, mirrored) - v.values[i]), v.slack[i]) << i;
  }
  EXPECT_GT(flipped, 10);
}

TEST(TangentHandedness, CameraNormalSlackCarriesTheOtherBitangent) {
  Scene s = mixed_handedness_triangle();
  test::top_camera(s);
  VctSettings st;
  st.width = st.height = 16;
  VisibilityBuffer vb;
  GBuffer g = render_gbuffer(s, st, &vb);
  add_gbuffer_freedoms(s, st, vb, g);
  int covered = 0;
  for (int row = 0; row < 16; ++row)
    for (int x = 0; x < 16; ++x) {
      const size_t i = vb.index(x, row);
      if (vb.triangle[i] < 0) continue;
      ++covered;
      const SurfacePoint p = interpolate_surface(s, uint32_t(vb.triangle[i]), vb.bary[i].y, vb.bary[i].z);
      const vec3 other = evaluate_material(s, with_other_handedness(p), {}).shading_normal;
      const vec3 own = evaluate_material(s, p, {}).shading_normal;
      // The bitangent tilt turns sign: 2 x 0.247 / |n| on z.
      EXPECT_GT(largest(other - own), 0.45f) << x << "," << row;
      EXPECT_GE(g.texture_slack.at(x, row, kSlackNormal), largest(other - own) * (1.0f - 1e-5f)) << x << "," << row;
    }
  EXPECT_GT(covered, 20);
}

}  // namespace
}  // namespace vct
