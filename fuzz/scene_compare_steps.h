// What `vct compare A B --scene builtin:cornell_box` does with a stage set B before it re-traces
// any cone: read B, settle the settings (B's manifest "settings" over the defaults), rebuild B's
// frame against the scene (compare/stage_set_frame.h), and judge B's stages against a reference
// A. Shared by scene_compare_fuzz and its regression test, so a crasher replays exactly.
#pragma once

#include <string>

#include "../app/compare_scene.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "compare/stage_set_frame.h"
#include "core/error.h"
#include "freedoms/reference_frame.h"
#include "fuzz_inputs.h"
#include "scene/gltf_loader.h"

namespace vct::fuzz {

/// What stays fixed across inputs: the built-in scene and A, its reference frame at the sizes of
/// the seeds (fuzz/make_seeds.py: 16 x 16 pixels, 16^3 voxels, 64^2 shadow map, and the GPU
/// voxelizer rule with fixed-point sums, as `vct validate` renders its ref/).
struct SceneCompareFixture {
  Scene scene;
  cmp::StageSet reference;
};

inline Settings scene_compare_seed_settings() {
  Settings s;
  s.vct.width = s.vct.height = 16;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 64;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.reduction = Reduction::FixedPoint;
  return s;
}

inline SceneCompareFixture make_scene_compare_fixture() {
  SceneCompareFixture f{load_scene(""), {}};
  const Settings s = scene_compare_seed_settings();
  f.reference = cmp::stage_set_from_frame(render_ref_frame(f.scene, s), s.vct);
  return f;
}

/// Steps passed without InputError: 0 = B did not read, 1 = read, 2 = read and its frame rebuilt;
/// +4 when A vs B was judged. Anything other than InputError escapes (the fuzzer's crash).
inline int run_scene_compare_steps(const std::string& input, const SceneCompareFixture& fx) {
  const auto dir = write_named_stage_set(input);
  cmp::StageSet test;
  try {
    test = cmp::read_stage_set(dir.string());
  } catch (const InputError&) {
    return 0;
  }
  int steps = 1;
  try {
    const VctSettings s = app::settings_of_test_set(test, "");
    cmp::frame_from_stage_set(test, fx.scene, s);
    steps = 2;
  } catch (const InputError&) {
  }
  try {  // `vct compare A B` judges every stage whether or not --scene is given
    cmp::compare_stage_sets(fx.reference, test);
    steps += 4;
  } catch (const InputError&) {
  }
  return steps;
}

}  // namespace vct::fuzz
