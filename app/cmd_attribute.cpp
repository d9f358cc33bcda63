// vct attribute [SCENE]: the per-component error budget of the CPU reference's VCT against the path
// tracer (issue 17 item 1, docs/attribution.md). Prints a table (component, term, mean, SE, share
// of the total), writes attribution.json, run.json, a waterfall PNG per component and a heat map
// (EXR + PNG) per term into --out; --sweep KEY=v1,v2 adds the budget's rows per value.
// Exit 0: every component's terms add up to its total within kSumCheckSigmas standard errors;
// 1: one does not (an estimator is wrong); 2: bad input.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "attribution/attribution.h"
#include "attribution_outputs.h"
#include "commands.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/run_dir.h"
#include "options.h"
#include "scene_warnings.h"
#include "freedoms/reference_frame.h"
#include "validate_run.h"

namespace vct::app {

namespace {

struct AttributeOptions {
  std::string scene;
  CommonOptions common;
  int rays = 32;
  std::vector<std::string> components;
  std::vector<std::string> sweeps;
};

// Small by default: a budget at 64^2, grid 64 takes seconds to a minute on 2 cores.
Settings attribute_defaults() {
  Settings s;
  s.vct.width = s.pt.width = 64;
  s.vct.height = s.pt.height = 64;
  s.vct.grid = 64;
  s.vct.shadow_map_size = 512;
  s.pt.spp = 64;
  return s;
}

nlohmann::json run_sweep(const Scene& scene, const Settings& base, const std::string& spec,
                         attr::AttributionOptions opt, attr::PtCache& cache) {
  const auto [key, values] = parse_sweep(spec);
  opt.pt_cache = &cache;  // the path tracer does not depend on the VCT keys swept
  nlohmann::json rows = nlohmann::json::array();
  for (const std::string& value : values) {
    const Settings s = apply_sweep_value(base, key, value);
    const attr::Attribution a = attr::attribute(scene, s, opt);
    for (const attr::ComponentBudget& b : a.components) print_budget(b, "  " + key + "=" + value + "  ");
    rows.push_back({{"value", value}, {"components", attr::to_json(a)}});
  }
  return {{"key", key}, {"rows", rows}};
}

int run_attribute(const AttributeOptions& o) {
  const Settings s = resolve_settings(o.common, attribute_defaults());
  attr::check_components(o.components, "--components");
  if (o.rays < 1) throw InputError("--rays", "must be >= 1 (got " + std::to_string(o.rays) + ")");
  attr::check_attributable(s.vct);  // before the run directory: no half-written output
  for (const std::string& spec : o.sweeps) {  // bad specs and values fail before any rendering
    const auto [key, values] = parse_sweep(spec);
    for (const std::string& v : values) attr::check_attributable(apply_sweep_value(s, key, v).vct);
  }
  const Scene scene = load_scene_and_warn(o.scene, o.common.scene_load, s.vct);
  RunDir run(o.common.out.empty() ? default_out_dir("attribute", o.scene) : o.common.out, RunRole::Run);
  Stopwatch sw;
  attr::AttributionOptions opt;
  opt.rays_per_pixel = o.rays;
  opt.components = o.components;
  attr::PtCache cache;
  opt.pt_cache = &cache;
  const FrameResult frame = render_ref_frame(scene, s);
  const attr::Attribution a = attr::attribute_frame(scene, s, frame, opt);
  std::printf("vct attribute: %s (%dx%d, grid %d, spp %d, %d rays per pixel) -> %s\n", scene.source.c_str(),
              s.vct.width, s.vct.height, s.vct.grid, s.pt.spp, o.rays, run.path().c_str());
  nlohmann::json doc;
  doc["scene"] = scene.source;
  doc["settings"] = s;
  doc["rays_per_pixel"] = o.rays;
  doc["components"] = write_attribution(run, a, frame.gbuffer.coverage);
  for (const attr::ComponentBudget& b : a.components) print_budget(b, "");
  if (!o.sweeps.empty()) {
    doc["sweeps"] = nlohmann::json::array();
    for (const std::string& spec : o.sweeps) doc["sweeps"].push_back(run_sweep(scene, s, spec, opt, cache));
  }
  doc["sums_to_totals"] = a.sums_to_totals();
  write_text_atomically(run.file("attribution.json"), doc.dump(2) + "\n");
  run.json()["command"] = "attribute";
  run.json()["settings"] = s;
  run.json()["environment"] = environment_info();
  run.json()["scene"] = {{"source", scene.source}, {"triangles", scene.triangle_count()}};
  run.json()["attribution"] = "attribution.json";
  run.json()["wall_ms"] = sw.ms();  // not timings_ms: the report reads that as backend -> stage -> ms
  run.finish();
  std::printf("%s (%.1f s)\n", a.sums_to_totals() ? "every budget adds up to its total" : "a budget does not add up",
              sw.ms() / 1000.0);
  return a.sums_to_totals() ? kExitOk : kExitFailed;
}

}  // namespace

void register_attribute(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<AttributeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "attribute", "Error budget per component: truth -> voxel field -> cone set -> mips (docs/attribution.md)");
  cmd->add_option("scene", o->scene, "glTF scene (default: the built-in Cornell box)");
  add_common_flags(cmd, o->common);
  add_scene_access_flag(cmd, o->common.scene_load);
  add_image_flags(cmd, o->common);
  add_grid_flag(cmd, o->common);
  add_spp_flag(cmd, o->common);
  cmd->add_option("--rays", o->rays, "Rays per pixel of each gathering rung (the cone-set rung: per cone)");
  cmd->add_option("--components", o->components, "indirect_diffuse, indirect_specular, direct (default all)")
      ->delimiter(',');
  cmd->add_option("--sweep", o->sweeps,
                  "KEY=V1,V2,... the budget per value (grid, diffuse_cone_count, aperture, quality or any vct.* key); repeatable");
  cmd->callback([o, &exit_code]() { exit_code = run_attribute(*o); });
}

}  // namespace vct::app
