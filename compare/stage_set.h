// A set of named stage outputs (images and volumes) from one renderer: ours (built from a
// FrameResult) or anyone's (read from a vct-stages.json manifest, docs/external_format.md).
// Comparisons work on stage sets only, so an external GPU run is judged exactly like our GL run.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/conventions.h"
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
  // storage "rgba8" | "rgba16f" | "rgba32f"; reduction "exact_mean" | "fixed_point" | "cas_rgba8" |
  // "running_mean".
  std::string storage = "rgba32f", reduction = "exact_mean";
  nlohmann::json settings = nlohmann::json::object();  // free-form, copied from the manifest
  nlohmann::json info = nlohmann::json::object();      // free-form notes
  Conventions conventions;  // declared by the manifest (compare/conventions.h)
  BackendFacts facts;  // typed: what ran, the driver's facts (manifest "facts", backend_facts.h)
  std::string root;  // directory the files live in (empty when built in memory)
  std::map<std::string, std::string> files;  // stage -> file relative to root (PNG preview beside)

  bool has(const std::string& stage) const { return images.count(stage) || volumes.count(stage); }
};

/// Every stage of one frame under its canonical name (docs/external_format.md lists them).
StageSet stage_set_from_frame(const FrameResult& f, const VctSettings& s);

/// Same, moving each stage's image or volume out of `f` instead of copying it (those slots of `f`
/// are left empty; what is no stage, e.g. the mips' base level, stays): the set of a frame that is
/// not read again costs no copy (at grid 256, ~700 MB; docs/performance.md).
StageSet stage_set_from_frame(FrameResult&& f, const VctSettings& s);

/// Same, copying every stage but the voxel grid's (radiance, fragments and whatever else
/// VoxelGrid holds), which it moves: `f` keeps its shadow maps, G-buffer, images, mips and bounce
/// volumes, which the isolated passes read (compare/isolated_stages.h), but not the grid, which
/// none does: at grid 256 that is 20 B per voxel, 320 MiB, less at validate's peak
/// (docs/performance.md, "Validate's memory").
StageSet stage_set_taking_voxels(FrameResult& f, const VctSettings& s);

/// A frame's stage set without its stages: backend, storage, reduction, settings, info, facts.
StageSet stage_set_header(const FrameResult& f, const VctSettings& s);

/// `set` without its images and volumes (every other field copied): a subset is then built
/// without copying the stages it leaves out.
StageSet stage_set_without_stages(const StageSet& set);

/// Writes every stage (EXR / NRRD + PNG previews) and `dir`/vct-stages.json; fills set.root/files.
void write_stage_set(const std::string& dir, StageSet& set);
/// The two halves of write_stage_set: name_stage_files fills set.root/files without writing;
/// write_named_stage_set then writes them, only reading `set` (so others may read it meanwhile).
void name_stage_files(const std::string& dir, StageSet& set);
void write_named_stage_set(const StageSet& set);

/// The vct-stages.json document of `set` whose "stages" entries ({file, kind, preview}) are given.
nlohmann::json stage_set_manifest(const StageSet& set, const nlohmann::json& stages);

/// Reads a directory holding vct-stages.json (or the manifest file itself). Throws InputError
/// naming the file and the problem.
StageSet read_stage_set(const std::string& path);

/// Whether the set's settings say soft shadows were on (free-form settings: anything but a
/// JSON true is off).
bool soft_shadows_of(const StageSet& set);

/// Canonical pipeline order of stage names present in either set (first failing stage = first
/// in this order).
std::vector<std::string> pipeline_order(const StageSet& a, const StageSet& b);

std::string storage_name(VoxelStorage s);
std::string reduction_name(Reduction r);

}  // namespace vct::cmp
