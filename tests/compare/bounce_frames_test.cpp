// Every multibounce frame judged (compare/bounce_frames.h; docs/compare.md, "Every multibounce frame
// is judged"): on the built-in box, the reference judged as its own test passes every frame, and a
// test whose bounce frames read the frame being written (GL's bounce_reads_current_frame,
// reproduced on the CPU: frame 2 without bounce light, frame 3 lit by frame 1) fails at frame 2 —
// while its last frame, on its own bounce input, passes, as it did before every frame was judged.
#include <gtest/gtest.h>

#include "compare/bounce_frames.h"
#include "compare/judge.h"
#include "find_verdict.h"
#include "freedoms/reference_frame.h"
#include "scene/gltf_loader.h"
#include "stages/multibounce.h"

namespace vct::cmp {
namespace {

Settings box_settings(int bounces) {
  Settings s;
  s.vct.width = s.vct.height = 32;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 128;
  s.vct.bounces = bounces;
  s.threads = 2;
  return s;
}

struct Judged {
  Report rep;
  FrameResult test;
};

Judged judge_as_test(const Scene& scene, const Settings& s, const FrameResult& ref, FrameResult test) {
  const StageSet test_set = stage_set_from_frame(test, s.vct);
  Report rep = judge(stage_set_from_frame(ref, s.vct), test_set, {&scene, &test, &s.vct});
  return {std::move(rep), std::move(test)};
}

TEST(BounceFrames, TheReferenceAsItsOwnTestPassesEveryFrame) {
  const Scene scene = load_scene("");
  const Settings s = box_settings(3);
  const FrameResult ref = render_ref_frame(scene, s);
  ASSERT_EQ(ref.multibounce_frames.size(), 2u);
  const Judged j = judge_as_test(scene, s, ref, ref);
  EXPECT_EQ(j.rep.first_failing(), "");
  for (const char* stage : {"voxel.frame.1", "voxel.frame.2", "voxel.energy"}) {
    const StageVerdict& v = test::find(j.rep, stage);
    EXPECT_EQ(v.verdict, Verdict::Pass) << stage << ": " << v.note;
  }
  const StageVerdict& energy = test::find(j.rep, "voxel.energy");
  ASSERT_EQ(energy.checked, 3u) << energy.note;  // frames 1, 2 and the last
  for (const auto& f : energy.extra["frames"]) EXPECT_EQ(f["test"], f["reference_on_test_inputs"]) << energy.note;
}

// vct validate moves the test frame's grid into its set before judging (stage_set_taking_voxels,
// app/validate_checks.cpp): the energy's summation allowance then counts the set's voxels, and the
// report is the one judged on the whole frame, note for note.
TEST(BounceFrames, JudgingAFrameWhoseGridWentToItsSetDecidesTheSame) {
  const Scene scene = load_scene("");
  const Settings s = box_settings(3);
  const FrameResult ref = render_ref_frame(scene, s);
  const Judged whole = judge_as_test(scene, s, ref, ref);
  FrameResult taken = ref;
  const StageSet test_set = stage_set_taking_voxels(taken, s.vct);
  ASSERT_EQ(taken.voxels.radiance.voxel_count(), 0u);
  const Report rep = judge(stage_set_from_frame(ref, s.vct), test_set, {&scene, &taken, &s.vct});
  EXPECT_EQ(to_json(rep).dump(), to_json(whole.rep).dump());
  EXPECT_EQ(test::find(rep, "voxel.energy").checked, 3u);
}

// The fault's frames: frame 2 injected with no bounce light (it read an empty texture), frame 3
// with the bounce light of frame 1 (the texture it writes held frame 1's mips).
FrameResult reads_current_frame(const Scene& scene, const Settings& s, const FrameResult& ref) {
  Settings one = s;
  one.vct.bounces = 1;
  Settings two = s;
  two.vct.bounces = 2;
  const FrameResult f1 = render_ref_frame(scene, one);
  const FrameResult f2 = render_ref_frame(scene, two);  // its last frame: lit by frame 1
  FrameResult test = ref;
  test.backend = "reads-current";
  test.multibounce_frames = {f1.voxels.radiance, f1.voxels.radiance};
  test.bounce_input = f1.voxels.radiance;
  test.voxels = f2.voxels;
  test.mips = f2.mips;
  test.multibounce_energy = {f1.multibounce_energy[0], f1.multibounce_energy[0], f2.multibounce_energy[1]};
  return test;
}

TEST(BounceFrames, ABounceFrameReadingTheCurrentFrameFailsAtFrameTwo) {
  const Scene scene = load_scene("");
  const Settings s = box_settings(3);
  const FrameResult ref = render_ref_frame(scene, s);
  const Judged j = judge_as_test(scene, s, ref, reads_current_frame(scene, s, ref));
  std::printf("  energy: %s\n", test::find(j.rep, "voxel.energy").note.c_str());
  EXPECT_EQ(j.rep.first_failing(), "voxel.frame.2");
  EXPECT_EQ(test::find(j.rep, "voxel.frame.1").verdict, Verdict::Pass) << test::find(j.rep, "voxel.frame.1").note;
  const StageVerdict& frame2 = test::find(j.rep, "voxel.frame.2");
  EXPECT_EQ(frame2.verdict, Verdict::Fail);
  EXPECT_NE(frame2.note.find("frame 2 of 3"), std::string::npos) << frame2.note;
  // The last frame, on its own bounce input (the test's frame 2), is right: what let it through.
  EXPECT_NE(test::find(j.rep, "voxel.radiance").verdict, Verdict::Fail) << test::find(j.rep, "voxel.radiance").note;
  const StageVerdict& energy = test::find(j.rep, "voxel.energy");
  EXPECT_EQ(energy.verdict, Verdict::Fail) << energy.note;
  EXPECT_EQ(energy.extra.value("first_failing_frame", 0), 2) << energy.note;
  EXPECT_EQ(energy.out_of_bound, 1u) << energy.note;  // frames 1 and 3 are right on their inputs
}

// Without a scene (vct compare A B) no frame can be re-injected: the frames say so, never pass.
TEST(BounceFrames, WithoutTheSceneTheFramesAreMissingAndSayWhy) {
  const Scene scene = load_scene("");
  const Settings s = box_settings(2);
  const FrameResult ref = render_ref_frame(scene, s);
  const Report rep = judge(stage_set_from_frame(ref, s.vct), stage_set_from_frame(ref, s.vct));
  EXPECT_EQ(test::find(rep, "voxel.frame.1").verdict, Verdict::Missing);
  EXPECT_EQ(test::find(rep, "voxel.frame.1").note, kBounceFramesNeedTheScene);
  EXPECT_EQ(test::find(rep, "voxel.energy").verdict, Verdict::Missing);
}

TEST(BounceFrames, SummationAllowanceIsTheDoubleSumsBound) {
  // 1000 voxels: 2999 additions of 2^-53 relative each, on both sums.
  EXPECT_DOUBLE_EQ(energy_summation_allowance(1000, 1.0, 1.0), 2999.0 * std::ldexp(1.0, -53) * 2.0);
  EXPECT_EQ(energy_summation_allowance(0, 5.0, 5.0), 0.0);
}

}  // namespace
}  // namespace vct::cmp
