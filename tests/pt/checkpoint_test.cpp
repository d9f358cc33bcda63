// Checkpoint and resume: a render stopped after 2 passes and resumed to 4 ends with exactly the
// bytes of a straight 4-pass render; incompatible checkpoints are ignored; asking for fewer
// passes than a checkpoint holds is an input error.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "pt/pathtrace_run.h"
#include "run_dir_fixture.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

namespace fs = std::filesystem;

using test::settings_with;
using test::TempDir;

PathtraceRunResult run(const Scene& scene, const Settings& s, const std::string& dir,
                       std::function<bool()> stop = nullptr) {
  PathtraceRunOptions o;
  o.out_dir = dir;
  o.stop_requested = std::move(stop);
  return run_pathtrace(scene, s, o);
}

std::string checkpoint_bytes(const std::string& dir) { return read_file(dir + "/" + kCheckpointFile); }

TEST(Checkpoint, ResumedRenderEqualsStraightRender) {
  const Scene scene = test::demo_room();
  TempDir a("resumed"), b("straight");
  const PathtraceRunResult first = run(scene, settings_with(2), a.str());
  EXPECT_EQ(first.spp, 2u);
  EXPECT_EQ(first.resumed_from, 0u);
  const PathtraceRunResult second = run(scene, settings_with(4), a.str());
  EXPECT_EQ(second.resumed_from, 2u);
  EXPECT_EQ(second.spp, 4u);
  EXPECT_TRUE(second.completed);
  run(scene, settings_with(4), b.str());
  EXPECT_EQ(checkpoint_bytes(a.str()), checkpoint_bytes(b.str()));
  for (const char* name : {"pt_full", "pt_direct", "pt_indirect_diffuse", "pt_full_var"}) {
    const Image ia = read_image(a.str() + "/" + name + ".exr"), ib = read_image(b.str() + "/" + name + ".exr");
    EXPECT_EQ(ia.data, ib.data) << name;
  }
  EXPECT_TRUE(fs::exists(a.path / "run.json"));
  EXPECT_TRUE(fs::exists(a.path / "pt_indirect_specular.png"));
}

TEST(Checkpoint, InterruptedRenderResumes) {
  const Scene scene = test::demo_room();
  TempDir a("interrupted"), b("uninterrupted");
  int polls = 0;
  const PathtraceRunResult stopped = run(scene, settings_with(4), a.str(), [&] { return ++polls >= 1; });
  EXPECT_FALSE(stopped.completed);
  EXPECT_EQ(stopped.spp, 1u);
  const PathtraceRunResult resumed = run(scene, settings_with(4), a.str());
  EXPECT_EQ(resumed.resumed_from, 1u);
  run(scene, settings_with(4), b.str());
  EXPECT_EQ(checkpoint_bytes(a.str()), checkpoint_bytes(b.str()));
}

TEST(Checkpoint, IncompatibleCheckpointStartsAfresh) {
  const Scene scene = test::demo_room();
  TempDir a("incompatible");
  run(scene, settings_with(2, 1), a.str());
  const PathtraceRunResult other = run(scene, settings_with(3, 2), a.str());
  EXPECT_EQ(other.resumed_from, 0u);
  EXPECT_NE(other.checkpoint_note.find("settings"), std::string::npos);
  Scene moved = scene;
  moved.lights[0].intensity *= 2.0f;
  const PathtraceRunResult other_scene = run(moved, settings_with(3, 2), a.str());
  EXPECT_EQ(other_scene.resumed_from, 0u);
  EXPECT_NE(other_scene.checkpoint_note.find("scene"), std::string::npos);
}

TEST(Checkpoint, FewerSamplesThanCheckpointIsInputError) {
  const Scene scene = test::demo_room();
  TempDir a("fewer");
  run(scene, settings_with(3), a.str());
  EXPECT_THROW(run(scene, settings_with(2), a.str()), InputError);
  // Same count: nothing to do, same result.
  EXPECT_EQ(run(scene, settings_with(3), a.str()).resumed_from, 3u);
}

}  // namespace
}  // namespace vct::pt
