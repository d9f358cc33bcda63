// vct metamorphic SCENE [--backend ref|gl]: relations every VCT implementation must satisfy
// whatever its conventions (compare/metamorphic.h, docs/metamorphic.md), judged on one backend
// alone: a whole-voxel translation, a shift inside the volume, three 90-degree turns, doubling the
// light, the white furnace. Writes run.json and the frames it compared (mapped back into the base
// scene's coordinates) into --out; exit 0 pass (or warn) / 1 fail / 2 bad input / 3 no GL.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "compare/metamorphic.h"
#include "core/error.h"
#include "io/run_dir.h"
#include "options.h"
#include "scene/gltf_loader.h"
#include "freedoms/reference_frame.h"
#include "validate_run.h"
#include "verdict_summary.h"

#ifdef VCT_HAVE_GL  // the GL backend is a build option (VCT_BUILD_GL)
#include "gl/gl_context.h"
#include "gl/gl_faults.h"
#include "gl/gl_pipeline.h"
#endif

namespace vct::app {

namespace {

struct MetaFlags {
  std::string backend = "ref";
  GlFlags gl;
  std::vector<std::string> only;
};

// Small by default: the backend renders up to eight frames (docs/metamorphic.md, "Cost").
Settings metamorphic_defaults() {
  Settings s;
  s.vct.width = s.pt.width = 64;
  s.vct.height = s.pt.height = 64;
  s.vct.grid = 32;
  s.vct.shadow_map_size = 256;
  // The GPU's own coverage rule and the deterministic reduction, as vct validate uses them.
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.msaa_samples = 4;
  s.vct.reduction = Reduction::FixedPoint;
  return s;
}

// The backend under test; a GL context is made once and kept for every frame.
cmp::FrameRenderer make_renderer(const MetaFlags& f) {
  if (f.backend == "ref" && !f.gl.fault.empty())
    throw InputError("--gl-fault", "needs --backend gl (the CPU reference has no faults)");
  if (f.backend == "ref")
    return [](const Scene& scene, const Settings& s) { return render_ref_frame(scene, s); };
#ifdef VCT_HAVE_GL
  gl::check_gl_fault(f.gl.fault, "--gl-fault");
  auto ctx = std::make_shared<gl::GlContext>(f.gl.device);  // EnvironmentError (exit 3) without GL
  const std::string fault = f.gl.fault;
  return [ctx, fault](const Scene& scene, const Settings& s) {
    return gl::render_gl_frame(*ctx, scene, s, {"", fault});
  };
#else
  throw EnvironmentError(
      "GL backend not built (no gl/gl_pipeline.h or no GL libraries at configure time)");
#endif
}

void print_relation(const cmp::RelationResult& r) {
  cmp::Report rep;
  rep.stages = r.stages;
  std::printf("%-4s %-16s %s\n", cmp::to_string(r.verdict).c_str(), r.name.c_str(), r.note.c_str());
  if (r.verdict == cmp::Verdict::Fail || r.verdict == cmp::Verdict::Warn)
    print_verdicts(rep, "  " + r.name);
}

void write_outputs(RunDir& run, const cmp::MetamorphicRun& m) {
  cmp::StageSet base = m.base;
  if (!base.images.empty() || !base.volumes.empty()) cmp::write_stage_set(run.file("base"), base);
  for (const cmp::RelationResult& r : m.relations)
    for (const auto& [key, set] : r.sets) {
      if (key == "base") continue;  // the base frame (or the part of it compared) is in base/
      cmp::StageSet copy = set;
      cmp::write_stage_set(run.file(r.name + "/" + key), copy);
    }
}

// Returns the exit code: a failing relation is 1, pass and warn are 0.
int run_metamorphic_command(const std::string& scene_path, const CommonOptions& common,
                            const MetaFlags& flags) {
  const Settings settings = resolve_settings(common, metamorphic_defaults());
  cmp::check_relation_names(flags.only);
  const Scene scene = load_scene(scene_path, common.scene_load);
  if (flags.backend == "gl") check_gl_backend_accepts(scene, settings, flags.gl);  // before the run directory
  const cmp::FrameRenderer render = make_renderer(flags);  // bad fault names and no GL fail here
  RunDir run(common.out.empty() ? default_out_dir("metamorphic", scene_path) : common.out,
             RunRole::Run);
  Stopwatch sw;
  const cmp::MetamorphicRun m = cmp::run_metamorphic(scene, settings, render, flags.only);
  run.json()["command"] = "metamorphic";
  run.json()["backend"] = flags.backend;
  if (!flags.gl.fault.empty()) run.json()["gl_fault"] = flags.gl.fault;
  run.json()["settings"] = settings;
  run.json()["environment"] = environment_info();
  run.json()["scene"] = {
      {"source", scene.source},
      {"triangles", scene.triangle_count()},
      {"lattice_volume",
       {{"origin", {m.scene.volume.origin.x, m.scene.volume.origin.y, m.scene.volume.origin.z}},
        {"size", m.scene.volume.size}}}};
  nlohmann::json relations = nlohmann::json::array();
  for (const cmp::RelationResult& r : m.relations) relations.push_back(cmp::to_json(r));
  run.json()["relations"] = relations;
  run.json()["overall"] = cmp::to_string(m.overall());
  run.json()["timings_ms"]["total"] = sw.ms();
  write_outputs(run, m);
  run.finish();
  std::printf("vct metamorphic: %s backend on %s (%dx%d, grid %d, voxel %.4g) -> %s\n",
              flags.backend.c_str(), scene.source.c_str(), settings.vct.width, settings.vct.height,
              settings.vct.grid, double(m.scene.volume.size) / settings.vct.grid,
              run.path().c_str());
  for (const cmp::RelationResult& r : m.relations) print_relation(r);
  std::printf("overall: %s (%.1f s)\n", cmp::to_string(m.overall()).c_str(), sw.ms() / 1000.0);
  return m.overall() == cmp::Verdict::Fail ? kExitFailed : kExitOk;
}

}  // namespace

void register_metamorphic(CLI::App& app, int& exit_code) {
  static std::string scene_storage;  // live as long as the process (CLI11 binds by reference)
  static CommonOptions common_storage;
  static MetaFlags flags_storage;
  auto* scene_path = &scene_storage;
  auto* common = &common_storage;
  auto* flags = &flags_storage;
  CLI::App* cmd = app.add_subcommand("metamorphic",
                                     "Relations any VCT must satisfy (translation, turns, "
                                     "linearity, furnace), judged on one backend");
  cmd->add_option("scene", *scene_path, "glTF 2.0 file (.gltf or .glb); none = the built-in scene");
  add_common_flags(cmd, *common);
  add_scene_access_flag(cmd, common->scene_load);
  add_image_flags(cmd, *common);
  add_grid_flag(cmd, *common);
  cmd->add_option("--backend", flags->backend, "ref (CPU reference) or gl (OpenGL 4.5)")
      ->check(CLI::IsMember({"ref", "gl"}));
  add_gl_flags(cmd, flags->gl);
  cmd->add_option("--only", flags->only,
                  "Relations to run (default all): " + cmp::metamorphic_names())
      ->delimiter(',');
  cmd->callback([scene_path, common, flags, &exit_code]() {
    exit_code = run_metamorphic_command(*scene_path, *common, *flags);
  });
}

}  // namespace vct::app
