// `vct compare A B --scene SCENE [--config FILE.json]`: what the isolated judgement of B's
// cone-traced stages needs (the scene, the settings B ran with, the frame behind B's stage set),
// gathered and checked before anything is compared, so bad input writes nothing (docs/compare.md).
#pragma once

#include <string>

#include "compare/stage_set.h"
#include "core/settings.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::app {

/// The VCT settings B was rendered with, in increasing precedence: the library defaults
/// (Settings()), the "vct" object of --config FILE (empty = none), then the keys of B's manifest
/// "settings" that are VctSettings keys (what B says it ran beats what the user guessed; a key
/// both give differently is named in a printed note, unknown manifest keys too). width, height
/// and grid are always B's own sizes (gbuffer.coverage, voxel.radiance); a layer that states a
/// different one is an InputError.
VctSettings settings_of_test_set(const cmp::StageSet& test, const std::string& config);

/// width, height (gbuffer.coverage, else gbuffer.depth) and grid (voxel.radiance) of a stage set's
/// files, for the stages it has.
nlohmann::json data_sizes(const cmp::StageSet& test);

struct IsolatedInputs {
  Scene scene;
  VctSettings settings;
  FrameResult frame;  // B's frame as far as the cone stages need it (compare/stage_set_frame.h)
};

/// `scene_arg` is a glTF path or "builtin:cornell_box". Throws InputError on a missing scene, a
/// missing cone input (named), a size mismatch or a scene that cannot be B's. `reference`: A's set,
/// which fills a partial G-buffer's missing stages (compare/partial_gbuffer.h).
IsolatedInputs load_isolated_inputs(const cmp::StageSet& test, const std::string& scene_arg,
                                    const std::string& config, const SceneLoadOptions& scene_load = {},
                                    const cmp::StageSet* reference = nullptr);

}  // namespace vct::app
