#include "runner_timings.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "gl/gl_context.h"
#include "gl/gl_pipeline.h"
#include "io/atomic_file.h"
#include "scene/gltf_loader.h"

namespace vct::gl {
namespace {

struct Config {
  int grid;
  bool aniso, prepass;
};

// Best (smallest) time of each stage over `repeat` frames, after one warm-up frame that pays for
// shader compilation and first-use uploads.
std::map<std::string, double> best_times(GlContext& ctx, const Scene& scene, const Settings& s, int repeat) {
  render_gl_frame(ctx, scene, s);
  std::map<std::string, double> best;
  for (int r = 0; r < repeat; ++r)
    for (const auto& [stage, ms] : render_gl_frame(ctx, scene, s).timings_ms)
      best[stage] = best.count(stage) ? std::min(best[stage], ms) : ms;
  return best;
}

void print_table(const nlohmann::json& rows) {
  const char* stages[] = {"shadow_maps", "depth_prepass", "gbuffer", "voxelize", "resolve", "mips",
                          "direct",      "indirect_cones", "particles", "total"};
  std::printf("%-5s %-5s %-7s", "grid", "mips", "prepass");
  for (const char* s : stages) std::printf(" %14s", s);
  std::printf("   (GPU ms, best of the repeats)\n");
  for (const auto& r : rows) {
    std::printf("%-5d %-5s %-7s", r["grid"].get<int>(), r["anisotropic"].get<bool>() ? "aniso" : "iso",
                r["depth_prepass"].get<bool>() ? "yes" : "no");
    for (const char* s : stages)
      if (r["ms"].contains(s)) std::printf(" %14.3f", r["ms"][s].get<double>());
      else std::printf(" %14s", "-");
    std::printf("\n");
  }
}

}  // namespace

int run_timings(const RunnerOptions& o) {
  if (o.out.empty()) throw InputError("--out", "is required (the timings directory)");
  const Settings base = runner_settings(o);
  const Scene scene = load_scene(o.scene);
  GlContext ctx(o.device);
  nlohmann::json rows = nlohmann::json::array();
  for (int grid : o.timing_grids)
    for (bool aniso : {false, true})
      for (bool prepass : {true, false}) {
        const Config c{grid, aniso, prepass};
        Settings s = base;
        s.vct.grid = c.grid;
        s.vct.anisotropic = c.aniso;
        s.vct.depth_prepass = c.prepass;
        if (o.max_msaa) s.vct.msaa_samples = max_settable_samples(ctx);
        validate_settings(s);
        rows.push_back({{"grid", c.grid}, {"anisotropic", c.aniso}, {"depth_prepass", c.prepass},
                        {"ms", best_times(ctx, scene, s, o.repeat)}});
      }
  print_table(rows);
  const nlohmann::json out = {{"scene", scene.source},     {"device", ctx.device()},  {"renderer", ctx.renderer()},
                              {"version", ctx.version()},  {"width", base.vct.width}, {"height", base.vct.height},
                              {"repeat", o.repeat},        {"rows", rows}};
  std::filesystem::create_directories(o.out);
  write_text_atomically((std::filesystem::path(o.out) / "timings.json").string(), out.dump(2) + "\n");
  return 0;
}

}  // namespace vct::gl
