#include "validate_run.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/error.h"
#include "interrupt.h"
#include "core/settings_table.h"
#include "io/run_dir.h"
#include "pt/path_tracer.h"
#include "pt/progress.h"
#include "freedoms/reference_frame.h"
#ifdef VCT_HAVE_GL  // the GL backend is a build option (VCT_BUILD_GL)
#include "gl/gl_context.h"
#include "gl/gl_pipeline.h"
#endif

namespace vct::app {

namespace fs = std::filesystem;

Settings validate_defaults() {
  Settings s;
  s.vct.width = s.pt.width = 256;
  s.vct.height = s.pt.height = 256;
  s.vct.grid = 64;
  s.vct.shadow_map_size = 1024;
  s.pt.spp = 64;
  // The GPU's own coverage rule and the deterministic reduction on both sides: occupancy and
  // voxel radiance are then comparable exactly (holes are still measured against the
  // conservative set).
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.reduction = Reduction::FixedPoint;
  return s;
}

BackendRun run_ref_backend(const Scene& scene, const Settings& s, const std::vector<vec2>& sample_positions) {
  BackendRun r;
  Stopwatch sw;
  r.frame = render_ref_frame(scene, s, sample_positions);
  r.ms = sw.ms();
  r.status = "ok";
  return r;
}

BackendRun run_gl_backend(const Scene& scene, const Settings& s, const GlFlags& flags) {
  BackendRun r;
#ifdef VCT_HAVE_GL
  try {
    Stopwatch sw;
    r.frame = gl::render_gl_frame(scene, s, {flags.device, flags.fault});
    r.ms = sw.ms();
    r.status = "ok";
  } catch (const EnvironmentError& e) {
    r.status = std::string("unavailable: ") + e.what();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    // A shader or GL error is a GPU-side failure to report, not a reason to lose ref and pt.
    r.status = std::string("error: ") + e.what();
  }
#else
  (void)scene, (void)s, (void)flags;
  r.status = "unavailable: built without the GL backend (VCT_BUILD_GL=OFF)";
#endif
  return r;
}

void check_gl_backend_accepts(const Scene& scene, const Settings& s, const GlFlags& flags) {
#ifdef VCT_HAVE_GL
  gl::check_gl_accepts(scene, s, {flags.device, flags.fault});
  gl::check_gl_device_exists(flags.device);
#else
  (void)scene, (void)s, (void)flags;
#endif
}

Settings settings_as_run_by_gl(const Settings& s, const BackendRun& gl) {
  Settings out = s;
  if (!gl.ok()) return out;
  // Counts the settings cannot name (2, 16, 32 on some drivers) are carried by the positions.
  const int n = gl.frame->facts.msaa_samples;
  if (n == 1 || n == 4 || n == 8) out.vct.msaa_samples = n;
  return out;
}

std::vector<vec2> sample_positions_of(const BackendRun& gl) {
  return gl.ok() ? gl.frame->facts.sample_positions : std::vector<vec2>{};
}

PtRun run_pt_backend(const Scene& scene, const Settings& s, bool progress) {
  PtRun r;
  Stopwatch sw;
  pt::PathTracer tracer(scene, s.pt);
  pt::Accumulator acc(s.pt.width, s.pt.height);
  pt::ProgressBar bar(progress, 0, uint32_t(s.pt.spp));
  tracer.render(acc, uint32_t(s.pt.spp), [&bar](const pt::Accumulator& a, const pt::RayCounts& rays) {
    bar.update(a.samples(), rays.primary + rays.secondary + rays.shadow);
    return true;
  });
  for (int a = 0; a < pt::kAovCount; ++a) {
    const std::string name = pt::kAovNames[a];
    r.aovs[name] = acc.mean(pt::Aov(a));
    r.aovs[name + "_var"] = acc.variance(pt::Aov(a));
  }
  r.spp = int(acc.samples());
  r.ms = sw.ms();
  r.status = "ok";
  return r;
}

std::pair<std::string, std::vector<std::string>> parse_sweep(const std::string& spec) {
  const size_t eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 >= spec.size())
    throw InputError("--sweep", "expected KEY=V1,V2,... (e.g. grid=64,128,256), got '" + spec + "'");
  std::vector<std::string> values;
  std::string rest = spec.substr(eq + 1);
  size_t pos = 0;
  while (pos <= rest.size()) {
    const size_t comma = rest.find(',', pos);
    const std::string v = rest.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    if (v.empty()) throw InputError("--sweep", "empty value in '" + spec + "'");
    values.push_back(v);
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return {spec.substr(0, eq), values};
}

Settings apply_sweep_value(const Settings& s, const std::string& key_in, const std::string& value) {
  static const std::map<std::string, std::string> kAliases = {
      {"aperture", "diffuse_aperture_deg"}, {"quality", "cone_quality"}, {"cones", "diffuse_cones"},
      {"storage", "storage"}, {"grid", "grid"}};
  auto a = kAliases.find(key_in);
  const std::string key = a != kAliases.end() ? a->second : key_in;
  // cones=0,5,9: 0 switches the diffuse cones off, N > 0 traces N of them.
  Settings out = s;
  if (key == "diffuse_cones" && value != "true" && value != "false") {
    const Settings counted = value == "0" ? s : with_setting(s, "diffuse_cone_count", value, "--sweep");
    out = with_setting(counted, key, value == "0" ? "false" : "true", "--sweep");
  } else {
    out = with_setting(s, key, value, "--sweep");
  }
  // The path tracer renders the light model the VCT frame assumes.
  if (key == "light_model") out = with_setting(out, "pt.light_model", value, "--sweep");
  validate_settings(out);
  return out;
}

namespace {
std::string exe_dir() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return ".";
  buf[n] = 0;
  return fs::path(buf).parent_path().string();
}

}  // namespace

std::string find_source_root() {
  if (const char* env = std::getenv("VCT_SOURCE_DIR")) return env;
  for (fs::path p : {fs::path(exe_dir()), fs::current_path()}) {
    for (; !p.empty(); p = p.parent_path()) {
      if (fs::exists(p / "report" / "make_report.py")) return p.string();
      if (p == p.parent_path()) break;
    }
  }
  return "";
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string make_report(const std::string& run_dir, std::string& why, const std::string& flip) {
  const std::string root = find_source_root();
  if (root.empty()) {
    why = "report/make_report.py not found (set VCT_SOURCE_DIR)";
    return "";
  }
  std::string py = root + "/.venv/bin/python";
  if (!fs::exists(py)) py = "python3";
  const std::string cmd = "VCT_REPORT_FLIP=" + shell_quote(flip) + " " + shell_quote(py) + " " + shell_quote(root + "/report/make_report.py") + " " +
                          shell_quote(run_dir) + " > " + shell_quote(run_dir + "/report.log") + " 2>&1";
  const int rc = run_child(cmd);  // stopped with vct on Ctrl-C or kill (interrupt.h)
  const std::string index = (fs::path(run_dir) / "report" / "index.html").string();
  if (rc != 0 || !fs::exists(index)) {
    why = "report generator failed (see " + run_dir + "/report.log)";
    return "";
  }
  return fs::absolute(index).string();
}

}  // namespace vct::app
