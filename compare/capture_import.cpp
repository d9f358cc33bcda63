#include "compare/capture_import.h"

#include <filesystem>
#include <unistd.h>

#include "core/error.h"
#include "core/reduction_names.h"

namespace vct::cmp {
namespace fs = std::filesystem;
namespace {

std::vector<std::string> channel_names(const std::string& stage, int channels) {
  if (channels == 1)
    return {stage.rfind("shadow_map", 0) == 0 || stage == "gbuffer.depth" ? "Z" : "Y"};
  const std::vector<std::string> rgba = {"R", "G", "B", "A"};
  return {rgba.begin(), rgba.begin() + channels};
}

std::vector<int> kept_channels(const CaptureStage& s, const CapturedTexture& t, const std::string& path) {
  std::vector<int> keep = s.channels;
  if (keep.empty())
    for (int c = 0; c < t.channels; ++c) keep.push_back(c);
  for (int c : keep)
    if (c >= t.channels)
      throw InputError(path, "stage '" + s.name + "': channel " + std::to_string(c) + " asked of '" + s.resource + "' (" +
                                 t.format + ", " + std::to_string(t.channels) + " channels)");
  return keep;
}

void check_size(const CaptureStage& s, const CapturedTexture& t, const std::string& path) {
  const size_t texels = size_t(t.width) * size_t(t.height) * size_t(t.depth);
  if (t.width < 1 || t.height < 1 || t.depth < 1 || t.channels < 1 || t.data.size() != texels * size_t(t.channels))
    throw InputError(path, "stage '" + s.name + "': the reader returned " + std::to_string(t.data.size()) + " values for a " +
                               std::to_string(t.width) + "x" + std::to_string(t.height) + "x" + std::to_string(t.depth) + "x" +
                               std::to_string(t.channels) + " texture");
  if (s.kind == "image" && t.depth != 1)
    throw InputError(path, "stage '" + s.name + "' is an image but '" + s.resource + "' level " + std::to_string(s.mip) +
                               " is " + std::to_string(t.depth) + " deep (a 3D texture: name a volume stage)");
}

// Image rows: GL's bottom-first rows are flipped so row 0 is the top (docs/external_format.md,
// Conventions); volumes keep the API's order, which is the voxel coordinates' in every API.
Image image_of(const CaptureStage& s, const CapturedTexture& t, const std::vector<int>& keep) {
  Image img(t.width, t.height, int(keep.size()));
  for (int y = 0; y < t.height; ++y) {
    const int src_row = s.bottom_first ? t.height - 1 - y : y;
    for (int x = 0; x < t.width; ++x)
      for (size_t c = 0; c < keep.size(); ++c)
        img.at(x, y, int(c)) = t.data[(size_t(src_row) * size_t(t.width) + size_t(x)) * size_t(t.channels) + size_t(keep[c])];
  }
  img.channel_names = channel_names(s.name, img.channels);
  return img;
}

Volume volume_of(const CaptureStage& s, const CapturedTexture& t, const std::vector<int>& keep) {
  Volume v(t.width, t.height, t.depth, int(keep.size()));
  const size_t texels = size_t(t.width) * size_t(t.height) * size_t(t.depth);
  for (size_t i = 0; i < texels; ++i)
    for (size_t c = 0; c < keep.size(); ++c) v.data[i * keep.size() + c] = t.data[i * size_t(t.channels) + size_t(keep[c])];
  v.channel_names = channel_names(s.name, v.channels);
  return v;
}

std::string string_or(const nlohmann::json& m, const char* key, const char* fallback) {
  return m.contains(key) ? m[key].get<std::string>() : std::string(fallback);
}

void fill_header(const CaptureMap& map, StageSet& set) {
  const nlohmann::json& m = map.manifest;
  set.backend = string_or(m, "backend", "capture");
  set.storage = string_or(m, "storage", "rgba32f");
  set.reduction = manifest_reduction_name(reduction_from_name(string_or(m, "reduction", "exact_mean")).value_or(Reduction::ExactMean));
  if (m.contains("settings")) set.settings = m["settings"];
  if (m.contains("info")) set.info = m["info"];
  if (m.contains("facts")) set.facts = m["facts"].get<BackendFacts>();
  if (m.contains("conventions")) set.conventions = read_conventions(map.path, m["conventions"]);
}

}  // namespace

StageSet stage_set_from_capture(const CaptureMap& map, const std::vector<CapturedTexture>& textures) {
  if (textures.size() != map.stages.size())
    throw InputError(map.path, "the capture reader returned " + std::to_string(textures.size()) + " textures for " +
                                   std::to_string(map.stages.size()) + " stages");
  StageSet set;
  fill_header(map, set);
  for (size_t i = 0; i < map.stages.size(); ++i) {
    const CaptureStage& s = map.stages[i];
    const CapturedTexture& t = textures[i];
    check_size(s, t, map.path);
    const std::vector<int> keep = kept_channels(s, t, map.path);
    if (s.kind == "image")
      set.images[s.name] = image_of(s, t, keep);
    else
      set.volumes[s.name] = volume_of(s, t, keep);
  }
  return set;
}

void import_capture(const std::string& capture, const CaptureMap& map, CaptureReader& reader, const std::string& out_dir) {
  const fs::path out = fs::absolute(out_dir).lexically_normal();
  if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out)))
    throw InputError(out_dir, "exists and is not an empty directory (remove it or choose another --out)");
  StageSet set = stage_set_from_capture(map, reader.read(capture, map.stages));
  set.info["capture"] = fs::path(capture).filename().string();
  set.info["capture_map"] = fs::path(map.path).filename().string();
  const fs::path tmp = out.parent_path() / (out.filename().string() + ".importing-" + std::to_string(getpid()));
  fs::create_directories(out.parent_path());
  fs::remove_all(tmp);
  try {
    write_stage_set(tmp.string(), set);
    (void)read_stage_set(tmp.string());  // the checks `vct compare` makes (kinds, channels, facts)
    if (fs::exists(out)) fs::remove(out);  // empty, checked above
    fs::rename(tmp, out);
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(tmp, ignored);
    throw;
  }
}

}  // namespace vct::cmp
