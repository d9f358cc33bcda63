// vct validate [SCENE]: ref + gl + pt, every comparison, run directory, report (docs/compare.md).
// Exit: 0 when every GPU stage passes (warnings included), 1 when one fails or the GL frame
// errors, 2 bad input, 3 only with --require-gl and no GL context; without --require-gl a
// missing GL context is reported ("gl: unavailable") and the ref/pt parts still run.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "commands.h"
#include "attribution_outputs.h"
#include "compare/judge.h"
#include "compare/bias.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "core/parallel.h"
#include "core/parallel_tasks.h"
#include "io/image_io.h"
#include "io/run_dir.h"
#include "io/atomic_file.h"
#include "options.h"
#include "phase_progress.h"
#include "phase_times.h"
#include "pt/progress.h"
#include "stages/explain.h"
#include "stages/scene_footprint.h"
#include "stages/stage_registry.h"
#include "stages/stage_registry_text.h"
#include "scene/gltf_loader.h"
#include "scene/exposure.h"
#include "camera_aspect.h"
#include "scene_warnings.h"
#include "validate_checks.h"
#include "validate_run.h"
#include "verdict_summary.h"

namespace vct::app {

namespace {

struct ValidateOptions {
  std::string scene;
  CommonOptions common;
  std::vector<std::string> sweeps;
  bool require_gl = false;
  bool no_report = false;
  bool attribute = false;  // --attribute: the error budget section (docs/attribution.md)
  int attribute_rays = 16;
  // FLIP is a perceptual side metric no verdict uses, and HDR-FLIP costs seconds per map: opt-in
  // (docs/performance.md, "Where validate's time goes").
  std::string flip = "none";
  GlFlags gl;
  // Sweep rows as cluster tasks (docs/cluster.md): the --sweep rows only, against the path tracer
  // and GL availability of an earlier validate run of the same scene and settings.
  std::string pt_from;     // --pt-from RUN_DIR
  std::string sweep_rows;  // --sweep-rows FILE.json
  bool check_input = false;  // --check-input: scene, settings and sweep values only
};

// True when a --set names `key` (with or without its "vct." prefix).
bool set_names(const CommonOptions& o, const std::string& key) {
  for (const std::string& kv : o.sets) {
    const std::string k = kv.substr(0, kv.find('='));
    if (k == key || k == "vct." + key) return true;
  }
  return false;
}

Settings resolve(const CommonOptions& o) {
  Settings s = resolve_settings(o, validate_defaults());
  // A conservative raster is judged against the exact voxelizer (docs/compare.md, "Conservative
  // voxelization"), not validate's default sample rule, unless a --set asks otherwise.
  if (s.vct.conservative_raster != ConservativeRaster::Off && !set_names(o, "voxelizer"))
    s.vct.voxelizer = Voxelizer::Conservative;
  s.pt.width = s.vct.width;  // bias needs the same pixels on both sides
  s.pt.height = s.vct.height;
  validate_settings(s);
  return s;
}

void record_frame(RunDir& run, const BackendRun& b, const std::string& name) {
  run.json()["backends"][name] = {{"status", b.status}, {"ms", b.ms}};
  if (!b.ok()) return;
  for (const auto& [stage, ms] : b.frame->timings_ms) run.add_timing(name, stage, ms);
  for (const auto& [k, v] : b.frame->info) run.json()["backends"][name]["info"][k] = v;
  run.json()["backends"][name]["facts"] = b.frame->facts;
  if (!b.frame->multibounce_energy.empty()) run.json()["multibounce_energy"][name] = b.frame->multibounce_energy;
}

// One pixel's cones for the walkthrough (the centre pixel: it sees the back wall and the floor).
void write_explanation(RunDir& run, const Scene& scene, const BackendRun& ref, const Settings& s) {
  if (!ref.ok()) return;
  const int x = s.vct.width / 2, y = s.vct.height * 3 / 4;
  const PixelExplanation e = explain_pixel(scene, *ref.frame, s.vct, x, y);
  RunDir ed(run.file("explain"));
  write_text_atomically(ed.file("explain.json"), e.json.dump(1) + "\n");
  write_png_linear(ed.file("explain.png"), e.picture, 0.0f, 1.0f);
}

// Whether voxel.radiance was re-judged on GL's own shadow maps or bounce input (its isolated
// verdict keeps the end-to-end one in extra): then that phase's prediction is the run's.
bool radiance_rejudged(const std::optional<cmp::Report>& report) {
  if (!report) return false;
  for (const cmp::StageVerdict& v : report->stages)
    if (v.stage == stage_names::kVoxelRadiance) return v.extra.contains("end_to_end");
  return false;
}

// Predicted (by phase; `predicted` the phases that ran) and measured peak, as `vct render` writes its own.
nlohmann::json validate_memory_json(const ValidateMemoryEstimate& e, uint64_t predicted) {
  return {{"predicted_bytes", predicted},
          {"predicted", format_bytes(predicted)},
          {"predicted_during_gl_bytes", e.during_gl()},
          {"predicted_during_ref_bytes", e.during_ref()},
          {"predicted_during_checks_bytes", e.during_checks()},
          {"predicted_with_reinjection_bytes", e.with_reinjection()},
          {"predicted_scene_bytes", e.ref.scene},
          {"peak_rss_bytes", peak_rss_bytes()},
          {"peak_rss", format_bytes(peak_rss_bytes())}};
}

nlohmann::json bias_json(const std::vector<cmp::BiasComponent>& bias) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& b : bias) j.push_back(cmp::to_json(b));
  return j;
}

// A sweep of exposure or exposure_ev100 re-exposes the scene as loaded for each value (docs/scenes.md,
// "Light units and exposure").
bool sweep_exposes(const std::string& key) { return key == "exposure" || key == "exposure_ev100"; }

// The base run's path tracer AOVs at another exposure: every AOV is radiance, linear in the sources,
// so it scales by the ratio of the scales and its variance by the ratio's square.
PtRun rescaled(const PtRun& pt, double ratio) {
  PtRun out = pt;
  for (auto& [name, img] : out.aovs) {
    const bool variance = name.size() > 4 && name.compare(name.size() - 4, 4, "_var") == 0;
    const float k = float(variance ? ratio * ratio : ratio);
    for (float& v : img.data) v *= k;
  }
  return out;
}

// One sweep: re-render ref (and gl) per value, bias against the PT of that light model (and exposure).
// `unexposed` is the scene as loaded, `scene` as the base settings expose it.
nlohmann::json run_sweep(const Scene& unexposed, const Scene& base_scene, const Settings& base, const std::string& spec,
                         const PtRun& pt, bool gl_available, const GlFlags& gl_flags, PhaseProgress& progress) {
  const auto [key, values] = parse_sweep(spec);
  nlohmann::json rows = nlohmann::json::array();
  for (const std::string& value : values) {
    const Settings s = apply_sweep_value(base, key, value);
    Scene exposed;
    if (sweep_exposes(key)) {
      exposed = unexposed;
      expose_scene(exposed, s.vct);
    }
    const Scene& scene = sweep_exposes(key) ? exposed : base_scene;
    std::printf("  sweep %s=%s ...\n", key.c_str(), value.c_str());
    std::fflush(stdout);
    progress.begin("sweep " + key + "=" + value + (gl_available ? ": gl, ref, compare, bias" : ": ref, bias"));
    nlohmann::json row = {{"key", key}, {"value", value}};
    // GL first: the reference then emulates the coverage rule the driver actually ran.
    const BackendRun gl = gl_available ? run_gl_backend(scene, s, gl_flags) : BackendRun{};
    const BackendRun ref = run_ref_backend(scene, settings_as_run_by_gl(s, gl), sample_positions_of(gl));
    row["ref_status"] = ref.status;
    row["ref_ms"] = ref.ms;
    if (ref.ok()) row["ref_timings_ms"] = ref.frame->timings_ms;
    row["exposure"] = exposure_json(scene.exposure);
    PtRun pt_here;
    const PtRun* p = &pt;
    if (key == "light_model" && s.pt.light_model != base.pt.light_model) p = &(pt_here = run_pt_backend(scene, s));
    if (sweep_exposes(key) && scene.exposure.scale != base_scene.exposure.scale && pt.ok())
      p = &(pt_here = rescaled(pt, double(scene.exposure.scale) / double(base_scene.exposure.scale)));
    if (ref.ok() && p->ok()) {
      const auto bias = cmp::measure_bias(cmp::stage_set_from_frame(*ref.frame, s.vct), p->aovs);
      row["bias"] = bias_json(bias);
    }
    if (gl_available) {
      row["gl_status"] = gl.status;
      row["gl_ms"] = gl.ms;
      if (gl.ok()) {
        row["gl_timings_ms"] = gl.frame->timings_ms;
        if (ref.ok()) {
          const cmp::StageSet gl_set = cmp::stage_set_from_frame(*gl.frame, s.vct);
          const cmp::StageSet ref_set = cmp::stage_set_from_frame(*ref.frame, s.vct);
          const cmp::Report rep = cmp::judge(ref_set, gl_set, {&scene, &*gl.frame, &s.vct});
          row["gl_verdict"] = cmp::to_string(rep.overall());
          row["gl_first_failing"] = rep.first_failing();
        }
      }
    }
    progress.end();
    rows.push_back(row);
  }
  return {{"key", key}, {"values", values}, {"rows", rows}};
}

// The base run's path tracer AOVs (pt/<aov>.exr, float32: the same floats run_sweep reads in
// memory) and whether its GL frame ran, so a sweep row computed later is the row validate makes.
PtRun load_base_pt(const std::string& base_dir, bool& gl_available) {
  namespace fs = std::filesystem;
  const std::string json_path = (fs::path(base_dir) / "run.json").string();
  std::ifstream in(json_path);
  if (!in) throw InputError(json_path, "cannot open: --pt-from needs a validate run directory");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(json_path, std::string("not a validate run.json: ") + e.what());
  }
  if (j.value("command", "") != "validate" || !j.contains("backends"))
    throw InputError(json_path, "not the run.json of a finished vct validate");
  gl_available = j["backends"].value("gl", nlohmann::json::object()).value("status", "") == "ok";
  PtRun pt;
  pt.status = j["backends"].value("pt", nlohmann::json::object()).value("status", "missing");
  pt.spp = j["backends"].value("pt", nlohmann::json::object()).value("spp", 0);
  if (pt.status != "ok") return pt;
  for (int a = 0; a < pt::kAovCount; ++a)
    for (const std::string suffix : {"", "_var"}) {
      const std::string name = pt::kAovNames[a] + suffix;
      const std::string f = (fs::path(base_dir) / "pt" / (name + ".exr")).string();
      if (!fs::exists(f)) throw InputError(f, "missing: --pt-from needs the path tracer images of a validate run");
      pt.aovs[name] = read_image(f);
    }
  return pt;
}

// Bad specs and values (GL's refusals too) fail before any rendering.
void check_sweeps(const Scene& scene, const Settings& s, const ValidateOptions& o) {
  for (const auto& sw : o.sweeps) {
    const auto [key, values] = parse_sweep(sw);
    for (const auto& v : values) check_gl_backend_accepts(scene, apply_sweep_value(s, key, v), o.gl);
  }
  check_gl_backend_accepts(scene, s, o.gl);
}

// --check-input: what validate would refuse, refused without rendering (a cluster client asks
// this before it sends any task).
int check_input_only(const ValidateOptions& o) {
  const Settings s = resolve(o.common);
  Scene scene = load_scene_and_warn(o.scene, o.common.scene_load);  // the camera may be fitted below
  check_sweeps(scene, s, o);
  // What the run would need, as its first line says (docs/performance.md, "Validate's memory").
  const ValidateMemoryEstimate e =
      estimate_validate_memory(fit_image_to_camera_and_warn(s, scene, o.common), scene_footprint(scene));
  const auto mib = [](uint64_t b) { return double(b) / double(1 << 20); };
  std::printf("memory predicted %.0f MiB (while GL renders %.0f, while the reference renders %.0f, while the stage "
              "sets are compared %.0f; %.0f MiB if voxel.radiance is re-judged on GL's own shadow maps)\n",
              mib(e.total()), mib(e.during_gl()), mib(e.during_ref()), mib(e.during_checks()), mib(e.with_reinjection()));
  warn_if_memory_short(e, "vct validate");
  return kExitOk;
}

// --sweep-rows: the rows of every --sweep, written as validate's run.json "sweeps" array.
int run_sweep_rows(const ValidateOptions& o) {
  if (o.pt_from.empty()) throw InputError("--sweep-rows", "needs --pt-from RUN_DIR (the base validate run)");
  if (o.sweeps.empty()) throw InputError("--sweep-rows", "needs at least one --sweep KEY=V1,...");
  const Settings s = resolve(o.common);
  const Scene unexposed = load_scene_and_warn(o.scene, o.common.scene_load);
  Scene scene = unexposed;
  expose_scene(scene, s.vct);  // as the base run exposed it
  check_sweeps(scene, s, o);
  bool gl_available = false;
  const PtRun pt = load_base_pt(o.pt_from, gl_available);
  PhaseProgress progress(false, "validate", 0);
  nlohmann::json sweeps = nlohmann::json::array();
  for (const auto& spec : o.sweeps)
    sweeps.push_back(run_sweep(unexposed, scene, s, spec, pt, gl_available, o.gl, progress));
  write_text_atomically(o.sweep_rows, sweeps.dump(1) + "\n");
  return kExitOk;
}

// The error budget on the reference's own frame (docs/attribution.md): attribution.json and its
// pictures in the run directory, named in run.json for the report. Informational: a budget that
// does not add up is printed, it does not change validate's exit code.
void write_validate_attribution(RunDir& run, const Scene& scene, const Settings& s, const FrameResult& frame,
                                const ValidateOptions& o) {
  attr::AttributionOptions opt;
  opt.rays_per_pixel = o.attribute_rays;
  const attr::Attribution a = attr::attribute_frame(scene, s, frame, opt);
  nlohmann::json doc;
  doc["scene"] = scene.source;
  doc["rays_per_pixel"] = o.attribute_rays;
  doc["components"] = write_attribution(run, a, frame.gbuffer.coverage);
  doc["sums_to_totals"] = a.sums_to_totals();
  write_text_atomically(run.file("attribution.json"), doc.dump(2) + "\n");
  run.json()["attribution"] = "attribution.json";
  // One line per component for the report's first screen (vct_report/glance.py): the largest term.
  for (const attr::ComponentBudget& b : a.components) {
    const attr::Term* top = &b.terms.front();
    for (const attr::Term& t : b.terms)
      if (std::abs(t.value.mean) > std::abs(top->value.mean)) top = &t;
    char line[160];
    std::snprintf(line, sizeof line, "largest term %s %+.3g of total %+.3g", top->name.c_str(), top->value.mean,
                  b.total.value.mean);
    run.json()["error_budget"][b.component] = line;
  }
  std::printf("error budget (vct attribute), mean luminance +- SE:\n");
  for (const attr::ComponentBudget& b : a.components) print_budget(b, "  ");
}

int run(const ValidateOptions& o) {
  if (o.check_input) return check_input_only(o);
  if (!o.sweep_rows.empty()) return run_sweep_rows(o);
  PhaseTimes phases;
  const Settings resolved = resolve(o.common);
  Scene loaded = phases.time("load scene", [&] { return load_scene_and_warn(o.scene, o.common.scene_load); });
  const Scene unexposed = loaded;  // an exposure sweep re-exposes it per value
  expose_scene(loaded, resolved.vct);
  const Settings s = fit_image_to_camera_and_warn(resolved, loaded, o.common);
  const Scene scene = std::move(loaded);
  const std::string out = o.common.out.empty() ? default_out_dir("validate", o.scene) : o.common.out;
  // Phases: gl, ref, pt, stage sets + comparison + bias, each sweep value, report.
  PhaseProgress progress(pt::ProgressBar::stderr_is_terminal(), "validate", 4 + (o.no_report ? 0 : 1));
  check_sweeps(scene, s, o);  // a refused GL frame or sweep value leaves no run directory
  for (const auto& sw : o.sweeps) progress.add_phases(int(parse_sweep(sw).second.size()));
  RunDir run(out, RunRole::Run);  // locked; INCOMPLETE until finish()
  run.json()["command"] = "validate";
  run.json()["scene"] = {{"source", scene.source},
                         {"triangles", scene.triangle_count()},
                         {"lights", scene.lights.size()},
                         {"warnings", scene.stats.warnings}};
  run.json()["exposure"] = exposure_json(scene.exposure);
  run.json()["settings"] = s;
  run.json()["report_options"] = {{"flip", o.flip}};  // a rebuilt report computes the same FLIP maps
  run.json()["environment"] = environment_info();
  // The report names, orders and explains stages from this table (ref/stages/stage_registry.h).
  run.json()["stage_registry"] = stage_registry_json();
  // Predicted with the loaded scene before anything renders; a run that will not fit is warned
  // about now, not found out in the allocator (docs/performance.md, "Validate's memory").
  const SceneFootprint footprint = scene_footprint(scene);
  const ValidateMemoryEstimate predicted = estimate_validate_memory(s, footprint);
  std::printf("vct validate: %s  %dx%d  grid %d  spp %d  threads %d  memory predicted %s (%s if voxel.radiance is "
              "re-judged on GL's own shadow maps)  -> %s\n",
              scene.source.c_str(), s.vct.width, s.vct.height, s.vct.grid, s.pt.spp, thread_count(),
              format_bytes(predicted.total()).c_str(), format_bytes(predicted.with_reinjection()).c_str(), out.c_str());
  std::fflush(stdout);
  warn_if_memory_short(predicted, "vct validate");

  // GL first: the reference then emulates the coverage rule the driver actually ran.
  progress.begin("GL frame (" + std::to_string(s.vct.width) + "x" + std::to_string(s.vct.height) + ", grid " +
                 std::to_string(s.vct.grid) + ")");
  BackendRun gl = phases.time("render gl", [&] { return run_gl_backend(scene, s, o.gl); }, true);
  progress.end();
  record_frame(run, gl, "gl");
  std::printf("  gl   %-12s %8.1f s  %s\n", gl.status.substr(0, 60).c_str(), gl.ms / 1000,
              gl.ok() ? gl.frame->facts.renderer.c_str() : "");
  std::fflush(stdout);
  const Settings ref_settings = settings_as_run_by_gl(s, gl);
  if (ref_settings.vct.msaa_samples != s.vct.msaa_samples) {
    std::printf("  note: GL ran %d MSAA samples (asked %d); the reference emulates %d\n",
                ref_settings.vct.msaa_samples, s.vct.msaa_samples, ref_settings.vct.msaa_samples);
    run.json()["settings_effective"] = ref_settings;
  }
  progress.begin("CPU reference frame");
  BackendRun ref = phases.time("render ref", [&] { return run_ref_backend(scene, ref_settings, sample_positions_of(gl)); }, true);
  progress.end();
  record_frame(run, ref, "ref");
  std::printf("  ref  %-12s %8.1f s\n", ref.status.c_str(), ref.ms / 1000);
  std::fflush(stdout);
  progress.begin("path tracer, " + std::to_string(s.pt.spp) + " spp");
  const PtRun pt = phases.time("render pt", [&] { return run_pt_backend(scene, s, progress.enabled()); }, true);
  progress.end();
  run.json()["backends"]["pt"] = {{"status", pt.status}, {"ms", pt.ms}, {"spp", pt.spp}};
  std::printf("  pt   %-12s %8.1f s  %d spp\n", pt.status.c_str(), pt.ms / 1000, pt.spp);
  run.save();

  phases.time("explain one pixel", [&] { write_explanation(run, scene, ref, s); });
  progress.begin("stage sets, GL vs CPU reference, bias against the path tracer");
  // The error budget reads the reference's frame after the checks; otherwise they consume it.
  CheckResults checks = run_checks(run, scene, s, ref, gl, pt, phases, o.attribute);
  progress.end();

  int exit_code = kExitOk;
  if (checks.report) {
    const cmp::Report& rep = *checks.report;
    run.json()["verdicts"] = cmp::to_json(rep);
    print_verdicts(rep, "GPU (gl) vs CPU reference");
    if (rep.overall() == cmp::Verdict::Fail) exit_code = kExitFailed;
  } else {
    const std::string why = !gl.ok() ? "gl " + gl.status : "ref " + ref.status;
    run.json()["verdicts"] = {{"overall", "missing"}, {"first_failing", ""}, {"note", why}, {"stages", nlohmann::json::array()}};
    std::printf("GPU vs CPU: not compared (%s)\n", why.c_str());
    if (gl.status.rfind("error", 0) == 0) exit_code = kExitFailed;
  }
  if (ref.ok() && pt.ok()) {
    run.json()["bias"] = {{"ref", bias_json(checks.bias_ref)}};
    if (gl.ok()) run.json()["bias"]["gl"] = bias_json(checks.bias_gl);
    print_bias(checks.bias_ref);
  }
  run.save();
  if (o.attribute && ref.ok())
    phases.time("attribution (error budget)", [&] { write_validate_attribution(run, scene, ref_settings, *ref.frame, o); });
  if (!o.sweeps.empty()) {
    nlohmann::json sweeps = nlohmann::json::array();
    for (const auto& spec : o.sweeps)
      phases.time("sweep " + spec, [&] { sweeps.push_back(run_sweep(unexposed, scene, s, spec, pt, gl.ok(), o.gl, progress)); });
    run.json()["sweeps"] = sweeps;
    run.save();
  }
  if (o.require_gl && !gl.ok() && gl.status.rfind("error", 0) != 0) exit_code = kExitNoEnvironment;
  run.json()["exit_code"] = exit_code;
  const uint64_t predicted_run = radiance_rejudged(checks.report) ? predicted.with_reinjection() : predicted.total();
  run.json()["memory"] = validate_memory_json(predicted, predicted_run);  // the report's Python is not counted
  run.json()["memory"]["predicted_fragments"] = fragment_count(footprint, s.vct.grid);  // Steiner's count
  run.json()["phases"] = phases.to_json();  // the report shows the phases before it (its own come after)
  run.save();
  std::string index, why;
  if (!o.no_report) {
    progress.begin("HTML report");
    Stopwatch report_sw;
    const double report_cpu0 = process_cpu_ms();
    index = make_report(out, why, o.flip);
    add_report_parts(phases, (std::filesystem::path(out) / "report" / "part_times.json").string(), report_sw.ms(),
                     process_cpu_ms() - report_cpu0);
    run.json()["phases"] = phases.to_json();
    progress.end();
  }
  run.finish();  // everything is written; the report is rebuilt from these files alone
  std::fputs(phases.table().c_str(), stdout);
  std::printf("memory: predicted %s, peak RSS %s (predicted / peak %.2f)\n", format_bytes(predicted_run).c_str(),
              format_bytes(peak_rss_bytes()).c_str(), double(predicted_run) / double(std::max<uint64_t>(peak_rss_bytes(), 1)));
  if (!o.no_report) {
    if (index.empty()) std::printf("report: not written: %s\n", why.c_str());
    else std::printf("%s\n", index.c_str());
  }
  return exit_code;
}

}  // namespace

void register_validate(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* cmd = app.add_subcommand("validate", "ref + gl + pt, every comparison, run directory and HTML report");
  cmd->add_option("scene", o->scene, "glTF scene (default: the built-in Cornell box)");
  add_common_flags(cmd, o->common);
  add_scene_access_flag(cmd, o->common.scene_load);
  add_image_flags(cmd, o->common);
  add_grid_flag(cmd, o->common);
  add_spp_flag(cmd, o->common);
  add_gl_flags(cmd, o->gl);
  cmd->add_option("--sweep", o->sweeps,
                  "KEY=V1,V2,... re-render per value, bias and time per setting (grid, cones, aperture, quality, "
                  "bounces, light_model or any vct.* key); repeatable");
  cmd->add_flag("--require-gl", o->require_gl, "Exit 3 when no GL context is available (default: report and go on)");
  cmd->add_flag("--no-report", o->no_report, "Skip the HTML report");
  cmd->add_flag("--attribute", o->attribute,
                "Add the error budget per component (vct attribute) to the run and the report");
  cmd->add_option("--attribute-rays", o->attribute_rays, "Rays per pixel of the budget's gathering rungs")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--flip", o->flip,
                  "FLIP maps in the report (opt-in; no verdict uses FLIP): none (default), full (the full image of "
                  "each backend) or all (every component; HDR-FLIP costs seconds per map)")
      ->check(CLI::IsMember({"full", "all", "none"}));
  cmd->add_option("--pt-from", o->pt_from, "With --sweep-rows: the validate run whose path tracer the rows use");
  cmd->add_option("--sweep-rows", o->sweep_rows,
                  "Compute only the --sweep rows into FILE.json (a cluster task, docs/cluster.md)");
  cmd->add_flag("--check-input", o->check_input, "Only check the scene, settings and --sweep values (exit 0 or 2)");
  cmd->callback([o, &exit_code]() { exit_code = run(*o); });
}

}  // namespace vct::app
