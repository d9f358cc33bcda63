#include "pt/pathtrace_run.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "io/run_dir.h"
#include "pt/accumulator.h"
#include "pt/checkpoint.h"
#include "pt/path_tracer.h"
#include "pt/progress.h"
#include "scene/exposure.h"

namespace vct::pt {

namespace {

void write_outputs(RunDir& dir, const Accumulator& acc) {
  for (int a = 0; a < kAovCount; ++a) {
    dir.write_color(kAovNames[a], acc.mean(Aov(a)));
    dir.write_color(std::string(kAovNames[a]) + "_var", acc.variance(Aov(a)));
  }
}

}  // namespace

PathtraceRunResult run_pathtrace(const Scene& scene, const Settings& settings, const PathtraceRunOptions& opt) {
  const PtSettings& ps = settings.pt;
  RunDir dir(opt.out_dir, RunRole::Run);  // locked; INCOMPLETE until every pass is done
  dir.keep_existing_json();
  const std::string ckpt_path = dir.file(kCheckpointFile);
  const ParticleOptions particles{settings.vct.particles, settings.vct.time};
  const CheckpointKey key{hash_scene(scene), hash_render_settings(ps, particles)};

  PathtraceRunResult result;
  Accumulator acc(ps.width, ps.height);
  std::string why;
  if (load_checkpoint(ckpt_path, key, ps.width, ps.height, acc, why)) {
    if (acc.samples() > uint32_t(ps.spp))
      throw InputError(ckpt_path, "holds " + std::to_string(acc.samples()) + " spp, more than the requested " +
                                      std::to_string(ps.spp) + "; ask for at least that many or use another --out");
    result.resumed_from = acc.samples();
  } else if (why != "no checkpoint") {
    result.checkpoint_note = why;
    std::fprintf(stderr, "vct pathtrace: %s: %s; starting afresh\n", ckpt_path.c_str(), why.c_str());
  }

  const Stopwatch build_clock;
  const PathTracer tracer(scene, ps, particles);
  const double build_ms = build_clock.ms();

  ProgressBar bar(opt.progress, acc.samples(), uint32_t(ps.spp));
  const Stopwatch render_clock;
  auto last_checkpoint = std::chrono::steady_clock::now();
  bool stopped = false;
  result.rays = tracer.render(acc, uint32_t(ps.spp), [&](const Accumulator& a, const RayCounts& rays) {
    bar.update(a.samples(), rays.total());
    const auto now = std::chrono::steady_clock::now();
    if (ps.checkpoint_seconds > 0 && now - last_checkpoint >= std::chrono::seconds(ps.checkpoint_seconds)) {
      save_checkpoint(ckpt_path, key, a);
      last_checkpoint = now;
    }
    if (opt.stop_requested && opt.stop_requested()) {
      stopped = true;
      return false;
    }
    return true;
  });
  bar.finish();
  result.render_seconds = render_clock.ms() * 1e-3;
  result.spp = acc.samples();
  result.completed = !stopped && acc.samples() >= uint32_t(ps.spp);
  save_checkpoint(ckpt_path, key, acc);

  if (opt.write_images) write_outputs(dir, acc);
  nlohmann::json& j = dir.json();
  j["settings"] = settings;
  j["environment"] = environment_info();
  j["scene"] = scene.source;
  j["scene_warnings"] = scene.stats.warnings;
  j["exposure"] = exposure_json(scene.exposure);
  const double rays = double(result.rays.total());
  j["pathtrace"] = {{"spp", result.spp},
                    {"requested_spp", ps.spp},
                    {"completed", result.completed},
                    {"resumed_from_spp", result.resumed_from},
                    {"checkpoint", kCheckpointFile},
                    {"scene_hash", key.scene_hash},
                    {"settings_hash", key.settings_hash},
                    {"emissive_triangles", tracer.emitters().size()},
                    {"lights", scene.lights.size()},
                    {"particles", tracer.particles().size()},
                    {"particle_time", settings.vct.time},
                    {"rays", {{"primary", result.rays.primary},
                              {"secondary", result.rays.secondary},
                              {"shadow", result.rays.shadow},
                              {"total", result.rays.total()}}},
                    {"nonfinite_samples_dropped", result.rays.nonfinite_samples},
                    {"render_seconds", result.render_seconds},
                    {"rays_per_second", result.render_seconds > 0.0 ? rays / result.render_seconds : 0.0},
                    {"aovs", std::vector<std::string>(kAovNames, kAovNames + kAovCount)}};
  dir.add_timing("pt", "setup", build_ms);  // BVH, emitter tables, particle layer
  dir.add_timing("pt", "render", result.render_seconds * 1e3);
  if (result.completed) dir.finish();
  else dir.save();
  return result;
}

}  // namespace vct::pt
