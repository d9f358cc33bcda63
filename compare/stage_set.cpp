#include "stage_set.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/nrrd.h"
#include "io/run_dir.h"

namespace vct::cmp {

namespace fs = std::filesystem;

std::string storage_name(VoxelStorage s) { return s == VoxelStorage::Rgba8 ? "rgba8" : "rgba16f"; }
std::string reduction_name(Reduction r) {
  switch (r) {
    case Reduction::ExactMean: return "exact_mean";
    case Reduction::FixedPoint: return "fixed_point";
    case Reduction::CasRgba8: return "cas_rgba8";
  }
  return "exact_mean";
}

namespace {
void put(std::map<std::string, Image>& m, const std::string& k, const Image& img) {
  if (!img.empty()) m[k] = img;
}
void put(std::map<std::string, Volume>& m, const std::string& k, const Volume& v) {
  if (!v.data.empty()) m[k] = v;
}
}  // namespace

StageSet stage_set_from_frame(const FrameResult& f, const VctSettings& s) {
  StageSet set;
  set.backend = f.backend;
  set.storage = storage_name(s.storage);
  set.reduction = reduction_name(s.reduction);
  set.settings = s;
  for (const auto& [k, v] : f.info) set.info[k] = v;
  set.facts = f.facts;
  // A backend may substitute a reduction (GL has no exact float mean: its facts say so).
  if (!f.facts.reduction.empty()) set.reduction = f.facts.reduction;
  for (size_t i = 0; i < f.shadow_maps.size(); ++i) put(set.images, "shadow_map." + std::to_string(i), f.shadow_maps[i].depth);
  const GBuffer& g = f.gbuffer;
  put(set.images, "gbuffer.coverage", g.coverage);
  put(set.images, "gbuffer.depth", g.depth);
  put(set.images, "gbuffer.position", g.position);
  put(set.images, "gbuffer.normal", g.normal);
  put(set.images, "gbuffer.albedo", g.albedo);
  put(set.images, "gbuffer.material", g.material);
  put(set.images, "gbuffer.specular_color", g.specular_color);
  put(set.images, "gbuffer.emission", g.emission);
  put(set.images, "gbuffer.texture_slack", g.texture_slack);
  put(set.volumes, "voxel.radiance", f.voxels.radiance);
  put(set.volumes, "voxel.fragments", f.voxels.fragments);
  put(set.volumes, "voxel.cas_lo", f.voxels.cas_lo);
  put(set.volumes, "voxel.cas_hi", f.voxels.cas_hi);
  put(set.volumes, "voxel.conservative", f.conservative_occupancy);
  put(set.volumes, "voxel.holes", f.holes);
  for (size_t l = 1; l < f.mips.iso.size(); ++l) put(set.volumes, "mip.iso." + std::to_string(l), f.mips.iso[l]);
  for (int d = 0; d < 6; ++d)
    for (size_t l = 0; l < f.mips.aniso[size_t(d)].size(); ++l)
      put(set.volumes, std::string("mip.") + kAnisoDirNames[size_t(d)] + "." + std::to_string(l + 1), f.mips.aniso[size_t(d)][l]);
  const FrameImages& im = f.images;
  put(set.images, "image.direct", im.direct);
  put(set.images, "image.indirect_diffuse", im.indirect_diffuse);
  put(set.images, "image.indirect_specular", im.indirect_specular);
  put(set.images, "image.diffuse_term", im.diffuse_term);
  put(set.images, "image.specular_term", im.specular_term);
  put(set.images, "image.emission", im.emission);
  put(set.images, "image.particles", im.particles);
  put(set.images, "image.soft_shadow", im.soft_shadow);
  put(set.images, "image.final", im.final_image);
  if (!f.multibounce_energy.empty()) set.info["multibounce_energy"] = f.multibounce_energy;
  return set;
}

namespace {
std::string file_stem(const std::string& stage) {
  std::string s = stage;
  std::replace(s.begin(), s.end(), '.', '_');
  return s;
}
// Data images (depth, coverage, masks) get a linear preview; radiance a tone-mapped one.
bool is_data_image(const std::string& stage) {
  return stage.rfind("shadow_map", 0) == 0 || stage == "gbuffer.depth" || stage == "gbuffer.coverage" ||
         stage == "gbuffer.material" || stage == "gbuffer.texture_slack" || stage == "image.soft_shadow";
}
}  // namespace

void write_stage_set(const std::string& dir, StageSet& set) {
  RunDir rd(dir);
  set.root = dir;
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [name, img] : set.images) {
    const std::string stem = file_stem(name);
    if (name == "gbuffer.normal") {
      // Normals previewed as (n+1)/2.
      write_exr(rd.file(stem + ".exr"), img);
      Image p = img;
      for (float& v : p.data) v = v * 0.5f + 0.5f;
      write_png_linear(rd.file(stem + ".png"), p, 0.0f, 1.0f);
    } else if (name == "gbuffer.position") {
      write_exr(rd.file(stem + ".exr"), img);
      float lo = 1e30f, hi = -1e30f;
      for (float v : img.data) lo = std::min(lo, v), hi = std::max(hi, v);
      write_png_linear(rd.file(stem + ".png"), img, lo, hi > lo ? hi : lo + 1.0f);
    } else if (is_data_image(name)) {
      float lo = 0.0f, hi = 1.0f;
      if (name.rfind("shadow_map", 0) == 0 || name == "gbuffer.depth") {
        lo = 1.0f;  // depth previews stretch the used range (perspective depth crowds near 1)
        for (float v : img.data) if (v < 1.0f) lo = std::min(lo, v);
        if (lo >= 1.0f) lo = 0.0f;
      }
      rd.write_data(stem, img, lo, 1.0f);
      (void)hi;
    } else {
      rd.write_color(stem, img);
    }
    set.files[name] = stem + ".exr";
    stages[name] = {{"file", stem + ".exr"}, {"kind", "image"}, {"preview", stem + ".png"}};
  }
  for (const auto& [name, vol] : set.volumes) {
    const std::string stem = file_stem(name);
    rd.write_volume(stem, vol, 1.0f);
    set.files[name] = stem + ".nrrd";
    stages[name] = {{"file", stem + ".nrrd"}, {"kind", "volume"}, {"preview", stem + ".png"}};
  }
  nlohmann::json m = {{"format", "vct-stages"}, {"version", 1},          {"backend", set.backend},
                      {"storage", set.storage}, {"reduction", set.reduction}, {"settings", set.settings},
                      {"info", set.info},       {"stages", stages}};
  if (!set.facts.empty()) m["facts"] = set.facts;
  write_text_atomically(rd.file("vct-stages.json"), m.dump(2) + "\n");
}

namespace {
// A canonical stage name has one kind (docs/external_format.md, "Stage names"): comparisons and
// --scene look a stage up among the images or the volumes by its name, so an image listed as
// mip.iso.2 or a volume as gbuffer.position would be missed where it is needed (a crash before:
// fuzz/regressions/scene_compare/).
void check_kind_of_name(const std::string& manifest, const std::string& name, const std::string& kind) {
  auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
  const bool image = starts("shadow_map.") || starts("gbuffer.") || starts("image.");
  const bool volume = starts("voxel.") || starts("mip.");
  if ((image && kind != "image") || (volume && kind != "volume"))
    throw InputError(manifest, "stage '" + name + "' must be " + (image ? "an image" : "a volume") + ", not kind '" +
                                   kind + "' (docs/external_format.md, Stage names)");
}

StageSet read_stage_set_unguarded(const std::string& path) {
  fs::path manifest = fs::is_directory(path) ? fs::path(path) / "vct-stages.json" : fs::path(path);
  if (!fs::exists(manifest)) throw InputError(path, "no vct-stages.json manifest here (docs/external_format.md)");
  nlohmann::json m;
  try {
    std::ifstream in(manifest);
    m = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw InputError(manifest.string(), std::string("not valid JSON: ") + e.what());
  }
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
  static const std::set<std::string> kReductions = {"exact_mean", "fixed_point", "cas_rgba8"};
  if (!kStorages.count(set.storage)) throw InputError(manifest.string(), "unknown storage '" + set.storage + "'");
  if (!kReductions.count(set.reduction)) throw InputError(manifest.string(), "unknown reduction '" + set.reduction + "'");
  if (m.contains("settings")) set.settings = m["settings"];
  if (m.contains("info")) set.info = m["info"];
  if (m.contains("facts")) set.facts = m["facts"].get<BackendFacts>();
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

std::vector<std::string> pipeline_order(const StageSet& a, const StageSet& b) {
  // Prefixes in pipeline order; within a prefix, names sort with numbers numerically.
  static const std::vector<std::string> kOrder = {
      "shadow_map.",      "gbuffer.coverage", "gbuffer.depth",  "gbuffer.position",       "gbuffer.normal",
      "gbuffer.albedo",   "gbuffer.material", "gbuffer.specular_color", "gbuffer.emission", "image.direct",
      "voxel.occupancy",  "voxel.radiance",   "voxel.holes",    "mip.iso.",               "mip.posx.",
      "mip.negx.",        "mip.posy.",        "mip.negy.",      "mip.posz.",              "mip.negz.",
      "image.soft_shadow", "image.indirect_diffuse", "image.indirect_specular", "image.diffuse_term",
      "image.specular_term", "image.emission", "image.particles", "image.final"};
  std::set<std::string> names;
  for (const StageSet* s : {&a, &b}) {
    for (const auto& kv : s->images) names.insert(kv.first);
    for (const auto& kv : s->volumes) names.insert(kv.first);
  }
  // Reference inputs that are not stages of their own are judged inside other stages.
  for (const char* aux : {"voxel.fragments", "voxel.cas_lo", "voxel.cas_hi", "voxel.conservative",
                          "gbuffer.texture_slack"})
    names.erase(aux);
  if (names.count("voxel.radiance")) names.insert("voxel.occupancy");
  if (a.volumes.count("voxel.conservative") || b.volumes.count("voxel.conservative")) names.insert("voxel.holes");
  auto rank = [](const std::string& n) -> std::pair<size_t, long> {
    for (size_t i = 0; i < kOrder.size(); ++i) {
      const std::string& p = kOrder[i];
      if (p.back() == '.' ? n.rfind(p, 0) == 0 : n == p) {
        long num = 0;
        if (p.back() == '.') try { num = std::stol(n.substr(p.size())); } catch (...) { num = 0; }
        return {i, num};
      }
    }
    return {kOrder.size(), 0};
  };
  std::vector<std::string> out(names.begin(), names.end());
  std::stable_sort(out.begin(), out.end(), [&](const std::string& x, const std::string& y) {
    const auto rx = rank(x), ry = rank(y);
    return rx != ry ? rx < ry : x < y;
  });
  return out;
}

}  // namespace vct::cmp
