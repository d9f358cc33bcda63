#include "gl_conservative.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "gl_context.h"
#include "gl_facts.h"

namespace vct::gl {
namespace {

bool has_extension(const std::string& name) {
  for (const std::string& e : gl_extensions())
    if (e == name) return true;
  return false;
}

// NV_conservative_raster: rasterization is conservative with respect to the primitive after its
// window coordinates are snapped to GL_SUBPIXEL_BITS + the precision bias bits (left at their
// initial value 0 here, and read back); NV_conservative_raster_dilate grows the primitive by
// CONSERVATIVE_RASTER_DILATE_NV pixels (initial value 0, left there and read back).
void nv_facts(BackendFacts& f) {
  GLint bx = 0, by = 0, bmax = 0;
  glGetIntegerv(GL_SUBPIXEL_PRECISION_BIAS_X_BITS_NV, &bx);
  glGetIntegerv(GL_SUBPIXEL_PRECISION_BIAS_Y_BITS_NV, &by);
  glGetIntegerv(GL_MAX_SUBPIXEL_PRECISION_BIAS_BITS_NV, &bmax);
  GLfloat dilate = 0.0f;
  const bool has_dilate = has_extension("GL_NV_conservative_raster_dilate");
  if (has_dilate) glGetFloatv(GL_CONSERVATIVE_RASTER_DILATE_NV, &dilate);
  f.conservative_snap_bits = std::max(f.subpixel_bits, 0) + int(std::min(bx, by));
  f.conservative_dilation = double(dilate);
  f.conservative_params = "GL_NV_conservative_raster: GL_SUBPIXEL_BITS " + std::to_string(f.subpixel_bits) +
                          ", SUBPIXEL_PRECISION_BIAS_X/Y_BITS_NV " + std::to_string(bx) + "/" + std::to_string(by) +
                          " (max " + std::to_string(bmax) + "), CONSERVATIVE_RASTER_DILATE_NV " +
                          (has_dilate ? std::to_string(dilate) : std::string("- (no _dilate extension: none)"));
}

}  // namespace

void require_conservative_raster(const VctSettings& s, const std::string& renderer) {
  const ConservativeRaster m = s.conservative_raster;
  if (m != ConservativeRaster::Nv && m != ConservativeRaster::Intel) return;
  const char* ext = m == ConservativeRaster::Nv ? "GL_NV_conservative_raster" : "GL_INTEL_conservative_rasterization";
  if (!has_extension(ext))
    throw EnvironmentError(std::string("conservative_raster = ") + to_string(m) + ": the driver (" + renderer +
                           ") has no " + ext + " (vct info --gl lists what it has; conservative_raster = gs runs anywhere)");
}

ConservativeSetup conservative_setup(const VctSettings& s, BackendFacts& facts) {
  ConservativeSetup c;
  c.mode = s.conservative_raster;
  if (c.mode == ConservativeRaster::Off) return c;
  facts.conservative_mode = to_string(c.mode);
  if (c.mode == ConservativeRaster::GeometryShader) {
    c.emit_quad = true;
    facts.conservative_params = "geometry-shader bounding quad (half a pixel + 1/16 margin) + exact clip per pixel";
    return c;
  }
  require_conservative_raster(s, facts.renderer);
  if (facts.subpixel_bits < 1)
    throw EnvironmentError(std::string("conservative_raster = ") + to_string(c.mode) +
                           ": the driver reports no GL_SUBPIXEL_BITS, so the bound of its rasterizer is unknown");
  if (c.mode == ConservativeRaster::Nv) {
    c.cap = GL_CONSERVATIVE_RASTERIZATION_NV;
    nv_facts(facts);
  } else {
    // INTEL_conservative_rasterization has no precision controls: the snapping is the driver's
    // GL_SUBPIXEL_BITS (docs/compare.md, "Conservative voxelization", says what this assumes).
    c.cap = GL_CONSERVATIVE_RASTERIZATION_INTEL;
    facts.conservative_snap_bits = facts.subpixel_bits;
    facts.conservative_params = "GL_INTEL_conservative_rasterization: GL_SUBPIXEL_BITS " + std::to_string(facts.subpixel_bits);
  }
  c.clip_dilation = float(std::ldexp(1.0, -facts.conservative_snap_bits) + facts.conservative_dilation);
  c.keep_outside = true;
  check_gl("conservative raster parameters");
  return c;
}

}  // namespace vct::gl
