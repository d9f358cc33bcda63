// Alpha-mask ties are geometric-edge ties (docs/compare.md, "Alpha-mask ties"): a sample whose
// alpha lies within the freedom GL leaves it (freedoms/alpha_ties.h: 8-bit bilinear weights plus a
// 2^-8 pixel sample shift) of the cutoff may show the surface or what lies behind it. The
// reference's G-buffer marks every such pixel (texture slack channel alpha_tie), and the
// comparison adds the marks to its edge map, where a flipped pixel must still be an admissible
// neighbour value; nothing else is admitted and no bound is widened.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <utility>

#include "compare/image_edges.h"
#include "compare/stage_compare.h"
#include "freedoms/alpha_ties.h"
#include "freedoms/gbuffer_freedoms.h"
#include "scene/alpha_mask.h"
#include "scene/gltf_loader.h"
#include "stages/gbuffer.h"
#include "stages/raster.h"

namespace vct::cmp {
namespace {

const Scene& foliage() {
  static const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/foliage.gltf");
  return scene;
}

struct TieCount {
  int may_flip = 0;     // samples whose alpha test could go either way
  int depth_edges = 0;  // of those, pixels the depth edge map flags on its own
  int marked = 0;       // of those, pixels the reference's alpha_tie channel marks
};

// The front-most surface of each pixel, masks ignored: where a masked sample could appear or
// vanish; its alpha test may flip there.
TieCount alpha_ties_in_view(const Scene& s, const mat4& view_proj, int size, const Image& depth,
                            const Image* alpha_tie) {
  const VisibilityBuffer unmasked =
      render_visibility(s.positions, s.triangles, view_proj, size, size);
  const WindowBarycentrics wb(view_proj, size, size);
  const std::vector<uint8_t> edges = edge_map(depth, &depth);
  TieCount c;
  for (int row = 0; row < size; ++row)
    for (int x = 0; x < size; ++x) {
      const size_t i = unmasked.index(x, row);
      if (unmasked.triangle[i] < 0) continue;
      if (!alpha_test_may_flip(s, wb, x, row, uint32_t(unmasked.triangle[i]), unmasked.bary[i]))
        continue;
      ++c.may_flip;
      c.depth_edges += edges[i];
      if (alpha_tie && alpha_tie->at(x, row, kSlackAlphaTie) > 0.0f) ++c.marked;
    }
  return c;
}

TEST(AlphaTies, TheGbufferMarksEverySampleThatMayFlip) {
  // The depth edge map alone misses some (a card in front of another card a few cm behind: the
  // window-depth second difference stays below 1e-3), so the G-buffer marks them itself.
  const Scene& s = foliage();
  int total = 0, missed_by_depth = 0;
  for (int size : {64, 128, 256}) {
    VctSettings st;
    st.width = st.height = size;
    const GBuffer g = render_gbuffer_with_freedoms(s, st);
    const mat4 view_proj = s.camera.projection(1.0f) * s.camera.view();
    const TieCount c = alpha_ties_in_view(s, view_proj, size, g.depth, &g.texture_slack);
    std::printf("  gbuffer %d^2: %d samples may flip, %d flagged by depth, %d marked alpha_tie\n",
                size, c.may_flip, c.depth_edges, c.marked);
    EXPECT_EQ(c.marked, c.may_flip);
    total += c.may_flip;
    missed_by_depth += c.may_flip - c.depth_edges;
  }
  EXPECT_GT(total, 0) << "the scene must have alpha ties for this test to say anything";
  EXPECT_GT(missed_by_depth, 0) << "the depth edge map would then suffice; the channel is moot";
}

TEST(AlphaTies, AFlipIsAdmittedOnlyWhereTheAlphaTieChannelMarksIt) {
  // Foliage at 256^2, stage gbuffer.depth (its edge map is the depth's own): a pixel the alpha_tie
  // channel marks and the depth edge map does not, flipped to the farthest depth of its 3x3
  // neighbourhood (a flip shows another surface, here one a few cm behind): a tolerated tie with
  // the channel, a failure without it; the same flip on an unmarked pixel fails.
  const Scene& s = foliage();
  VctSettings st;
  st.width = st.height = 256;
  const GBuffer g = render_gbuffer_with_freedoms(s, st);
  const Image& ref = g.depth;
  const std::vector<uint8_t> depth_edges = edge_map(ref, &ref);
  const auto flipped = [&](int x, int y) {
    Image t = ref;
    float best = -1.0f;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const float d = std::abs(ref.at(x + dx, y + dy, 0) - ref.at(x, y, 0));
        if (d > best) best = d, t.at(x, y, 0) = ref.at(x + dx, y + dy, 0);
      }
    return std::make_pair(t, best);
  };
  int tie_x = -1, tie_y = -1, plain_x = -1, plain_y = -1;
  for (int y = 1; y < 255; ++y)
    for (int x = 1; x < 255; ++x) {
      const size_t i = size_t(y) * 256 + size_t(x);
      if (depth_edges[i] || g.coverage.at(x, y, 0) == 0.0f || flipped(x, y).second < 2e-4f)
        continue;
      if (g.texture_slack.at(x, y, kSlackAlphaTie) > 0.0f)
        tie_x = x, tie_y = y;
      else
        plain_x = x, plain_y = y;
    }
  ASSERT_GE(tie_x, 0) << "no marked alpha tie off the depth edges";
  ASSERT_GE(plain_x, 0);
  std::printf("  flipped alpha tie at %d,%d; plain pixel at %d,%d\n", tie_x, tie_y, plain_x,
              plain_y);
  CompareOptions opt;
  Image no_ties = g.texture_slack;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) no_ties.at(x, y, kSlackAlphaTie) = 0.0f;
  const Image tie = flipped(tie_x, tie_y).first;
  const StageVerdict admitted =
      compare_image_stage("gbuffer.depth", ref, tie, &ref, opt, &g.texture_slack);
  EXPECT_EQ(admitted.verdict, Verdict::Warn) << admitted.note;
  EXPECT_EQ(compare_image_stage("gbuffer.depth", ref, tie, &ref, opt, &no_ties).verdict,
            Verdict::Fail);
  const Image plain = flipped(plain_x, plain_y).first;
  EXPECT_EQ(compare_image_stage("gbuffer.depth", ref, plain, &ref, opt, &g.texture_slack).verdict,
            Verdict::Fail);
}

TEST(AlphaTies, FreedomIsTheWeightTermOnAFlatAlpha) {
  // Far from the ramp the alpha is constant (0 or 1): no shift changes it, only the weight term
  // remains, and 0 or 1 is never within it of the cutoff 1/2.
  Scene s = foliage();
  VctSettings st;
  st.width = st.height = 64;
  const mat4 view_proj = s.camera.projection(1.0f) * s.camera.view();
  const VisibilityBuffer vb = render_visibility(s.positions, s.triangles, view_proj, 64, 64);
  const WindowBarycentrics wb(view_proj, 64, 64);
  int flat = 0;
  for (int row = 0; row < 64; ++row)
    for (int x = 0; x < 64; ++x) {
      const size_t i = vb.index(x, row);
      if (vb.triangle[i] < 0 || !triangle_alpha_tested(s, uint32_t(vb.triangle[i]))) continue;
      const float a = base_color_alpha(s, uint32_t(vb.triangle[i]), vb.bary[i].y, vb.bary[i].z);
      if (a != 0.0f && a != 1.0f) continue;
      const float f = alpha_freedom(s, wb, x, row, uint32_t(vb.triangle[i]), vb.bary[i]);
      if (f == kAlphaWeightSlack) ++flat;
      EXPECT_GE(f, kAlphaWeightSlack);
      EXPECT_FALSE(alpha_test_may_flip(s, wb, x, row, uint32_t(vb.triangle[i]), vb.bary[i]));
    }
  EXPECT_GT(flat, 50);
}

}  // namespace
}  // namespace vct::cmp
