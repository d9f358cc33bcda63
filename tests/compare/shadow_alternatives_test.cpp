// Shadow maps judged on the reference's light-space raster alternatives (freedoms/shadow_map_ties.h,
// compare/tie_range.h): a texel showing a depth a correct GL may store there is admitted at any
// count; any other beyond-bound texel fails, with no edge or interior share. Without the range
// (an external reference) the neighbourhood rule and the edge share stay.
#include <gtest/gtest.h>
#include <string>

#include "compare/stage_compare.h"
#include "freedoms/shadow_map_ties.h"
#include "scene/scene.h"
#include "stages/depth_raster.h"
#include "stages/stage_registry.h"

namespace vct::cmp {
namespace {

constexpr int kSize = 16;

void add_quad(Scene& s, vec3 a, vec3 b, vec3 c, vec3 d) {
  const uint32_t base = uint32_t(s.positions.size());
  for (const vec3& p : {a, b, c, d}) {
    s.positions.push_back(p);
    s.normals.push_back(vec3(0.0f, 0.0f, 1.0f));
    s.uv0.push_back(vec2(0.0f));
    s.bounds.add(p);
  }
  s.triangles.push_back(uvec3(base, base + 1, base + 2));
  s.triangles.push_back(uvec3(base, base + 2, base + 3));
  s.triangle_material.push_back(0);
  s.triangle_material.push_back(0);
}

// tests/ref/shadow_map_ties_test.cpp's silhouette: an orthographic light over x, y in [-8, 8]
// (texel column c's centre at x = c - 7.5), a quad at depth 0.2 whose right edge runs through the
// centres of column 10, a wall at 0.7 behind its lower half (image rows 8..15), nothing (1) above.
struct Silhouette {
  Image map, range;
};
Silhouette silhouette() {
  Scene s;
  s.materials.push_back(Material());
  add_quad(s, {-9, -9, -3}, {2.5f, -9, -3}, {2.5f, 9, -3}, {-9, 9, -3});
  add_quad(s, {-9, -9, -8}, {9, -9, -8}, {9, 0, -8}, {-9, 0, -8});
  const mat4 vp = glm::ortho(-8.0f, 8.0f, -8.0f, 8.0f, 1.0f, 11.0f) *
                  glm::lookAt(vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 1.0f, 0.0f));
  Silhouette out;
  out.map = Image(kSize, kSize, 1);
  out.map.data = render_depth(s.positions, s.triangles, vp, kSize, kSize, &s);
  out.range = shadow_depth_range(s, vp, kSize, ShadowDepthFormat::Depth32f);
  return out;
}

// GL's quad one texel wider: the edge's column shows the quad (as a GL whose snap put the edge a
// step right of the centres would).
Image edge_covered(const Image& map) {
  Image t = map;
  for (int row = 0; row < kSize; ++row) t.at(10, row, 0) = map.at(9, row, 0);
  return t;
}

TEST(ShadowAlternatives, EdgeShiftedOntoItsTiedColumnFailsWithoutTheRangeAndWarnsWithIt) {
  const Silhouette s = silhouette();
  ASSERT_FLOAT_EQ(s.map.at(10, 12, 0), 0.7f);  // the reference keeps the wall on the edge
  ASSERT_EQ(s.map.at(10, 3, 0), 1.0f);          // and nothing above it
  const Image test = edge_covered(s.map);
  CompareOptions opt;
  // Before: each texel is a neighbour's value (an edge tie), but a whole column of them is more
  // than 2.5 % of the edge texels.
  const StageVerdict before = compare_image_stage("shadow_map.0", s.map, test, nullptr, opt);
  EXPECT_EQ(before.verdict, Verdict::Fail) << before.note;
  EXPECT_EQ(before.out_of_bound, 16u);
  EXPECT_EQ(before.extra.at("inadmissible").get<size_t>(), 0u);
  // With the reference's alternatives: the quad's depth is what a correct GL stores there.
  const StageVerdict with = compare_image_stage("shadow_map.0", s.map, test, nullptr, opt, nullptr, nullptr, &s.range);
  EXPECT_EQ(with.verdict, Verdict::Warn) << with.note;
  EXPECT_EQ(with.extra.at("raster_alternatives").get<size_t>(), 16u);
  EXPECT_NE(with.bound.find("shadow_map_tie_range.0"), std::string::npos) << with.bound;
}

TEST(ShadowAlternatives, EdgeShiftedTheOtherWayOrAValueOutsideTheRangeFails) {
  const Silhouette s = silhouette();
  CompareOptions opt;
  // GL's quad one texel narrower: column 9, half a texel inside the quad, shows the wall or
  // nothing. No snap of one step reaches there.
  Image narrower = s.map;
  for (int row = 0; row < kSize; ++row) narrower.at(9, row, 0) = s.map.at(10, row, 0);
  const StageVerdict v = compare_image_stage("shadow_map.0", s.map, narrower, nullptr, opt, nullptr, nullptr, &s.range);
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
  EXPECT_EQ(v.extra.at("inadmissible").get<size_t>(), 16u);
  EXPECT_EQ(v.extra.at("raster_alternatives").get<size_t>(), 0u);
  // On the tied column, a depth in front of both surfaces is no alternative either.
  Image nearer = edge_covered(s.map);
  nearer.at(10, 12, 0) = 0.1f;
  const StageVerdict n = compare_image_stage("shadow_map.0", s.map, nearer, nullptr, opt, nullptr, nullptr, &s.range);
  EXPECT_EQ(n.verdict, Verdict::Fail) << n.note;
  EXPECT_EQ(n.extra.at("inadmissible").get<size_t>(), 1u);
  EXPECT_EQ(n.extra.at("raster_alternatives").get<size_t>(), 15u);
}

// compare_stage_sets finds each map's range beside it by name, for 2D maps and cube faces, and
// keeps the former rule for a reference without one.
TEST(ShadowAlternatives, StageSetsJudgeEachMapOnItsOwnRange) {
  const Silhouette s = silhouette();
  const Image test = edge_covered(s.map);
  for (const char* family : {stage_names::kShadowMap, stage_names::kShadowMapCube}) {
    const std::string stage = std::string(family) + ".3";
    const std::string range = std::string(family) + "_tie_range.3";
    StageSet ref, gl;
    ref.backend = "ref";
    gl.backend = "gl";
    ref.images[stage] = s.map;
    gl.images[stage] = test;
    auto verdict_of = [&](const StageSet& r) {
      for (const StageVerdict& v : compare_stage_sets(r, gl).stages)
        if (v.stage == stage) return v.verdict;
      return Verdict::Missing;
    };
    EXPECT_EQ(verdict_of(ref), Verdict::Fail) << stage;
    ref.images[range] = s.range;
    EXPECT_EQ(verdict_of(ref), Verdict::Warn) << stage;
    // Another member's range is not this map's.
    ref.images.erase(range);
    ref.images[std::string(family) + "_tie_range.2"] = s.range;
    EXPECT_EQ(verdict_of(ref), Verdict::Fail) << stage;
  }
}

}  // namespace
}  // namespace vct::cmp
