#include "compare_scene.h"

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "compare/stage_set_frame.h"
#include "stages/stage_registry.h"
#include "core/error.h"
#include "io/bounded_json.h"
#include "scene/gltf_loader.h"
#include "scene_warnings.h"

namespace vct::app {

namespace {

std::string manifest_of(const cmp::StageSet& set) {
  return (std::filesystem::path(set.root) / "vct-stages.json").string();
}

// The "vct" keys the --config file states (the whole file is validated by load_settings_file).
nlohmann::json config_vct(const std::string& config) {
  if (config.empty()) return nlohmann::json::object();
  load_settings_file(config, Settings());
  const nlohmann::json j = read_bounded_json_file(config, "settings file");
  return j.is_object() && j.contains("vct") ? j["vct"] : nlohmann::json::object();
}

// The manifest's settings are free-form (docs/external_format.md): only VctSettings keys are used.
nlohmann::json manifest_vct(const cmp::StageSet& test, const nlohmann::json& known) {
  nlohmann::json used = nlohmann::json::object();
  std::string ignored;
  if (test.settings.is_object())
    for (const auto& [k, v] : test.settings.items()) {
      if (known.contains(k)) used[k] = v;
      else ignored += (ignored.empty() ? "" : ", ") + k;
    }
  if (!ignored.empty()) std::printf("note: --scene ignores manifest settings that are not VCT settings: %s\n", ignored.c_str());
  return used;
}

void note_overrides(const nlohmann::json& config, const nlohmann::json& manifest) {
  std::string keys;
  for (const auto& [k, v] : config.items())
    if (manifest.contains(k) && manifest[k] != v) keys += (keys.empty() ? "" : ", ") + k;
  if (!keys.empty()) std::printf("note: B's manifest overrides --config for: %s\n", keys.c_str());
}

// Sizes are facts of B's files; a settings layer that disagrees describes another run.
void check_sizes(const nlohmann::json& layer, const nlohmann::json& data, const std::string& where) {
  for (const auto& [k, v] : data.items())
    if (layer.contains(k) && layer[k] != v)
      throw InputError(where, "says " + k + " = " + layer[k].dump() + " but B's stages have " + k + " = " + v.dump() +
                                  " (gbuffer.coverage, voxel.radiance)");
}

}  // namespace

nlohmann::json data_sizes(const cmp::StageSet& test) {
  nlohmann::json sizes = nlohmann::json::object();
  // A partial G-buffer (compare/partial_gbuffer.h) has no coverage: its depth gives the size.
  for (const char* stage : {stage_names::kGbufferCoverage, stage_names::kGbufferDepth})
    if (test.images.count(stage)) {
      sizes["width"] = test.images.at(stage).width;
      sizes["height"] = test.images.at(stage).height;
      break;
    }
  if (test.volumes.count(stage_names::kVoxelRadiance)) sizes["grid"] = test.volumes.at(stage_names::kVoxelRadiance).nx;
  return sizes;
}

VctSettings settings_of_test_set(const cmp::StageSet& test, const std::string& config) {
  nlohmann::json merged = VctSettings();
  const nlohmann::json from_config = config_vct(config), from_manifest = manifest_vct(test, merged);
  const nlohmann::json sizes = data_sizes(test);
  check_sizes(from_config, sizes, config);
  check_sizes(from_manifest, sizes, manifest_of(test));
  note_overrides(from_config, from_manifest);
  merged.merge_patch(from_config);
  merged.merge_patch(from_manifest);
  merged.merge_patch(sizes);
  Settings s;
  try {
    s.vct = merged.get<VctSettings>();
    validate_settings(s);
  } catch (const InputError& e) {
    throw InputError(manifest_of(test), std::string("settings for --scene: ") + e.what());
  }
  return s.vct;
}

IsolatedInputs load_isolated_inputs(const cmp::StageSet& test, const std::string& scene_arg,
                                    const std::string& config, const SceneLoadOptions& scene_load,
                                    const cmp::StageSet* reference) {
  IsolatedInputs in;
  in.scene = load_scene_and_warn(scene_arg == kBuiltinSceneName ? std::string() : scene_arg, scene_load);
  in.settings = settings_of_test_set(test, config);
  expose_scene(in.scene, in.settings);  // the reference renders the scene as the settings expose it
  in.frame = cmp::frame_from_stage_set(test, in.scene, in.settings, reference);
  return in;
}

}  // namespace vct::app
