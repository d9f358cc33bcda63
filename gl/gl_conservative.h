// The conservative voxelization modes of the GL pass (settings.conservative_raster; docs/gl_backend.md,
// "Conservative voxelization"): which candidates the geometry shader emits, whether the driver's
// conservative rasterizer is on (GL_NV_conservative_raster, GL_INTEL_conservative_rasterization),
// and the facts the occupancy judge derives its bound from (compare/conservative_occupancy.h).
#pragma once

#include <string>

#include "core/settings.h"
#include "gl_api.h"
#include "stages/backend_facts.h"

namespace vct::gl {

struct ConservativeSetup {
  ConservativeRaster mode = ConservativeRaster::Off;
  GLenum cap = 0;              // glEnable'd around the voxelization draw (hardware modes)
  bool emit_quad = false;      // gs: the bounding quad; hardware: the triangle
  float clip_dilation = 0.0f;  // the fragment shader's pixel square grows by this (pixels)
  bool keep_outside = false;   // hardware: a fragment beyond the stated bound still writes a voxel
};

/// Throws the EnvironmentError below when `s` asks for a hardware mode the current context's
/// driver (`renderer`, for the message) lacks; callers that create output check this first, so a
/// refused run leaves nothing behind (app/cmd_render.cpp prepare_frame, the runner).
void require_conservative_raster(const VctSettings& s, const std::string& renderer);

/// The mode `s` asks for on the current context. A hardware mode whose extension the driver lacks
/// is an EnvironmentError (exit 3) naming it, thrown before any pass runs. Records the mode and
/// its parameters in `facts` (conservative_mode, conservative_snap_bits, conservative_dilation,
/// conservative_params).
ConservativeSetup conservative_setup(const VctSettings& s, BackendFacts& facts);

}  // namespace vct::gl
