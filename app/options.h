// Flags shared by the subcommands (README.md) and how they become Settings.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/settings.h"
#include "scene/gltf_loader.h"

namespace vct::app {

struct CommonOptions {
  std::string out;     // --out DIR
  std::string config;  // --config FILE.json
  int threads = 0;     // --threads N
  std::optional<int> width, height, grid, spp;
  std::vector<std::string> sets;  // --set KEY=VALUE ... (any row of core/settings_table.h)
  SceneLoadOptions scene_load;    // --allow-outside-scene-dir
};

/// --out, --config, --threads, --set.
void add_common_flags(CLI::App* cmd, CommonOptions& o);
/// --allow-outside-scene-dir, on every command that loads a scene (docs/scenes.md, "File access").
void add_scene_access_flag(CLI::App* cmd, SceneLoadOptions& o);
/// --width, --height (image size for VCT and the path tracer).
void add_image_flags(CLI::App* cmd, CommonOptions& o);
/// --grid N.
void add_grid_flag(CLI::App* cmd, CommonOptions& o);
/// --spp N.
void add_spp_flag(CLI::App* cmd, CommonOptions& o);

/// How the GL backend runs, apart from the shared VCT settings (gl/gl_pipeline.h GlOptions).
struct GlFlags {
  std::string device;  // --gl-device N|NAME|surfaceless ("" = first hardware device, else surfaceless)
  std::string fault;   // --gl-fault NAME (gl/gl_faults.h); "" = none
};
/// --gl-device, --gl-fault.
void add_gl_flags(CLI::App* cmd, GlFlags& g);

/// `base` <- --config file <- --set <- flags; validated (InputError on a bad value); threads applied.
Settings resolve_settings(const CommonOptions& o, const Settings& base = Settings());

/// Default run directory when --out is not given: runs/<command>-<scene stem>.
std::string default_out_dir(const std::string& command, const std::string& scene_path);

}  // namespace vct::app
