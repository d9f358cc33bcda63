// vct bench [SCENE]: per-stage times of the CPU reference and the GL build side by side (median
// of --repeat frames) with CPU/GL ratios, and the path tracer's rays/s against raw Embree
// rtcIntersect1 on the same scene. Defaults: built-in scene, 128^3 grid, 512x512 (the settings'
// defaults). --out DIR writes DIR/bench.json atomically
// (a run directory: locked, INCOMPLETE until done). Prints; exit code 0 unless input is bad.
#include <cstdio>
#include <memory>
#include <optional>
#include <filesystem>
#include <string>

#include "bench_run.h"
#include "commands.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "io/atomic_file.h"
#include "io/run_dir.h"
#include "options.h"
#include "scene/gltf_loader.h"
#include "scene_warnings.h"

namespace vct::app {

namespace {

struct BenchFlags {
  std::string scene;
  CommonOptions common;
  BenchOptions bench;
  bool no_gl = false, no_pt = false, no_validate = false;
  std::optional<int> validate_spp, validate_grid;
};

void run(const BenchFlags& f) {
  const Settings settings = resolve_settings(f.common);
  check_memory_budget(settings);
  const Scene scene = load_scene_and_warn(f.scene, f.common.scene_load, settings.vct);
  BenchOptions o = f.bench;
  o.gl = !f.no_gl;
  o.pt = !f.no_pt;
  o.validate = !f.no_validate;
  o.scene_path = f.scene;
  // validate keeps its own defaults (256^2, 64^3, 64 spp) unless bench was given sizes explicitly.
  if (f.common.width) o.validate_args += " --width " + std::to_string(*f.common.width);
  if (f.common.height) o.validate_args += " --height " + std::to_string(*f.common.height);
  if (f.validate_grid) o.validate_args += " --grid " + std::to_string(*f.validate_grid);  // issue 37: 256
  else if (f.common.grid) o.validate_args += " --grid " + std::to_string(*f.common.grid);
  if (f.validate_spp) o.validate_args += " --spp " + std::to_string(*f.validate_spp);
  // --out is a run directory (ref/io/run_dir.h): locked for the whole measurement, so a second
  // bench into it is refused at once; INCOMPLETE until bench.json is written.
  std::unique_ptr<RunDir> run;
  if (!f.common.out.empty()) {
    run = std::make_unique<RunDir>(f.common.out, RunRole::Run);
    run->json()["command"] = "bench";
    run->json()["environment"] = environment_info();
  }
  const nlohmann::json result = run_bench(scene, settings, o);
  std::fputs(format_bench(result).c_str(), stdout);
  if (run) {
    const std::string path = run->file("bench.json");
    write_text_atomically(path, result.dump(1) + "\n");
    run->json()["bench"] = "bench.json";
    run->finish();
    std::printf("\nwrote %s\n", path.c_str());
  }
}

}  // namespace

void register_bench(CLI::App& app, int& exit_code) {
  static BenchFlags storage;  // lives as long as the process (CLI11 binds by reference)
  auto* f = &storage;
  CLI::App* cmd = app.add_subcommand("bench", "Stage times CPU ref vs GL (ratios), path tracer vs raw Embree");
  cmd->add_option("--scene,scene", f->scene, "glTF 2.0 file (default: built-in scene)");
  add_common_flags(cmd, f->common);
  add_scene_access_flag(cmd, f->common.scene_load);
  add_image_flags(cmd, f->common);
  add_grid_flag(cmd, f->common);
  cmd->add_option("--repeat", f->bench.repeat, "Frames per backend (median reported)")->check(CLI::Range(1, 100));
  cmd->add_option("--pt-spp", f->bench.pt_spp, "Path tracer passes to time")->check(CLI::Range(1, 4096));
  cmd->add_option("--raw-rays", f->bench.raw_rays, "Random rays for the raw Embree rate")->check(CLI::Range(1000, 100000000));
  cmd->add_flag("--no-gl", f->no_gl, "Measure the CPU reference only");
  cmd->add_flag("--no-pt", f->no_pt, "Skip the path tracer and raw Embree measurement");
  cmd->add_option("--validate-spp", f->validate_spp, "Path tracer samples of the timed validate run (default: its 64)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--validate-grid", f->validate_grid,
                  "Grid of the timed validate run (default: --grid if given, else validate's 64); 256 prints "
                  "docs/performance.md's \"validate non-render / renders at grid 256\"")
      ->check(CLI::IsMember({16, 32, 64, 128, 256, 512}));
  cmd->add_flag("--no-validate", f->no_validate, "Skip the timed `vct validate` run (its defaults, report included)");
  cmd->callback([f, &exit_code]() {
    run(*f);
    exit_code = kExitOk;
  });
}

}  // namespace vct::app
