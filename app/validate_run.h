// vct validate's engine: render ref, gl and pt on one scene, compare GPU vs CPU stage by stage and
// VCT vs PT per component, optional parameter sweeps, run directory + run.json, then the report.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/settings.h"
#include "options.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::app {

/// What one backend produced: status "ok", "unavailable: ..." (no GL context, or a build
/// without GL), "error: ...".
struct BackendRun {
  std::string status = "not run";
  std::optional<FrameResult> frame;
  double ms = 0.0;
  bool ok() const { return frame.has_value(); }
};

struct PtRun {
  std::string status = "not run";
  std::map<std::string, Image> aovs;  // pt_full, pt_full_var, ...
  double ms = 0.0;
  int spp = 0;
  bool ok() const { return !aovs.empty(); }
};

/// `sample_positions`: the GPU-rule voxelizer's samples (the driver's, sample_positions_of);
/// empty = the standard pattern of s.vct.msaa_samples.
BackendRun run_ref_backend(const Scene& scene, const Settings& s, const std::vector<vec2>& sample_positions = {});
BackendRun run_gl_backend(const Scene& scene, const Settings& s, const GlFlags& flags = {});
/// InputError for what run_gl_backend would refuse as bad input (gl::check_gl_accepts), so a
/// command refuses it before creating its run directory. Without the GL build: nothing (the GL
/// frame is then recorded as unavailable, not refused).
void check_gl_backend_accepts(const Scene& scene, const Settings& s, const GlFlags& flags);
/// The settings the GL run actually used: a driver may clamp the MSAA sample count (llvmpipe
/// allows 4), and the CPU reference must then emulate the same coverage rule, or every voxel
/// stage differs for a reason that is not a GPU bug. Unchanged when GL did not run.
Settings settings_as_run_by_gl(const Settings& s, const BackendRun& gl);
/// The MSAA sample positions the GL run's driver reported (BackendFacts), for the reference's
/// GPU-rule voxelizer; empty when GL did not run.
std::vector<vec2> sample_positions_of(const BackendRun& gl);
/// `progress`: draw the path tracer's pass bar on stderr (ref/pt/progress.h; only on a terminal).
PtRun run_pt_backend(const Scene& scene, const Settings& s, bool progress = false);

/// Settings validate starts from (before --config and flags): small enough that the default
/// job (ref + gl + pt + report) finishes in a few minutes on 2 cores (docs/compare.md).
Settings validate_defaults();

/// Applies one sweep value ("grid", "64") to a copy of `s` through the JSON form, so every
/// vct.* key works; aliases: aperture, quality, cones. Throws InputError on an unknown key.
Settings apply_sweep_value(const Settings& s, const std::string& key, const std::string& value);

/// Parses "key=v1,v2,..."; throws InputError.
std::pair<std::string, std::vector<std::string>> parse_sweep(const std::string& spec);

/// The source tree: $VCT_SOURCE_DIR, else the nearest ancestor of the executable (or of the
/// working directory) holding report/make_report.py; "" when none.
std::string find_source_root();
/// `s` quoted for /bin/sh.
std::string shell_quote(const std::string& s);

/// Finds report/make_report.py and the venv Python next to the executable's source tree;
/// runs it on `run_dir`. Returns the index.html path, or "" with `why` filled.
/// `flip` chooses the FLIP maps ("full": the full image only, "all": every component, "none"),
/// passed as $VCT_REPORT_FLIP.
std::string make_report(const std::string& run_dir, std::string& why, const std::string& flip = "none");

}  // namespace vct::app
