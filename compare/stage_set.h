// A set of named stage outputs (images and volumes) from one renderer: ours (built from a
// FrameResult) or anyone's (read from a vct-stages.json manifest, docs/external_format.md).
// Comparisons work on stage sets only, so an external GPU run is judged exactly like our GL run.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/image.h"
#include "core/settings.h"
#include "core/volume.h"
#include "stages/stage_types.h"

namespace vct::cmp {

struct StageSet {
  std::string backend;                  // "ref", "gl", or whatever the manifest says
  std::map<std::string, Image> images;  // "shadow_map.0", "gbuffer.normal", "image.final", ...
  std::map<std::string, Volume> volumes;  // "voxel.radiance", "mip.iso.1", "mip.posx.1", ...
  // How the voxels were stored and reduced (selects the voxel radiance tolerance model):
  // storage "rgba8" | "rgba16f" | "rgba32f"; reduction "exact_mean" | "fixed_point" | "cas_rgba8".
  std::string storage = "rgba32f", reduction = "exact_mean";
  nlohmann::json settings = nlohmann::json::object();  // free-form, copied from the manifest
  nlohmann::json info = nlohmann::json::object();      // e.g. GL_RENDERER
  std::string root;  // directory the files live in (empty when built in memory)
  std::map<std::string, std::string> files;  // stage -> file relative to root (PNG preview beside)

  bool has(const std::string& stage) const { return images.count(stage) || volumes.count(stage); }
};

/// The FrameResult images and volumes that have a canonical stage name, as (name, member) pairs:
/// the one table both directions use (stage_set_from_frame, frame_from_stage_set). Shadow maps
/// and mips are named by shadow_map_stage / mip_stage. F is FrameResult or const FrameResult.
template <class F>
auto frame_image_slots(F& f) {
  auto& g = f.gbuffer;
  auto& im = f.images;
  using Slot = std::pair<const char*, decltype(&g.coverage)>;
  return std::vector<Slot>{{"gbuffer.coverage", &g.coverage},
                           {"gbuffer.depth", &g.depth},
                           {"gbuffer.position", &g.position},
                           {"gbuffer.normal", &g.normal},
                           {"gbuffer.albedo", &g.albedo},
                           {"gbuffer.material", &g.material},
                           {"gbuffer.specular_color", &g.specular_color},
                           {"gbuffer.emission", &g.emission},
                           {"gbuffer.texture_slack", &g.texture_slack},
                           {"image.direct", &im.direct},
                           {"image.indirect_diffuse", &im.indirect_diffuse},
                           {"image.indirect_specular", &im.indirect_specular},
                           {"image.diffuse_term", &im.diffuse_term},
                           {"image.specular_term", &im.specular_term},
                           {"image.emission", &im.emission},
                           {"image.particles", &im.particles},
                           {"image.soft_shadow", &im.soft_shadow},
                           {"image.final", &im.final_image}};
}

template <class F>
auto frame_volume_slots(F& f) {
  using Slot = std::pair<const char*, decltype(&f.holes)>;
  return std::vector<Slot>{{"voxel.radiance", &f.voxels.radiance},
                           {"voxel.fragments", &f.voxels.fragments},
                           {"voxel.cas_lo", &f.voxels.cas_lo},
                           {"voxel.cas_hi", &f.voxels.cas_hi},
                           {"voxel.conservative", &f.conservative_occupancy},
                           {"voxel.holes", &f.holes}};
}

inline std::string shadow_map_stage(size_t light) { return "shadow_map." + std::to_string(light); }
/// "mip.iso.L" for direction -1, else "mip.<posx|negx|...>.L" (level L >= 1).
inline std::string mip_stage(int direction, int level) {
  return std::string("mip.") + (direction < 0 ? "iso" : kAnisoDirNames[size_t(direction)]) + "." +
         std::to_string(level);
}

/// Every stage of one frame under its canonical name (docs/external_format.md lists them).
StageSet stage_set_from_frame(const FrameResult& f, const VctSettings& s);

/// Writes every stage (EXR / NRRD + PNG previews) and `dir`/vct-stages.json; fills set.root/files.
void write_stage_set(const std::string& dir, StageSet& set);

/// Reads a directory holding vct-stages.json (or the manifest file itself). Throws InputError
/// naming the file and the problem.
StageSet read_stage_set(const std::string& path);

/// Canonical pipeline order of stage names present in either set (first failing stage = first
/// in this order).
std::vector<std::string> pipeline_order(const StageSet& a, const StageSet& b);

std::string storage_name(VoxelStorage s);
std::string reduction_name(Reduction r);

}  // namespace vct::cmp
