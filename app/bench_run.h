// What `vct bench` measures, as JSON (written to bench.json and printed by cmd_bench.cpp):
// per-stage median times of the CPU reference and the GL build on the same scene and settings,
// their ratios per stage group, and the path tracer's rays/s beside raw Embree rtcIntersect1.
#pragma once

#include <nlohmann/json.hpp>

#include "core/settings.h"
#include "scene/scene.h"

namespace vct::app {

struct BenchOptions {
  int repeat = 3;     // frames per backend; the median of each stage is reported
  bool gl = true;     // measure the GL build too (skipped with a note if there is no context)
  bool pt = true;     // measure the path tracer and raw Embree
  int pt_spp = 2;     // passes of the path tracer (at the VCT image size)
  size_t raw_rays = 2000000;
  bool validate = true;    // time a whole `vct validate` (its defaults) on the scene, phase by phase
  std::string scene_path;  // what validate is given ("" = the built-in scene)
  std::string validate_args;  // flags for it (bench's explicit --width/--height/--grid, --validate-spp)
};

/// Runs the measurements; keys: machine, scene, settings, repeat, ref, gl (or gl_note),
/// groups [{name, ref_ms, gl_ms, ref_over_gl}], path_tracer {...}, validate {wall_ms, render_ms,
/// other_ms, phases} (a child `vct validate` at its defaults, report included).
nlohmann::json run_bench(const Scene& scene, const Settings& settings, const BenchOptions& o);

/// The report as text: settings line, side-by-side group table, per-stage tables, path tracer.
std::string format_bench(const nlohmann::json& bench);

}  // namespace vct::app
