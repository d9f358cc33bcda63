// Command line of vct_gl_runner (gl/runner/main.cpp): the VCT settings a GPU check varies, the
// device, the fault, and the timing sweep. docs/gl_backend.md, "GL runner".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/settings.h"

namespace vct::gl {

struct RunnerOptions {
  std::string scene;    // glTF path ("" = the built-in Cornell box)
  std::string out;      // stage set directory (render) or timing directory (--timings)
  std::string config;   // settings JSON ({"vct": {...}})
  std::string device;   // --gl-device
  std::string fault;    // --gl-fault
  std::optional<int> width, height, grid, msaa, shadow_map_size, bounces;
  std::optional<std::string> reduction, storage, voxelizer, conservative_raster;
  bool aniso = false, no_depth_prepass = false, max_msaa = false;
  std::vector<int> timing_grids;  // --timings 32,64,128,256: GPU times per stage instead of a stage set
  int repeat = 3;                 // timing repetitions (the best is kept)
};

class GlContext;

/// --max-msaa: the driver's GL_MAX_FRAMEBUFFER_SAMPLES, at most 8 (the largest count the settings
/// accept, core/settings.h: a driver with 16 or 32 is run at 8, with its own 8x positions).
int max_settable_samples(const GlContext& context);

/// Library defaults <- --config <- flags, validated (InputError on a bad value).
Settings runner_settings(const RunnerOptions& o);

}  // namespace vct::gl
