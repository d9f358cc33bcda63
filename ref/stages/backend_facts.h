// What a backend actually ran and what its driver reports, as typed values (not prose in
// FrameResult::info): the effective MSAA sample count and sample positions of the voxelization
// pass, the effective reduction, the device and the driver's facts the CPU mirrors. Written to
// run.json ("facts") and to a stage set's manifest ("facts"), read back by the same from_json.
// docs/gl_backend.md, "Driver facts".
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/math.h"

namespace vct {

struct BackendFacts {
  // What ran, when it differs from what the settings asked for or must be known exactly.
  int msaa_samples = 0;            // voxelization samples used (0 = unknown)
  int msaa_samples_requested = 0;  // settings.msaa_samples
  // Sample positions of the voxelization pass in pixel units, GL convention (origin at the
  // pixel's lower-left corner, y up: GL 4.5 §14.3.1, glGetMultisamplefv(GL_SAMPLE_POSITION)).
  // The CPU's GPU-rule voxelizer uses these instead of assumed ones. Empty = not reported.
  std::vector<vec2> sample_positions;
  std::string reduction;  // "exact_mean" | "fixed_point" | "cas_rgba8"; "" = as the settings say
  std::string reduction_note;  // why it differs, if it does
  std::string gl_fault;        // deliberate fault compiled into the shaders ("" = none)

  // The device and driver (GL backend).
  std::string device;  // "egl device 0 (...)", "mesa surfaceless"
  std::string vendor, renderer, version;  // GL_VENDOR, GL_RENDERER, GL_VERSION
  int max_samples = 0;     // GL_MAX_FRAMEBUFFER_SAMPLES
  int subpixel_bits = -1;  // GL_SUBPIXEL_BITS (-1 = not reported)
  std::vector<std::string> conservative_raster;  // GL_NV_conservative_raster, ... when present
  // The conservative voxelization mode that ran (settings.conservative_raster: "gs", "nv",
  // "intel"; "" = the sample rule) and what its bound rests on (docs/compare.md, "Conservative
  // voxelization"): the window-coordinate snapping precision in bits while it ran (hardware: GL_SUBPIXEL_BITS
  // + the NV precision bias; -1 = not hardware), the extension's dilation in pixels (NV_conservative_raster_dilate;
  // 0 = its default, none), and the parameters in words.
  std::string conservative_mode;
  int conservative_snap_bits = -1;
  double conservative_dilation = 0.0;
  std::string conservative_params;
  // Facts the comparison would use but the driver does not report (each "name: why"); the
  // verdicts that depend on them say so in their note.
  std::vector<std::string> unreported;

  bool empty() const { return msaa_samples == 0 && renderer.empty() && reduction.empty(); }
};

void to_json(nlohmann::json& j, const BackendFacts& f);
/// Reads what to_json wrote; missing keys keep their defaults. Throws nlohmann::json::exception
/// on a key of the wrong type (callers turn it into an InputError naming their file).
void from_json(const nlohmann::json& j, BackendFacts& f);

/// The sub-pixel precision the CPU rasterizer snaps to (stages/raster.h kSubpixelBits), to set
/// beside the driver's GL_SUBPIXEL_BITS.
int cpu_subpixel_bits();

}  // namespace vct
