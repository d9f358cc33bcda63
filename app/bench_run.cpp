#include "bench_run.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "compare/stage_timings.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "core/parallel.h"
#include "freedoms/reference_frame.h"
#include "interrupt.h"
#include "io/bounded_json.h"
#include "io/run_dir.h"
#include "pt/ray_throughput.h"
#include "stages/scene_footprint.h"

#ifdef VCT_HAVE_GL  // the GL backend is a build option (VCT_BUILD_GL)
#include "gl/gl_context.h"
#include "gl/gl_pipeline.h"
#endif

namespace vct::app {

namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown";
}

double load_average() {
  std::ifstream in("/proc/loadavg");
  double l = 0.0;
  in >> l;
  return l;
}

nlohmann::json machine() {
  return {{"cpu", cpu_model()},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"worker_threads", thread_count()},
          {"memory", format_bytes(physical_memory_bytes())},
          {"load_average_1min", load_average()},
          {"environment", environment_info()}};
}

nlohmann::json ref_times(const Scene& scene, const Settings& s, int repeat) {
  std::vector<StageTimes> runs;
  for (int r = 0; r < repeat; ++r) runs.push_back(render_ref_frame(scene, s).timings_ms);
  return median_times(runs);
}

// GL stage times (GPU timer queries) after one warm-up frame (shader compilation, driver caches);
// null with the reason in `note` when there is no GL.
nlohmann::json gl_times(const Scene& scene, const Settings& s, int repeat, std::string& note, std::string& renderer) {
#ifdef VCT_HAVE_GL
  try {
    gl::GlContext ctx;
    renderer = ctx.renderer() + " | " + ctx.version();
    gl::render_gl_frame(ctx, scene, s);
    std::vector<StageTimes> runs;
    for (int r = 0; r < repeat; ++r) runs.push_back(gl::render_gl_frame(ctx, scene, s).timings_ms);
    return median_times(runs);
  } catch (const EnvironmentError& e) {
    note = std::string("GL unavailable: ") + e.what();
  }
#else
  (void)scene, (void)s, (void)repeat, (void)renderer;
  note = "GL backend not built";
#endif
  return nullptr;
}

nlohmann::json groups(const nlohmann::json& ref, const nlohmann::json& gl) {
  const StageTimes r = ref.get<StageTimes>();
  const StageTimes g = gl.is_null() ? StageTimes{} : gl.get<StageTimes>();
  nlohmann::json out = nlohmann::json::array();
  for (const StageGroup& grp : stage_groups()) {
    nlohmann::json row = {{"name", grp.name}, {"ref_ms", sum_stages(r, grp.ref)}};
    if (!gl.is_null()) {
      const double gms = sum_stages(g, grp.gl);
      row["gl_ms"] = gms;
      row["ref_over_gl"] = gms > 0.0 ? nlohmann::json(row["ref_ms"].get<double>() / gms) : nlohmann::json(nullptr);
    }
    out.push_back(row);
  }
  return out;
}

nlohmann::json path_tracer(const Scene& scene, const Settings& s, const BenchOptions& o) {
  const pt::RawRayRates raw = pt::measure_raw_embree(scene, o.raw_rays);
  PtSettings ps = s.pt;
  ps.width = s.vct.width;
  ps.height = s.vct.height;
  auto rate_json = [&](const pt::TracerRate& t) {
    return nlohmann::json{{"rays_per_second", t.rays_per_second}, {"seconds", t.seconds},
                          {"primary", t.counts.primary},      {"secondary", t.counts.secondary},
                          {"shadow", t.counts.shadow},        {"fraction_of_raw_intersect", t.rays_per_second / raw.intersect}};
  };
  PtSettings primary = ps;
  primary.max_depth = 0;  // camera ray + first-hit shading only
  return {{"raw_rays", raw.rays},
          {"raw_intersect_rays_per_second", raw.intersect},
          {"raw_occluded_rays_per_second", raw.occluded},
          {"spp", o.pt_spp},
          {"width", ps.width},
          {"height", ps.height},
          // One pass: later passes reuse each pixel's first vertex (pt::Integrator::FirstVertex)
          // and trace nothing at max_depth 0.
          {"primary_only", rate_json(pt::measure_path_tracer(scene, primary, 1))},
          {"full_paths", rate_json(pt::measure_path_tracer(scene, ps, o.pt_spp))}};
}

// The whole validate job as a user runs it (its own process: start-up, renders, writes, report),
// with the phase times it records in run.json (app/phase_times.h).
nlohmann::json validate_row(const BenchOptions& o) {
  char exe[4096];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) return {{"note", "cannot find the vct executable"}};
  exe[n] = 0;
  char dir_template[] = "/tmp/vct-bench-validate-XXXXXX";
  const char* dir = mkdtemp(dir_template);
  if (!dir) return {{"note", "cannot make a temporary directory"}};
  const std::string out = std::string(dir) + "/run";
  std::string cmd = std::string("'") + exe + "' validate";
  if (!o.scene_path.empty()) cmd += " '" + o.scene_path + "'";
  cmd += " " + o.validate_args + " --threads " + std::to_string(thread_count()) + " --out '" + out + "' > '" + std::string(dir) + "/log' 2>&1";
  Stopwatch sw;
  const int rc = run_child(cmd);  // stopped with vct on Ctrl-C or kill (interrupt.h)
  nlohmann::json row = {{"wall_ms", sw.ms()}, {"exit_code", rc}};
  try {
    const nlohmann::json run = read_bounded_json_file(out + "/run.json", "run.json");
    row["phases"] = run.at("phases");
    row["settings"] = {{"width", run["settings"]["vct"]["width"]}, {"grid", run["settings"]["vct"]["grid"]},
                       {"spp", run["settings"]["pt"]["spp"]}};
    if (run.contains("memory")) row["memory"] = run["memory"];  // predicted and peak RSS (validate's own)
  } catch (const std::exception&) {
    row["note"] = "validate wrote no phase times (see its log)";
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  return row;
}

}  // namespace

nlohmann::json run_bench(const Scene& scene, const Settings& s, const BenchOptions& o) {
  nlohmann::json j;
  j["machine"] = machine();
  j["scene"] = {{"source", scene.source}, {"triangles", scene.triangle_count()}};
  j["settings"] = s;
  j["repeat"] = o.repeat;
  j["memory"]["predicted"] = format_bytes(estimate_memory(s, scene_footprint(scene)).total());
  j["ref"] = ref_times(scene, s, o.repeat);
  std::string note, renderer;
  j["gl"] = o.gl ? gl_times(scene, s, o.repeat, note, renderer) : nlohmann::json(nullptr);
  if (!o.gl) note = "GL not measured (--no-gl)";
  if (!note.empty()) j["gl_note"] = note;
  if (!renderer.empty()) j["machine"]["gl_renderer"] = renderer;
  j["groups"] = groups(j["ref"], j["gl"]);
  if (o.pt) j["path_tracer"] = path_tracer(scene, s, o);
  if (o.validate) j["validate"] = validate_row(o);
  j["memory"]["peak_rss"] = format_bytes(peak_rss_bytes());
  return j;
}

namespace {

__attribute__((format(printf, 1, 2))) std::string line(const char* fmt, ...) {
  char buf[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

std::string stage_table(const char* title, const nlohmann::json& t) {
  std::string out = line("%s\n", title);
  for (const auto& [k, v] : t.items()) out += line("  %-26s %10.2f ms\n", k.c_str(), v.get<double>());
  return out;
}

std::string format_path_tracer(const nlohmann::json& p) {
  const double raw = p["raw_intersect_rays_per_second"].get<double>();
  std::string out = line("\npath tracer vs raw Embree (%dx%d, %d spp):\n", p["width"].get<int>(),
                         p["height"].get<int>(), p["spp"].get<int>());
  out += line("  raw rtcIntersect1 (random rays) %8.2f Mrays/s\n", raw * 1e-6);
  out += line("  raw rtcOccluded1  (random rays) %8.2f Mrays/s\n",
              p["raw_occluded_rays_per_second"].get<double>() * 1e-6);
  for (const char* k : {"primary_only", "full_paths"}) {
    const auto& r = p[k];
    out += line("  path tracer, %-18s %8.2f Mrays/s  = %5.1f %% of raw intersect\n", k,
                r["rays_per_second"].get<double>() * 1e-6, 100.0 * r["fraction_of_raw_intersect"].get<double>());
  }
  return out;
}

std::string format_validate(const nlohmann::json& v) {
  if (!v.contains("phases")) return line("\nvalidate: %s\n", v.value("note", std::string("not measured")).c_str());
  const auto& p = v["phases"];
  std::string out = line("\nvalidate (%dx%d, grid %d^3, %d spp, report): %.2f s wall\n",
                         v["settings"]["width"].get<int>(), v["settings"]["width"].get<int>(),
                         v["settings"]["grid"].get<int>(), v["settings"]["spp"].get<int>(), v["wall_ms"].get<double>() / 1000);
  const double r = p["render_ms"].get<double>(), other = p["other_ms"].get<double>();
  out += line("  renders %.2f s, everything else %.2f s (non-render / renders %.2f at grid %d)\n", r / 1000,
              other / 1000, r > 0 ? other / r : 0.0, v["settings"]["grid"].get<int>());
  // CPU time tells work from waiting on a shared machine (app/phase_times.h).
  if (p.contains("render_cpu_ms") && p.contains("other_cpu_ms")) {
    const double rc = p["render_cpu_ms"].get<double>(), oc = p["other_cpu_ms"].get<double>();
    out += line("  CPU time: renders %.2f s, everything else %.2f s (non-render / renders %.2f)\n", rc / 1000,
                oc / 1000, rc > 0 ? oc / rc : 0.0);
  }
  if (v.contains("memory")) {
    const double predicted = v["memory"]["predicted_bytes"].get<double>(), peak = v["memory"]["peak_rss_bytes"].get<double>();
    out += line("  memory predicted %s, peak RSS %s (predicted / peak %.2f)\n",
                format_bytes(uint64_t(predicted)).c_str(), format_bytes(uint64_t(peak)).c_str(),
                peak > 0 ? predicted / peak : 0.0);
  }
  out += line("  largest other phases (wall):\n");
  std::vector<std::pair<double, std::string>> rest;
  for (const auto& ph : p["phases"])
    if (!ph["render"].get<bool>()) rest.emplace_back(ph["ms"].get<double>(), ph["name"].get<std::string>());
  std::sort(rest.rbegin(), rest.rend());
  for (size_t i = 0; i < rest.size() && i < 5; ++i) out += line("    %8.2f s  %s\n", rest[i].first / 1000, rest[i].second.c_str());
  return out;
}

}  // namespace

std::string format_bench(const nlohmann::json& j) {
  const auto& v = j["settings"]["vct"];
  std::string out = line("scene %s (%zu triangles), %dx%d, grid %d^3, %d threads, median of %d runs\n",
                         j["scene"]["source"].get<std::string>().c_str(), j["scene"]["triangles"].get<size_t>(),
                         v["width"].get<int>(), v["height"].get<int>(), v["grid"].get<int>(),
                         j["machine"]["worker_threads"].get<int>(), j["repeat"].get<int>());
  out += line("CPU: %s\n", j["machine"]["cpu"].get<std::string>().c_str());
  if (j["machine"].contains("gl_renderer"))
    out += line("GL:  %s\n", j["machine"]["gl_renderer"].get<std::string>().c_str());
  if (j.contains("gl_note")) out += line("note: %s (CPU column only)\n", j["gl_note"].get<std::string>().c_str());
  const bool gl = !j["gl"].is_null();
  out += gl ? line("\n%-24s %12s %12s %10s\n", "stage group", "CPU ref ms", "GL ms", "CPU/GL")
            : line("\n%-24s %12s\n", "stage group", "CPU ref ms");
  for (const auto& g : j["groups"]) {
    const double r = g["ref_ms"].get<double>();
    if (!gl) {
      out += line("%-24s %12.2f\n", g["name"].get<std::string>().c_str(), r);
    } else {
      // No GL time (the reference's own extras, a stage GL does not run): no ratio.
      const std::string ratio = g["ref_over_gl"].is_null() ? "-" : line("%.2f", g["ref_over_gl"].get<double>());
      out += line("%-24s %12.2f %12.2f %10s\n", g["name"].get<std::string>().c_str(), r, g["gl_ms"].get<double>(),
                  ratio.c_str());
    }
  }
  out += "\n" + stage_table("CPU reference stages (wall clock, median):", j["ref"]);
  if (gl) out += stage_table("GL stages (GPU timer queries, median):", j["gl"]);
  if (j.contains("path_tracer")) out += format_path_tracer(j["path_tracer"]);
  if (j.contains("validate")) out += format_validate(j["validate"]);
  // The peak is this whole process's: the GL driver's and Embree's memory come on top of the CPU
  // frame the prediction covers (`vct render` reports the two for the CPU frame alone).
  out += line("\nmemory: predicted %s for the CPU frame; peak RSS %s for this process (CPU + GL + path tracer)\n",
              j["memory"]["predicted"].get<std::string>().c_str(), j["memory"]["peak_rss"].get<std::string>().c_str());
  return out;
}

}  // namespace vct::app
