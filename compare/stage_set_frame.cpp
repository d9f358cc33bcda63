#include "compare/stage_set_frame.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "compare/partial_gbuffer.h"
#include "core/error.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {

int mip_levels(int n) {  // GL: levels down to 1^3
  int levels = 1;
  for (; n > 1; n /= 2) ++levels;
  return levels;
}

int level_size(int n, int level) { return std::max(1, n >> level); }

bool is_volume_stage(const std::string& stage) { return namespace_kind(stage) == StageKind::Volume; }

std::string manifest_of(const StageSet& set) {
  return set.root.empty() ? "test stage set" : (std::filesystem::path(set.root) / "vct-stages.json").string();
}

std::string file_of(const StageSet& set, const std::string& stage) {
  const auto it = set.files.find(stage);
  return it == set.files.end() || set.root.empty() ? stage : (std::filesystem::path(set.root) / it->second).string();
}

bool wants_particles(const Scene& scene, const VctSettings& s) { return s.particles && !scene.emitters.empty(); }

// "info" is free-form (docs/external_format.md): an energy list that is not all numbers stays text.
bool all_numbers(const nlohmann::json& v) {
  return v.is_array() && std::all_of(v.begin(), v.end(), [](const nlohmann::json& e) { return e.is_number(); });
}

// The marcher indexes pixels and voxels with a fixed channel count: extra channels (RGBA files
// for RGB stages) are dropped, missing ones are an error.
Image first_channels(const Image& in, int channels, const std::string& file) {
  if (in.channels == channels) return in;
  if (in.channels < channels)
    throw InputError(file, std::to_string(in.channels) + " channel(s), --scene needs " + std::to_string(channels));
  Image out(in.width, in.height, channels);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) std::copy_n(in.pixel(x, y), channels, out.pixel(x, y));
  return out;
}

Volume rgba_volume(const Volume& in, int n, const std::string& file) {
  if (in.nx != n || in.ny != n || in.nz != n)
    throw InputError(file, "size " + std::to_string(in.nx) + "x" + std::to_string(in.ny) + "x" + std::to_string(in.nz) +
                               ", the settings' grid gives " + std::to_string(n) + "^3 at this level");
  if (in.channels < 4) throw InputError(file, std::to_string(in.channels) + " channel(s), --scene needs RGBA");
  if (in.channels == 4) return in;
  Volume out(n, n, n, 4);
  for (size_t i = 0; i < in.voxel_count(); ++i) std::copy_n(&in.data[i * size_t(in.channels)], 4, &out.data[i * 4]);
  return out;
}

// Every stage the set holds goes to its FrameResult slot (shadow maps without their matrices:
// the re-trace does not read them).
void fill_everything(const StageSet& set, FrameResult& f) {
  for (const auto& [name, img] : set.images) {
    const auto ref = find_stage(name);
    if (ref && ref->row->image) *ref->row->image(f, ref->index, true) = img;
  }
  for (const auto& [name, vol] : set.volumes) {
    const auto ref = find_stage(name);
    // Single volumes and the multibounce frames (mips are filled by level below).
    if (ref && ref->row->volume && (ref->row->index == StageIndex::None || ref->row->index == StageIndex::Frame))
      *ref->row->volume(f, ref->index, true) = vol;
  }
  for (const auto& [k, v] : set.info.items()) {
    if (k == "multibounce_energy" && all_numbers(v)) f.multibounce_energy = v.get<std::vector<double>>();
    else f.info[k] = v.is_string() ? v.get<std::string>() : v.dump();
  }
  f.backend = set.backend;
  f.facts = set.facts;
  f.voxels.n = f.voxels.radiance.nx;
}

// The mip chain the marcher samples: iso[0] = voxel.radiance, then the levels the settings
// select. Isotropic iso levels beyond the chain a set holds are not guessed.
void fill_mips(const StageSet& set, const VctSettings& s, FrameResult& f) {
  const int levels = mip_levels(s.grid);
  f.mips.iso = {rgba_volume(f.voxels.radiance, s.grid, file_of(set, stage_names::kVoxelRadiance))};
  f.voxels.radiance = f.mips.iso[0];
  for (int l = 1; l < levels; ++l) {
    const std::string name = stage_name(mip_row(-1), l);
    if (!set.volumes.count(name)) break;
    f.mips.iso.push_back(rgba_volume(set.volumes.at(name), level_size(s.grid, l), file_of(set, name)));
  }
  if (!s.anisotropic) return;
  for (int d = 0; d < 6; ++d)
    for (int l = 1; l < levels; ++l) {
      const std::string name = stage_name(mip_row(d), l);
      f.mips.aniso[size_t(d)].push_back(rgba_volume(set.volumes.at(name), level_size(s.grid, l), file_of(set, name)));
    }
}

// Each input is looked up by kind (an image listed as a volume would leave its slot empty while
// its pixels are indexed); read_stage_set already refuses such sets, in-memory ones are checked here.
void require_stages(const StageSet& set, const Scene& scene, const VctSettings& s) {
  for (const std::string& stage : cone_input_stages(scene, s))
    if (!(is_volume_stage(stage) ? set.volumes.count(stage) : set.images.count(stage)))
      throw InputError(manifest_of(set), "stage '" + stage +
                                             "' is missing; --scene re-traces the cone stages from the test's own "
                                             "G-buffer (or gbuffer.depth + gbuffer.normal, the rest from the "
                                             "reference), direct light and mips (docs/external_format.md)");
}

// The images the marcher and the composite index pixel by pixel: the G-buffer, direct light and
// particles (whenever present: the composite adds them) must be width x height.
void check_input_images(const StageSet& set, const VctSettings& s, FrameResult& f) {
  for (const StageRow& row : stage_rows()) {
    if (row.cone_input == ConeInput::No || row.kind != StageKind::Image || !frame_image(f, row)) continue;
    const std::string name = row.name;
    Image& slot = *row.image(f, 0, false);
    if (slot.width != s.width || slot.height != s.height)
      throw InputError(file_of(set, name), "size " + std::to_string(slot.width) + "x" + std::to_string(slot.height) +
                                               ", the settings give " + std::to_string(s.width) + "x" +
                                               std::to_string(s.height));
    slot = first_channels(slot, row.channels, file_of(set, name));
  }
}

// Shadow maps name their light: shadow_map.N must be a spot or directional light of the scene,
// shadow_map_cube.(N x 6 + face) a point light's (the GL and ref dumps hold one or the other).
void check_light_maps(const StageSet& set, const Scene& scene) {
  size_t maps = 0;
  for (const auto& [name, img] : set.images) {
    const auto ref = find_stage(name);
    if (!ref || (ref->row->index != StageIndex::Light && ref->row->index != StageIndex::CubeFace)) continue;
    if (ref->row->role != StageRole::Judged) continue;  // a reference's range beside its map
    const bool cube = ref->row->index == StageIndex::CubeFace;
    const size_t light = size_t(cube ? ref->index / 6 : ref->index);
    const bool fits = light < scene.lights.size() && scene.lights[light].is_point() == cube;
    if (!fits)
      throw InputError(manifest_of(set), "stage '" + name + "' needs " + (cube ? "a point" : "a spot or directional") +
                                             " light " + std::to_string(light) + " but " + scene.source + " has " +
                                             std::to_string(scene.lights.size()) + " light(s)" +
                                             (light < scene.lights.size()
                                                  ? std::string(", that one ") + light_kind_name(scene.lights[light].kind)
                                                  : std::string()) +
                                             ": wrong --scene?");
    if (!cube || ref->index % 6 == 0) ++maps;
  }
  // With maps at all, every light has its own (a set from a scene with more lights is refused too).
  if (maps > 0 && maps != scene.lights.size())
    throw InputError(manifest_of(set), std::to_string(maps) + " lights' shadow maps but " + scene.source + " has " +
                                           std::to_string(scene.lights.size()) + " light(s): wrong --scene?");
}

// A wrong --scene would re-trace from the wrong camera and lights and fail every cone stage for
// no fault of the test; say so instead. Positions must land on their own pixel (within 1 px:
// float error and sub-pixel jitter stay far below) for all but 1 % of the covered pixels.
void check_scene_matches(const StageSet& set, const Scene& scene, const GBuffer& g) {
  check_light_maps(set, scene);
  const int w = g.coverage.width, h = g.coverage.height;
  const mat4 view_proj = scene.camera.projection(float(w) / float(h)) * scene.camera.view();
  size_t covered = 0, off = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.5f) continue;
      ++covered;
      const vec4 c = view_proj * vec4(g.position.rgb(x, y), 1.0f);
      const float px = (c.x / c.w * 0.5f + 0.5f) * float(w), py = (0.5f - c.y / c.w * 0.5f) * float(h);
      if (!(c.w > 0.0f && std::abs(px - (float(x) + 0.5f)) <= 1.0f && std::abs(py - (float(y) + 0.5f)) <= 1.0f)) ++off;
    }
  if (off * 100 > covered)
    throw InputError(file_of(set, stage_names::kGbufferPosition),
                     std::to_string(off) + " of " + std::to_string(covered) +
                         " covered pixels do not project to their pixel through the camera of " + scene.source +
                         ": wrong --scene, or images not flipped to row 0 = top?");
}

}  // namespace

std::vector<std::string> cone_input_stages(const Scene& scene, const VctSettings& s) {
  std::vector<std::string> stages;
  const int levels = mip_levels(s.grid);
  for (const StageRow& row : stage_rows()) {
    switch (row.cone_input) {
      case ConeInput::No: break;
      case ConeInput::Always: stages.push_back(row.name); break;
      case ConeInput::UnlessSoftShadows:
        if (!s.soft_shadows) stages.push_back(row.name);
        break;
      case ConeInput::WithParticles:
        if (wants_particles(scene, s)) stages.push_back(row.name);
        break;
      case ConeInput::ChosenMips:
        if ((aniso_direction(row) >= 0) == s.anisotropic)
          for (int l = 1; l < levels; ++l) stages.push_back(stage_name(row, l));
        break;
    }
  }
  return stages;
}

FrameResult frame_from_stage_set(const StageSet& given, const Scene& scene, const VctSettings& s,
                                 const StageSet* reference) {
  const bool partial = is_partial_gbuffer(given);
  const StageSet set = partial ? complete_partial_gbuffer(given, scene, reference, cone_input_stages(scene, s)) : given;
  require_stages(set, scene, s);
  FrameResult f;
  fill_everything(set, f);
  check_input_images(set, s, f);
  fill_mips(set, s, f);
  check_scene_matches(set, scene, f.gbuffer);
  // Positions reconstructed from depth are not the engine's own floats: how far those may lie
  // decides which cones may start on the other side of a volume face (the start-face tie).
  if (partial) f.gbuffer.position_margin = position_margin_from_depth(scene, f.gbuffer);
  return f;
}

}  // namespace vct::cmp
