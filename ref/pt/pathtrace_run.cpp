#include "pt/pathtrace_run.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <fstream>

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

ParticleOptions particle_options(const Settings& s) { return {s.vct.particles, s.vct.time}; }

// run.json's sections, the same for a one-machine render and a merge of cluster tasks.
void write_run_json(RunDir& dir, const Scene& scene, const Settings& settings, const CheckpointKey& key,
                    const PathTracer& tracer, const PathtraceRunResult& result, double build_ms) {
  const PtSettings& ps = settings.pt;
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
                    {"seed", ps.seed},
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
                    {"render_cpu_seconds", result.render_cpu_seconds},
                    {"rays_per_second", result.render_seconds > 0.0 ? rays / result.render_seconds : 0.0},
                    {"aovs", std::vector<std::string>(kAovNames, kAovNames + kAovCount)}};
  dir.add_timing("pt", "setup", build_ms);  // BVH, emitter tables, particle layer
  dir.add_timing("pt", "render", result.render_seconds * 1e3);
}

// Loads a compatible checkpoint into acc; returns the passes it held (0 = fresh start).
uint32_t resume_from_checkpoint(const std::string& ckpt_path, const CheckpointKey& key, const PtSettings& ps,
                                Accumulator& acc, PathtraceRunResult& result) {
  std::string why;
  if (load_checkpoint(ckpt_path, key, ps.width, ps.height, acc, why)) {
    if (acc.samples() > uint32_t(ps.spp))
      throw InputError(ckpt_path, "holds " + std::to_string(acc.samples()) + " spp, more than the requested " +
                                      std::to_string(ps.spp) + "; ask for at least that many or use another --out");
    return acc.samples();
  }
  if (why != "no checkpoint") {
    result.checkpoint_note = why;
    std::fprintf(stderr, "vct pathtrace: %s: %s; starting afresh\n", ckpt_path.c_str(), why.c_str());
  }
  return 0;
}

}  // namespace

CheckpointKey checkpoint_key(const Scene& scene, const Settings& settings) {
  return {hash_scene(scene), hash_render_settings(settings.pt, particle_options(settings))};
}

PathtraceRunResult run_pathtrace(const Scene& scene, const Settings& settings, const PathtraceRunOptions& opt) {
  const PtSettings& ps = settings.pt;
  RunDir dir(opt.out_dir, RunRole::Run);  // locked; INCOMPLETE until every pass is done
  dir.keep_existing_json();
  const std::string ckpt_path = dir.file(kCheckpointFile);
  const CheckpointKey key = checkpoint_key(scene, settings);

  PathtraceRunResult result;
  Accumulator acc(ps.width, ps.height);
  result.resumed_from = resume_from_checkpoint(ckpt_path, key, ps, acc, result);

  const Stopwatch build_clock;
  const PathTracer tracer(scene, ps, particle_options(settings));
  const double build_ms = build_clock.ms();

  ProgressBar bar(opt.progress, acc.samples(), uint32_t(ps.spp));
  const Stopwatch render_clock;
  const std::clock_t render_cpu = std::clock();  // process CPU time, every thread
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
  result.render_cpu_seconds = double(std::clock() - render_cpu) / CLOCKS_PER_SEC;
  result.spp = acc.samples();
  result.completed = !stopped && acc.samples() >= uint32_t(ps.spp);
  save_checkpoint(ckpt_path, key, acc);

  if (opt.write_images) write_outputs(dir, acc);
  write_run_json(dir, scene, settings, key, tracer, result, build_ms);
  if (result.completed) dir.finish();
  else dir.save();
  return result;
}

PartialSums run_sample_range(const Scene& scene, const Settings& settings, uint32_t first, uint32_t end,
                             const std::string& partial_path, bool progress) {
  if (first >= end) throw InputError("--sample-range", "expected A:B with A < B");
  const PtSettings& ps = settings.pt;
  PartialSums p;
  p.key = checkpoint_key(scene, settings);
  p.first_sample = first;
  p.end_sample = end;
  p.sums = Accumulator(ps.width, ps.height);
  p.sums.set_samples(first);  // render() continues at pass `first`: sample indices, seeds and halves as in one run
  const PathTracer tracer(scene, ps, particle_options(settings));
  ProgressBar bar(progress, first, end);
  p.rays = tracer.render(p.sums, end, [&bar](const Accumulator& a, const RayCounts& rays) {
    bar.update(a.samples(), rays.total());
    return true;
  });
  bar.finish();
  save_partial_sums(partial_path, p);
  return p;
}

namespace {

std::vector<PartialSums> load_partials_in(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir, "not a directory of partial sums");
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".ptpart") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  std::vector<PartialSums> partials;
  for (const std::string& f : files) partials.push_back(load_partial_sums(f));
  return partials;
}

nlohmann::json load_task_table(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / "tasks.json").string();
  std::ifstream in(path);
  if (!in) return nlohmann::json::array();
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, std::string("not valid JSON: ") + e.what());
  }
}

}  // namespace

PathtraceRunResult merge_sample_ranges(const Scene& scene, const Settings& settings, const std::string& partials_dir,
                                       const PathtraceRunOptions& opt) {
  const PtSettings& ps = settings.pt;
  const CheckpointKey key = checkpoint_key(scene, settings);
  PathtraceRunResult result;
  // Everything is read and checked before the run directory is touched (no half-written output).
  const Accumulator acc =
      merge_partial_sums(load_partials_in(partials_dir), key, ps.width, ps.height, uint32_t(ps.spp), result.rays);
  const nlohmann::json tasks = load_task_table(partials_dir);
  for (const auto& t : tasks)
    if (t.is_object() && t.contains("seconds") && t["seconds"].is_number()) result.render_seconds += t["seconds"].get<double>();
  RunDir dir(opt.out_dir, RunRole::Run);
  dir.keep_existing_json();
  const Stopwatch build_clock;
  const PathTracer tracer(scene, ps, particle_options(settings));  // for run.json's emitter/particle counts
  const double build_ms = build_clock.ms();
  result.spp = acc.samples();
  result.completed = true;
  save_checkpoint(dir.file(kCheckpointFile), key, acc);  // a later `vct pathtrace --spp M` refines it
  if (opt.write_images) write_outputs(dir, acc);
  write_run_json(dir, scene, settings, key, tracer, result, build_ms);
  dir.json()["pathtrace"]["tasks"] = tasks;
  dir.json()["pathtrace"]["render_seconds_note"] = "sum of the tasks' seconds (docs/cluster.md)";
  dir.finish();
  return result;
}

}  // namespace vct::pt
