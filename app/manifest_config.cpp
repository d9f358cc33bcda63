#include "manifest_config.h"

#include <filesystem>

#include "compare_scene.h"
#include "core/error.h"
#include "core/reduction_names.h"
#include "core/settings.h"

namespace vct::app {
namespace {

std::string setting_reduction(const std::string& name) {
  const auto r = reduction_from_name(name);
  for (const ReductionName& n : kReductionNames)
    if (r && n.value == *r) return n.setting;
  return "exact";
}

// The manifest's free-form settings that are VCT settings keys (docs/external_format.md).
void add_settings(const cmp::StageSet& set, const nlohmann::json& known, nlohmann::json& vct, std::vector<std::string>& notes) {
  if (!set.settings.is_object()) return;
  for (const auto& [key, value] : set.settings.items()) {
    if (known.contains(key)) vct[key] = value;
    else notes.push_back("settings." + key + ": not a VCT setting (vct settings lists them), left out");
  }
}

void add_storage_and_reduction(const cmp::StageSet& set, nlohmann::json& vct, std::vector<std::string>& notes) {
  vct["reduction"] = setting_reduction(set.reduction);
  if (set.storage == "rgba8" || set.storage == "rgba16f") vct["storage"] = set.storage;
  else notes.push_back("storage " + set.storage + ": the reference keeps float voxels; the judge reads storage from the manifest");
}

void add_facts(const cmp::StageSet& set, nlohmann::json& vct, std::vector<std::string>& notes) {
  if (set.facts.msaa_samples > 0) vct["msaa_samples"] = set.facts.msaa_samples;
  if (!set.facts.sample_positions.empty())
    notes.push_back("facts.sample_positions: render with --facts-from " + set.root + " to voxelize at them");
}

}  // namespace

nlohmann::json config_from_manifest(const cmp::StageSet& set, std::vector<std::string>& notes) {
  const nlohmann::json known = VctSettings();
  nlohmann::json vct = nlohmann::json::object();
  add_settings(set, known, vct, notes);
  add_storage_and_reduction(set, vct, notes);
  add_facts(set, vct, notes);
  vct.merge_patch(data_sizes(set));  // the files' sizes are facts, above any stated setting
  if (!set.conventions.empty())
    notes.push_back("conventions: judged by vct compare from the manifest, nothing to render");
  const std::string manifest = (std::filesystem::path(set.root) / "vct-stages.json").string();
  nlohmann::json merged = known;
  merged.merge_patch(vct);
  try {
    Settings s;
    s.vct = merged.get<VctSettings>();
    validate_settings(s);
  } catch (const InputError& e) {
    throw InputError(manifest, std::string("its settings are not valid reference settings: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(manifest, std::string("its settings are not valid reference settings: ") + e.what());
  }
  return {{"vct", vct}};
}

}  // namespace vct::app
