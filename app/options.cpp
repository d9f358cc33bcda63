#include "options.h"

#include <filesystem>

#include "core/error.h"
#include "core/parallel.h"
#include "core/settings_table.h"

namespace vct::app {

void add_common_flags(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("--out", o.out, "Run directory to write (created if missing)");
  cmd->add_option("--config", o.config, "Settings JSON file (keys as in run.json's \"settings\")");
  cmd->add_option("--threads", o.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--set", o.sets, "KEY=VALUE: any setting (vct.KEY or pt.KEY; bare keys are vct.*); 'vct settings' lists them")
      ->take_all();
}

void add_scene_access_flag(CLI::App* cmd, SceneLoadOptions& o) {
  cmd->add_flag("--allow-outside-scene-dir", o.allow_outside_scene_dir,
                "Let the scene's URIs name files outside its folder (absolute paths, '..', file:, symbolic links)");
}

void add_image_flags(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("--width", o.width, "Image width in pixels")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", o.height, "Image height in pixels")->check(CLI::Range(1, 16384));
}

void add_grid_flag(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("--grid", o.grid, "Voxel grid resolution N (N^3 voxels, power of two, 16..512)");
}

void add_spp_flag(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("--spp", o.spp, "Path tracer samples per pixel")->check(CLI::Range(1, 1 << 24));
}

Settings resolve_settings(const CommonOptions& o, const Settings& base) {
  Settings s = base;
  if (!o.config.empty()) s = load_settings_file(o.config, s);
  for (const std::string& kv : o.sets) {
    const size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set", "expected KEY=VALUE, got '" + kv + "'");
    s = with_setting(s, kv.substr(0, eq), kv.substr(eq + 1), "--set");
  }
  if (o.width) s.vct.width = s.pt.width = *o.width;
  if (o.height) s.vct.height = s.pt.height = *o.height;
  if (o.grid) s.vct.grid = *o.grid;
  if (o.spp) s.pt.spp = *o.spp;
  if (o.threads) s.threads = o.threads;
  validate_settings(s);
  set_thread_count(s.threads);
  return s;
}

std::string default_out_dir(const std::string& command, const std::string& scene_path) {
  const std::string stem = scene_path.empty() ? "default" : std::filesystem::path(scene_path).stem().string();
  return "runs/" + command + "-" + stem;
}

void add_gl_flags(CLI::App* cmd, GlFlags& g) {
  cmd->add_option("--gl-device", g.device,
                  "GL: EGL device index, a name (substring of its renderer or extensions) or 'surfaceless' "
                  "(default: first hardware device, else Mesa surfaceless; `vct info --gl` lists them)");
  cmd->add_option("--gl-fault", g.fault, "GL: compile a deliberate fault in (testing the oracle; docs/gl_backend.md)");
}


}  // namespace vct::app
