// vct pathtrace SCENE --spp N: the Embree ground truth. Writes pt_full, pt_direct, pt_emission,
// pt_indirect_diffuse, pt_indirect_specular (+ _var) as EXR/PNG and run.json. Resumes from the
// checkpoint in --out when it matches the scene and settings; a higher --spp refines it.
// Ctrl-C stops after the current pass with a checkpoint (exit 4, interrupt.h); rerun the command to resume.
// Cluster tasks (docs/cluster.md): --sample-range A:B --partial FILE renders samples A..B-1 into a
// partial-sums file; --merge DIR adds DIR's partials in sample order into the run directory;
// --job-key prints the hashes those files carry (the client checks reused and returned files).
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
#include "camera_aspect.h"
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
  std::string sample_range;  // "A:B": one cluster task
  std::string partial;       // its partial-sums file
  std::string merge;         // directory of partial-sums files to merge
  bool job_key = false;
};

std::pair<uint32_t, uint32_t> parse_sample_range(const std::string& text) {
  const size_t colon = text.find(':');
  try {
    if (colon != std::string::npos && text.find_first_not_of("0123456789:") == std::string::npos) {
      const unsigned long a = std::stoul(text.substr(0, colon)), b = std::stoul(text.substr(colon + 1));
      if (a < b && b <= 0x7fffffffUL) return {uint32_t(a), uint32_t(b)};
    }
  } catch (const std::exception&) {
  }
  throw InputError("--sample-range", "expected A:B with 0 <= A < B (sample indices), got '" + text + "'");
}

int run_cluster_part(const Scene& scene, const Settings& s, const CommonOptions& common, const PtFlags& f) {
  if (f.job_key) {
    const pt::CheckpointKey k = pt::checkpoint_key(scene, s);
    std::printf("{\"scene_hash\": %llu, \"settings_hash\": %llu, \"width\": %d, \"height\": %d}\n",
                (unsigned long long)k.scene_hash, (unsigned long long)k.settings_hash, s.pt.width, s.pt.height);
    return kExitOk;
  }
  if (!f.sample_range.empty()) {
    if (f.partial.empty()) throw InputError("--sample-range", "needs --partial FILE for the partial sums");
    const auto [first, end] = parse_sample_range(f.sample_range);
    const pt::PartialSums p = pt::run_sample_range(scene, s, first, end, f.partial,
                                                   !f.quiet && pt::ProgressBar::stderr_is_terminal());
    std::printf("pathtrace: samples %u..%u, %llu rays -> %s\n", first, end, (unsigned long long)p.rays.total(),
                f.partial.c_str());
    return kExitOk;
  }
  pt::PathtraceRunOptions o;
  o.out_dir = common.out.empty() ? default_out_dir("pathtrace", f.scene) : common.out;
  const pt::PathtraceRunResult r = pt::merge_sample_ranges(scene, s, f.merge, o);
  std::printf("pathtrace: merged %u spp from %s -> %s\n", r.spp, f.merge.c_str(), o.out_dir.c_str());
  return kExitOk;
}

int run_pathtrace_command(const CommonOptions& common, const PtFlags& f) {
  Settings s = resolve_settings(common);
  if (f.max_depth) s.pt.max_depth = *f.max_depth;
  if (f.light_model) s.pt.light_model = *f.light_model == "seed" ? LightModel::Seed : LightModel::Gltf;
  validate_settings(s);
  Scene loaded = load_scene_and_warn(f.scene, common.scene_load, s.vct);
  s = fit_image_to_camera_and_warn(s, loaded, common);
  const Scene scene = std::move(loaded);
  if (f.job_key || !f.sample_range.empty() || !f.merge.empty()) return run_cluster_part(scene, s, common, f);

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
  auto* range = cmd->add_option("--sample-range", flags->sample_range,
                                "A:B: render samples A..B-1 only into --partial FILE (a cluster task, docs/cluster.md)");
  cmd->add_option("--partial", flags->partial, "Partial-sums file that --sample-range writes")->needs(range);
  auto* merge = cmd->add_option("--merge", flags->merge,
                                "Merge DIR/*.ptpart (samples 0..spp-1) in sample order into --out, as one run writes it")
                    ->excludes(range);
  cmd->add_flag("--job-key", flags->job_key, "Print the scene and settings hashes of partial-sums files (JSON)")
      ->excludes(range)
      ->excludes(merge);
  cmd->callback([common, flags, &exit_code]() { exit_code = run_pathtrace_command(*common, *flags); });
}

}  // namespace vct::app
