// vct compare A B: A is the reference, B the test. Each is a stage-set directory (holding
// vct-stages.json, ours or an external renderer's: docs/external_format.md), a validate run
// directory (A's ref/ against B's gl/), an image (.exr .png .hdr ...) or a volume (.nrrd).
// With --scene, stage sets' cone-traced stages are judged on B's own inputs, as vct validate does.
// --out DIR is a run directory (locked, INCOMPLETE until done: ref/io/run_dir.h).
// Exit: 0 pass or warn, 1 fail, 2 bad input.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "commands.h"
#include "compare_scene.h"
#include "options.h"
#include "compare/judge.h"
#include "compare/metrics.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "compare/tolerance.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/nrrd.h"
#include "io/run_dir.h"
#include "stages/stage_registry.h"
#include "verdict_summary.h"

namespace vct::app {

namespace fs = std::filesystem;

namespace {

struct CompareArgs {
  std::string a, b, out, stage = stage_names::kImageFinal;
  std::string scene, config;  // --scene, --config: isolated judgement of cone stages
  double abs = 0.0, rel = 0.0;
  size_t worst = 10;
  std::vector<int> explain;  // --explain X,Y[,Z]
  SceneLoadOptions scene_load;  // --allow-outside-scene-dir, with --scene
};

// A run directory of `vct validate` holds ref/ and gl/; a stage directory holds the manifest.
std::string stage_dir(const std::string& path, const char* side) {
  if (fs::exists(fs::path(path) / "vct-stages.json") || fs::is_regular_file(path)) return path;
  const fs::path sub = fs::path(path) / side;
  if (fs::exists(sub / "vct-stages.json")) return sub.string();
  throw InputError(path, std::string("no vct-stages.json here nor in ") + side + "/ (docs/external_format.md)");
}

bool is_volume(const std::string& p) { return fs::path(p).extension() == ".nrrd"; }

// --out is a run directory like every command's (ref/io/run_dir.h): locked while compare writes
// it, INCOMPLETE until compare.json is written. Opened only once every input has been read, so
// bad input leaves no directory behind. A run.json already there (compare --out into a validate
// run) keeps its sections.
std::unique_ptr<RunDir> open_out_run(const CompareArgs& a) {
  if (a.out.empty()) return nullptr;
  auto run = std::make_unique<RunDir>(a.out, RunRole::Run);
  // The masks are this comparison's alone: a mask left by an earlier comparison into the same --out
  // (another stage, another pair) would read as one of this verdict's.
  fs::remove_all(fs::path(a.out) / "masks");
  run->keep_existing_json();
  if (!run->json().contains("command")) run->json()["command"] = "compare";
  return run;
}

// --explain: per stage holding that element, the rule that admitted it and its numbers.
void print_explained(const cmp::Report& rep) {
  for (const cmp::StageVerdict& v : rep.stages) {
    const auto e = v.extra.find("explain");
    if (e == v.extra.end()) continue;
    std::printf("  %-26s at %s: %s (%s), reference %s, test %s, |d| %.4g, bound %.4g (docs/compare.md \"%s\")\n",
                v.stage.c_str(), (*e)["at"].dump().c_str(), (*e)["rule"].get<std::string>().c_str(),
                (*e)["kind"].get<std::string>().c_str(), (*e)["reference"].dump().c_str(), (*e)["test"].dump().c_str(),
                (*e)["error"].get<double>(), (*e)["bound"].get<double>(), (*e)["derived_in"].get<std::string>().c_str());
  }
}

int finish(const cmp::Report& rep, const CompareArgs& a, RunDir* run, const std::string& title,
           const nlohmann::json& fields = nlohmann::json::object()) {
  print_verdicts(rep, title);
  if (!a.explain.empty()) print_explained(rep);
  if (run) {
    nlohmann::json j = {{"reference", a.a}, {"test", a.b}, {"verdicts", cmp::to_json(rep)}};
    j.update(fields);
    write_text_atomically(run->file("compare.json"), j.dump(2) + "\n");
    run->json()["compare"] = {{"reference", a.a}, {"test", a.b}, {"overall", cmp::to_string(rep.overall())},
                              {"file", "compare.json"}};
    run->finish();
  }
  return rep.overall() == cmp::Verdict::Fail ? kExitFailed : kExitOk;
}

cmp::CompareOptions compare_options(const CompareArgs& a) {
  return {a.worst, a.out.empty() ? "" : a.out + "/masks", "masks/", a.explain};
}


bool has_cone_stage(const cmp::Report& rep, bool soft_shadows) {
  for (const cmp::StageVerdict& v : rep.stages)
    if (cmp::is_cone_traced(v.stage, soft_shadows)) return true;
  return false;
}

// Every input of the isolated judgement is loaded and checked before the first comparison, so
// bad input writes neither masks nor compare.json.
int compare_sets(const cmp::StageSet& ref, const cmp::StageSet& test, const CompareArgs& a) {
  const std::string title = test.backend + " vs " + ref.backend;
  std::optional<IsolatedInputs> in;
  if (!a.scene.empty()) in = load_isolated_inputs(test, a.scene, a.config, a.scene_load, &ref);
  const std::unique_ptr<RunDir> run = open_out_run(a);
  const cmp::JudgeInputs inputs = in ? cmp::JudgeInputs{&in->scene, &in->frame, &in->settings} : cmp::JudgeInputs{};
  const cmp::Report rep = cmp::judge(ref, test, inputs, compare_options(a));
  if (!in) {
    const int code = finish(rep, a, run.get(), title, {{"cone_stages", "end_to_end"}});
    if (has_cone_stage(rep, cmp::soft_shadows_of(ref) || cmp::soft_shadows_of(test)))
      std::printf("cone stages were judged end to end (an upstream voxel tie changes every cone through it); "
                  "--scene SCENE judges them on B's own inputs (docs/compare.md)\n");
    return code;
  }
  const int code = finish(rep, a, run.get(), title, {{"cone_stages", "isolated"}, {"scene", in->scene.source}});
  std::printf("cone stages were judged on B's own G-buffer, direct light and mips, re-traced in %s\n",
              in->scene.source.c_str());
  return code;
}

int compare_volumes(const CompareArgs& a) {
  const Volume r = read_nrrd(a.a), t = read_nrrd(a.b);
  const std::unique_ptr<RunDir> run = open_out_run(a);
  cmp::Report rep;
  rep.stages.push_back(cmp::compare_volume_plain("volume", r, t, a.abs, a.rel, compare_options(a)));
  return finish(rep, a, run.get(), "compare");
}

int compare_images(const CompareArgs& a) {
  const Image r = read_image(a.a), t = read_image(a.b);
  if (r.width != t.width || r.height != t.height)
    throw InputError(a.b, "size " + std::to_string(t.width) + "x" + std::to_string(t.height) + " differs from " +
                              a.a + " (" + std::to_string(r.width) + "x" + std::to_string(r.height) + ")");
  const std::unique_ptr<RunDir> run = open_out_run(a);
  cmp::Report rep;
  rep.stages.push_back(cmp::compare_image_stage(a.stage, r, t, nullptr, compare_options(a)));
  const cmp::ImageMetrics m = cmp::image_metrics(t, r);
  std::printf("metrics (reference = %s): MSE %.4g  relMSE %.4g (eps %.2g)  mean bias %+.4g  max|d| %.4g  SSIM %.4f\n",
              a.a.c_str(), m.mse, m.rel_mse, m.rel_mse_epsilon, m.mean_bias, m.max_abs, m.ssim);
  rep.stages.back().extra["metrics"] = {{"mse", m.mse}, {"rel_mse", m.rel_mse}, {"rel_mse_epsilon", m.rel_mse_epsilon},
                                        {"mean_bias", m.mean_bias}, {"max_abs", m.max_abs}, {"ssim", m.ssim}};
  return finish(rep, a, run.get(), "compare");
}

int run(const CompareArgs& a) {
  if (!a.config.empty() && a.scene.empty()) throw InputError("--config", "is only used with --scene");
  for (const auto& p : {a.a, a.b})
    if (!fs::exists(p)) throw InputError(p, "no such file or directory");
  if (fs::is_directory(a.a) || fs::is_directory(a.b) || fs::path(a.a).extension() == ".json") {
    const cmp::StageSet ref = cmp::read_stage_set(stage_dir(a.a, "ref"));
    const cmp::StageSet test = cmp::read_stage_set(stage_dir(a.b, "gl"));
    return compare_sets(ref, test, a);
  }
  if (!a.scene.empty()) throw InputError("--scene", "applies to stage sets only, not to two images or volumes");
  if (is_volume(a.a) != is_volume(a.b)) throw InputError(a.b, "cannot compare an image with a volume");
  return is_volume(a.a) ? compare_volumes(a) : compare_images(a);
}

}  // namespace

void register_compare(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand("compare", "Stage-by-stage verdict: A = reference, B = test (run dirs, images, volumes)");
  cmd->add_option("A", a->a, "Reference: stage dir / run dir / image / volume")->required();
  cmd->add_option("B", a->b, "Test: stage dir / run dir / image / volume")->required();
  cmd->add_option("--out", a->out, "Write compare.json and error masks here");
  cmd->add_option("--stage", a->stage, "Tolerance model for two images (a stage name, default image.final)");
  cmd->add_option("--abs", a->abs, "Two volumes: absolute bound (default 0 = exact)");
  cmd->add_option("--rel", a->rel, "Two volumes: relative bound");
  cmd->add_option("--worst", a->worst, "Offenders listed per stage")->check(CLI::Range(1, 1000));
  cmd->add_option("--explain", a->explain,
                  "X,Y (images) or X,Y,Z (volumes): print, per stage, the rule that admitted that element and its numbers")
      ->delimiter(',')
      ->expected(2, 3)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--scene", a->scene,
                  "Stage sets: judge B's cone stages on B's own inputs, re-traced in this glTF scene "
                  "(or builtin:cornell_box), as vct validate does");
  cmd->add_option("--config", a->config, "With --scene: settings JSON for what B's manifest does not say");
  add_scene_access_flag(cmd, a->scene_load);
  cmd->callback([a, &exit_code]() { exit_code = run(*a); });
}

}  // namespace vct::app
