// The reference's texture slack widens the textured G-buffer stages' bounds, and only theirs.
#include <gtest/gtest.h>

#include "compare/stage_compare.h"
#include "compare/tolerance.h"
#include "find_verdict.h"

namespace vct::cmp {
namespace {

using test::find;

// 8x8 flat G-buffer; the test's normal and albedo differ by 0.05 on pixel (3, 4), which is beyond
// the 8-bit-weight bounds (normal: 2^-6 + 2^-7 * 0.6 = 0.0203; albedo: 2^-7 + 2^-7 * 0.5 = 0.0117).
struct Sets {
  StageSet ref, test;
};

Sets textured_sets(float slack_normal, float slack_albedo) {
  Sets s;
  s.ref.backend = "ref";
  s.test.backend = "gl";
  s.ref.images["gbuffer.depth"] = Image(8, 8, 1, 0.5f);
  s.ref.images["gbuffer.normal"] = Image(8, 8, 3, 0.6f);
  s.ref.images["gbuffer.albedo"] = Image(8, 8, 3, 0.5f);
  s.test.images = s.ref.images;
  s.test.images["gbuffer.normal"].at(3, 4, 1) += 0.05f;
  s.test.images["gbuffer.albedo"].at(3, 4, 0) += 0.05f;
  // Channels in EXR order (sorted by name), as read back from a run directory.
  Image slack(8, 8, 4, 0.0f);
  slack.channel_names = {"albedo", "emission", "material", "normal"};
  slack.at(3, 4, 3) = slack_normal;
  slack.at(3, 4, 0) = slack_albedo;
  s.ref.images["gbuffer.texture_slack"] = slack;
  return s;
}

TEST(TextureSlackBound, SlackCoversAShiftedTextureSampleOnlyWhereItIsLargeEnough) {
  {
    const Sets s = textured_sets(0.0f, 0.0f);
    const Report r = compare_stage_sets(s.ref, s.test);
    EXPECT_EQ(find(r, "gbuffer.normal").verdict, Verdict::Fail);
    EXPECT_EQ(find(r, "gbuffer.albedo").verdict, Verdict::Fail);
  }
  {
    // 0.05 - 0.0203 = 0.0297 needed for the normal, 0.05 - 0.0117 = 0.0383 for the albedo.
    const Sets s = textured_sets(0.03f, 0.03f);
    const Report r = compare_stage_sets(s.ref, s.test);
    EXPECT_EQ(find(r, "gbuffer.normal").verdict, Verdict::Pass);
    EXPECT_EQ(find(r, "gbuffer.albedo").verdict, Verdict::Fail);
    EXPECT_NEAR(find(r, "gbuffer.albedo").worst.at(0).bound, 0.0117 + 0.03, 1e-4);
  }
  {
    const Sets s = textured_sets(0.03f, 0.04f);
    const Report r = compare_stage_sets(s.ref, s.test);
    EXPECT_EQ(r.overall(), Verdict::Pass);
    // An auxiliary of the reference, not a stage: no "missing on gl" verdict for it.
    for (const auto& v : r.stages) EXPECT_NE(v.stage, "gbuffer.texture_slack");
  }
}

TEST(TextureSlackBound, ChannelsAreFoundByName) {
  Image named(1, 1, 4);
  named.channel_names = {"albedo", "emission", "material", "normal"};
  EXPECT_EQ(texture_slack_channel("gbuffer.normal", named), 3);
  EXPECT_EQ(texture_slack_channel("gbuffer.albedo", named), 0);
  EXPECT_EQ(texture_slack_channel("gbuffer.material", named), 2);
  EXPECT_EQ(texture_slack_channel("gbuffer.emission", named), 1);
  EXPECT_EQ(texture_slack_channel("image.emission", named), 1);  // the G-buffer emission, added
  EXPECT_EQ(texture_slack_channel("gbuffer.position", named), -1);
  EXPECT_EQ(texture_slack_channel("image.final", named), -1);
  const Image unnamed(1, 1, 4);  // freedoms/texture_slack.h's order
  EXPECT_EQ(texture_slack_channel("gbuffer.normal", unnamed), 0);
  EXPECT_EQ(texture_slack_channel("gbuffer.emission", unnamed), 3);
  EXPECT_EQ(texture_slack_channel("image.emission", unnamed), 3);
}

}  // namespace
}  // namespace vct::cmp
