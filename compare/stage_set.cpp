#include "stage_set.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <set>
#include <utility>

#include "core/error.h"
#include "core/parallel_tasks.h"
#include "io/atomic_file.h"
#include "io/bounded_json.h"
#include "io/image_io.h"
#include "io/nrrd.h"
#include "io/run_dir.h"
#include "core/reduction_names.h"
#include "stages/dumps.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace fs = std::filesystem;

std::string storage_name(VoxelStorage s) { return s == VoxelStorage::Rgba8 ? "rgba8" : "rgba16f"; }
std::string reduction_name(Reduction r) { return manifest_reduction_name(r); }

StageSet stage_set_header(const FrameResult& f, const VctSettings& s) {
  StageSet set;
  set.backend = f.backend;
  set.storage = storage_name(s.storage);
  set.reduction = reduction_name(s.reduction);
  set.settings = s;
  for (const auto& [k, v] : f.info) set.info[k] = v;
  set.facts = f.facts;
  // A backend may substitute a reduction (GL has no exact float mean: its facts say so).
  if (!f.facts.reduction.empty()) set.reduction = f.facts.reduction;
  if (!f.multibounce_energy.empty()) set.info["multibounce_energy"] = f.multibounce_energy;
  return set;
}

StageSet stage_set_without_stages(const StageSet& set) {
  StageSet out;
  out.backend = set.backend;
  out.storage = set.storage;
  out.reduction = set.reduction;
  out.settings = set.settings;
  out.info = set.info;
  out.conventions = set.conventions;
  out.facts = set.facts;
  out.root = set.root;
  out.files = set.files;
  return out;
}

StageSet stage_set_from_frame(const FrameResult& f, const VctSettings& s) {
  StageSet set = stage_set_header(f, s);
  for (const StageRow& row : stage_rows())
    for (int i : frame_members(f, row)) {
      if (row.kind == StageKind::Image) set.images[stage_name(row, i)] = *frame_image(f, row, i);
      else set.volumes[stage_name(row, i)] = *frame_volume(f, row, i);
    }
  return set;
}

StageSet stage_set_from_frame(FrameResult&& f, const VctSettings& s) {
  StageSet set = stage_set_header(f, s);
  for (const StageRow& row : stage_rows())
    for (int i : frame_members(f, row)) {  // every member found before any is moved
      if (row.kind == StageKind::Image) set.images[stage_name(row, i)] = std::move(*row.image(f, i, false));
      else set.volumes[stage_name(row, i)] = std::move(*row.volume(f, i, false));
    }
  return set;
}

namespace {
bool in_voxel_grid(const FrameResult& f, const Volume* v) {
  const VoxelGrid& g = f.voxels;
  for (const Volume* member : {&g.radiance, &g.fragments, &g.cas_lo, &g.cas_hi, &g.shading_slack, &g.exact,
                               &g.occupancy_tie, &g.fragment_count_range})
    if (v == member) return true;
  return false;
}
}  // namespace

StageSet stage_set_taking_voxels(FrameResult& f, const VctSettings& s) {
  StageSet set = stage_set_header(f, s);
  for (const StageRow& row : stage_rows())
    for (int i : frame_members(f, row)) {  // every member found before any is moved
      if (row.kind == StageKind::Image) {
        set.images[stage_name(row, i)] = *frame_image(f, row, i);
        continue;
      }
      Volume* v = row.volume(f, i, false);
      // A moved-from Volume keeps its sizes; emptied, the frame says honestly that it has no grid.
      set.volumes[stage_name(row, i)] = in_voxel_grid(f, v) ? std::exchange(*v, Volume()) : *v;
    }
  return set;
}

namespace {
std::string file_stem(const std::string& stage) {
  std::string s = stage;
  std::replace(s.begin(), s.end(), '.', '_');
  return s;
}

// A stage set has no scene: positions preview over the data's own range.
void write_image_stage(RunDir& rd, const std::string& name, const std::string& stem, const Image& img) {
  const auto ref = find_stage(name);
  if (!ref) {
    rd.write_color(stem, img);  // a stage of another renderer's: radiance unless it says otherwise
    return;
  }
  float lo = 1e30f, hi = -1e30f;
  if (ref->row->preview == Preview::Position)
    for (float v : img.data) lo = std::min(lo, v), hi = std::max(hi, v);
  write_stage_image(rd, stem, *ref->row, img, lo, hi > lo ? hi : lo + 1.0f);
}
}  // namespace

void name_stage_files(const std::string& dir, StageSet& set) {
  set.root = dir;
  for (const auto& kv : set.volumes) set.files[kv.first] = file_stem(kv.first) + ".nrrd";
  for (const auto& kv : set.images) set.files[kv.first] = file_stem(kv.first) + ".exr";
}

void write_named_stage_set(const StageSet& set) {
  RunDir rd(set.root);
  nlohmann::json stages = nlohmann::json::object();
  // One task per stage (its data file and preview), volumes first: they are the largest, so the
  // last tasks to start are short ones. Each writes its own files, so the bytes do not depend on
  // the thread count (docs/performance.md, "Where validate's time goes").
  std::vector<std::function<void()>> tasks;
  for (const auto& [name, vol] : set.volumes) {
    const std::string stem = file_stem(name);
    tasks.push_back([&rd, stem, &vol = vol] { rd.write_volume(stem, vol, 1.0f); });
    stages[name] = {{"file", stem + ".nrrd"}, {"kind", "volume"}, {"preview", stem + ".png"}};
  }
  for (const auto& [name, img] : set.images) {
    const std::string stem = file_stem(name);
    tasks.push_back([&rd, name = name, stem, &img = img] { write_image_stage(rd, name, stem, img); });
    stages[name] = {{"file", stem + ".exr"}, {"kind", "image"}, {"preview", stem + ".png"}};
  }
  parallel_tasks(int64_t(tasks.size()), [&](int64_t i) { tasks[size_t(i)](); });
  write_text_atomically(rd.file("vct-stages.json"), stage_set_manifest(set, stages).dump(2) + "\n");
}

void write_stage_set(const std::string& dir, StageSet& set) {
  name_stage_files(dir, set);
  write_named_stage_set(set);
}

nlohmann::json stage_set_manifest(const StageSet& set, const nlohmann::json& stages) {
  nlohmann::json m = {{"format", "vct-stages"}, {"version", 1},          {"backend", set.backend},
                      {"storage", set.storage}, {"reduction", set.reduction}, {"settings", set.settings},
                      {"info", set.info},       {"stages", stages}};
  if (!set.facts.empty()) m["facts"] = set.facts;
  if (!set.conventions.empty()) m["conventions"] = to_json(set.conventions);
  return m;
}

namespace {
// A canonical stage name has one kind (docs/external_format.md, "Stage names"): comparisons and
// --scene look a stage up among the images or the volumes by its name, so an image listed as
// mip.iso.2 or a volume as gbuffer.position would be missed where it is needed (a crash before:
// fuzz/regressions/scene_compare/).
void check_kind_of_name(const std::string& manifest, const std::string& name, const std::string& kind) {
  const auto expected = namespace_kind(name);
  if (!expected) return;
  const bool image = *expected == StageKind::Image;
  if (kind != (image ? "image" : "volume"))
    throw InputError(manifest, "stage '" + name + "' must be " + (image ? "an image" : "a volume") + ", not kind '" +
                                   kind + "' (docs/external_format.md, Stage names)");
}

// A stage with fewer channels than its registry row says would be judged on what it lacks (a
// voxel.radiance with 1 of its 4 channels passed `vct compare`: issue 38).
void check_channels(const std::string& manifest, const std::string& name, const StageSet& set) {
  const auto ref = find_stage(name);
  if (!ref || ref->row->channels <= 0) return;
  const auto image = set.images.find(name);
  const auto volume = set.volumes.find(name);
  const int have = image != set.images.end() ? image->second.channels : volume->second.channels;
  if (have < ref->row->channels)
    throw InputError(manifest, "stage '" + name + "' has " + std::to_string(have) + " channel(s), but it needs " +
                                   std::to_string(ref->row->channels) + " (docs/external_format.md, Stage names)");
}

StageSet read_stage_set_unguarded(const std::string& path) {
  fs::path manifest = fs::is_directory(path) ? fs::path(path) / "vct-stages.json" : fs::path(path);
  if (!fs::exists(manifest)) throw InputError(path, "no vct-stages.json manifest here (docs/external_format.md)");
  // Regular file, size and depth bounded (a manifest 300 000 levels deep overflowed the stack).
  const nlohmann::json m = read_bounded_json_file(manifest.string(), "stage-set manifest");
  if (!m.is_object() || m.value("format", "") != "vct-stages")
    throw InputError(manifest.string(), "\"format\" must be \"vct-stages\"");
  if (!m.contains("stages") || !m["stages"].is_object())
    throw InputError(manifest.string(), "\"stages\" must be an object of stage name -> {file, kind}");
  StageSet set;
  set.root = manifest.parent_path().string();
  set.backend = m.value("backend", "external");
  set.storage = m.value("storage", "rgba32f");
  set.reduction = m.value("reduction", "exact_mean");
  static const std::set<std::string> kStorages = {"rgba8", "rgba16f", "rgba32f"};
  if (!kStorages.count(set.storage)) throw InputError(manifest.string(), "unknown storage '" + set.storage + "'");
  // Either vocabulary (core/reduction_names.h: the settings' "fixed" is the manifest's "fixed_point").
  const auto reduction = reduction_from_name(set.reduction);
  if (!reduction) throw InputError(manifest.string(), "unknown reduction '" + set.reduction + "'");
  set.reduction = manifest_reduction_name(*reduction);
  if (m.contains("settings")) set.settings = m["settings"];
  if (m.contains("info")) set.info = m["info"];
  if (m.contains("facts")) set.facts = m["facts"].get<BackendFacts>();
  if (m.contains("conventions")) set.conventions = read_conventions(manifest.string(), m["conventions"]);
  for (const auto& [name, entry] : m["stages"].items()) {
    if (!entry.is_object() || !entry.contains("file") || !entry["file"].is_string())
      throw InputError(manifest.string(), "stage '" + name + "' needs a \"file\" string");
    const std::string rel = entry["file"].get<std::string>();
    const std::string file = (fs::path(set.root) / rel).string();
    if (!fs::exists(file)) throw InputError(file, "listed for stage '" + name + "' but missing");
    const std::string ext = fs::path(rel).extension().string();
    const std::string kind = entry.value("kind", ext == ".nrrd" ? "volume" : "image");
    if (kind == "volume" || kind == "image") check_kind_of_name(manifest.string(), name, kind);
    if (kind == "volume") {
      set.volumes[name] = read_nrrd(file);
    } else if (kind == "image") {
      set.images[name] = read_image(file);
    } else {
      throw InputError(manifest.string(), "stage '" + name + "' has unknown kind '" + kind + "'");
    }
    check_channels(manifest.string(), name, set);
    set.files[name] = rel;
  }
  return set;
}
}  // namespace

StageSet read_stage_set(const std::string& path) {
  // A manifest field of the wrong JSON type (e.g. "kind": 3) or an unusable file name (too long,
  // ...) is bad input like any other: one InputError, never another exception (found by fuzz/).
  try {
    return read_stage_set_unguarded(path);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, std::string("bad vct-stages.json: ") + e.what());
  } catch (const fs::filesystem_error& e) {
    throw InputError(path, std::string("bad file in vct-stages.json: ") + e.what());
  }
}

bool soft_shadows_of(const StageSet& set) {
  if (!set.settings.is_object()) return false;
  const auto it = set.settings.find("soft_shadows");
  return it != set.settings.end() && it->is_boolean() && it->get<bool>();
}

std::vector<std::string> pipeline_order(const StageSet& a, const StageSet& b) {
  std::set<std::string> names;
  for (const StageSet* s : {&a, &b}) {
    for (const auto& kv : s->images) names.insert(kv.first);
    for (const auto& kv : s->volumes) names.insert(kv.first);
  }
  // Derived stages are judged whenever what they are made of is there.
  namespace st = stage_names;
  if (names.count(st::kVoxelRadiance)) names.insert(st::kVoxelOccupancy);
  if (names.count(st::kVoxelConservative)) names.insert(st::kVoxelHoles);
  for (const std::string& n : std::set<std::string>(names))
    if (const auto ref = find_stage(n); ref && ref->row->index == StageIndex::Frame) names.insert(st::kVoxelEnergy);
  // Registry order; family members by number; then names the registry does not know, sorted.
  // With soft shadows, direct light is traced through the mips: it is judged after them (just
  // before the first cone stage), so a voxel or mip bug is blamed where it is, not on direct.
  const bool soft = soft_shadows_of(a) || soft_shadows_of(b);
  const auto& rows = stage_rows();
  size_t first_cone_row = rows.size();
  for (size_t i = 0; i < rows.size() && first_cone_row == rows.size(); ++i)
    if (rows[i].own_inputs) first_cone_row = i;
  std::vector<std::pair<std::pair<size_t, int>, std::string>> ranked;
  for (const std::string& n : names) {
    const auto ref = find_stage(n);
    if (ref && ref->row->role == StageRole::Auxiliary) continue;  // judged inside other stages
    // Rank 2i + 1 for row i; a moved row takes 2i just before row i; unknown names come last.
    size_t rank = ref ? 2 * size_t(ref->row - rows.data()) + 1 : 2 * rows.size() + 2;
    if (ref && !ref->row->own_inputs && judged_on_own_inputs(*ref->row, soft)) rank = 2 * first_cone_row;
    ranked.push_back({{rank, ref ? ref->index : 0}, n});
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::string> out;
  for (auto& r : ranked) out.push_back(std::move(r.second));
  return out;
}

}  // namespace vct::cmp
