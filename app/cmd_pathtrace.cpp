// vct pathtrace SCENE --spp N: the Embree ground truth. Writes pt_full, pt_direct, pt_emission,
// pt_indirect_diffuse, pt_indirect_specular (+ _var) as EXR/PNG and run.json. Resumes from the
// checkpoint in --out when it matches the scene and settings; a higher --spp refines it.
// Ctrl-C stops after the current pass with a checkpoint (exit 4, interrupt.h); rerun the command to resume.
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>

#include "commands.h"
#include "core/error.h"
#include "interrupt.h"
#include "options.h"
#include "pt/pathtrace_run.h"
#include "pt/progress.h"
#include "scene/gltf_loader.h"
#include "scene_warnings.h"

namespace vct::app {

namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_interrupt(int) { g_stop = 1; }

struct PtFlags {
  std::string scene;
  std::optional<int> max_depth;
  std::optional<std::string> light_model;
  bool quiet = false;
};

int run_pathtrace_command(const CommonOptions& common, const PtFlags& f) {
  Settings s = resolve_settings(common);
  if (f.max_depth) s.pt.max_depth = *f.max_depth;
  if (f.light_model) s.pt.light_model = *f.light_model == "seed" ? LightModel::Seed : LightModel::Gltf;
  validate_settings(s);
  const Scene scene = load_scene_and_warn(f.scene, common.scene_load);

  pt::PathtraceRunOptions o;
  o.out_dir = common.out.empty() ? default_out_dir("pathtrace", f.scene) : common.out;
  o.progress = !f.quiet && pt::ProgressBar::stderr_is_terminal();
  o.stop_requested = [] { return g_stop != 0; };
  g_stop = 0;
  auto old_int = std::signal(SIGINT, on_interrupt);
  auto old_term = std::signal(SIGTERM, on_interrupt);
  pt::PathtraceRunResult r;
  try {
    r = pt::run_pathtrace(scene, s, o);
  } catch (...) {
    std::signal(SIGINT, old_int);
    std::signal(SIGTERM, old_term);
    throw;
  }
  std::signal(SIGINT, old_int);
  std::signal(SIGTERM, old_term);

  const double rate = r.render_seconds > 0.0 ? double(r.rays.total()) / r.render_seconds : 0.0;
  std::printf("pathtrace: %u spp", r.spp);
  if (r.resumed_from > 0) std::printf(" (resumed from %u)", r.resumed_from);
  std::printf(", %.2f s, %.2f Mrays/s -> %s\n", r.render_seconds, rate * 1e-6, o.out_dir.c_str());
  if (!r.completed) {
    std::fprintf(stderr, "vct pathtrace: interrupted at %u of %d spp; checkpoint saved, rerun to resume\n", r.spp,
                 s.pt.spp);
    return kExitInterrupted;
  }
  return kExitOk;
}

}  // namespace

void register_pathtrace(CLI::App& app, int& exit_code) {
  static CommonOptions common_storage;  // live as long as the process (CLI11 binds by reference);
  static PtFlags flags_storage;         // static, not new, so LeakSanitizer sees no leak
  auto* common = &common_storage;
  auto* flags = &flags_storage;
  CLI::App* cmd = app.add_subcommand(
      "pathtrace", "Path-traced ground truth with AOVs (resumes from a checkpoint in --out; no SCENE = built-in)");
  cmd->add_option("scene", flags->scene, "glTF 2.0 file (.gltf or .glb); empty = built-in default scene");
  add_common_flags(cmd, *common);
  add_scene_access_flag(cmd, common->scene_load);
  add_image_flags(cmd, *common);
  add_spp_flag(cmd, *common);
  cmd->add_option("--max-depth", flags->max_depth, "Maximum number of bounces (1 = direct light only)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--light-model", flags->light_model, "Spot falloff: gltf (KHR_lights_punctual) or seed")
      ->check(CLI::IsMember({"gltf", "seed"}));
  cmd->add_flag("--quiet", flags->quiet, "No progress bar even on a terminal");
  cmd->callback([common, flags, &exit_code]() { exit_code = run_pathtrace_command(*common, *flags); });
}

}  // namespace vct::app
