#include "gl_pipeline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "gl_context.h"
#include "gl_frame.h"
#include "gl_program.h"
#include "stages/shadow_map.h"

namespace vct::gl {

mat4 light_view_proj(const Scene& scene, const SpotLight& light) {
  // The CPU's definition, shared by call: both backends render from the same matrix.
  return spot_light_view_proj(light, scene.bounds);
}

FrameResult render_gl_frame(GlContext& context, const Scene& scene, const Settings& settings) {
  if (scene.spot_lights.size() > size_t(kMaxLights))
    throw InputError(scene.source, "the GL backend takes at most " + std::to_string(kMaxLights) + " spot lights, the scene has " +
                                       std::to_string(scene.spot_lights.size()));
  const ScopedShaderFault fault(settings.vct.gl_fault);  // "" = the correct shaders
  FrameResult result;
  result.backend = "gl";
  if (!settings.vct.gl_fault.empty()) result.info["gl_fault"] = settings.vct.gl_fault;
  result.info["GL_RENDERER"] = context.renderer();
  result.info["GL_VERSION"] = context.version();
  GlFrame f(scene, settings.vct, result);
  f.samples = std::min(std::max(settings.vct.msaa_samples, 1), context.max_framebuffer_samples());
  result.info["msaa_samples"] = std::to_string(f.samples);
  if (f.samples != settings.vct.msaa_samples)
    result.info["msaa_note"] = "requested " + std::to_string(settings.vct.msaa_samples) +
                               " samples; the driver's GL_MAX_FRAMEBUFFER_SAMPLES is " +
                               std::to_string(context.max_framebuffer_samples());
  if (settings.vct.voxelizer == Voxelizer::Conservative)
    result.info["voxelizer"] = "gpu rule (dominant axis + MSAA; GL has no conservative rasterization on this path)";
  if (settings.vct.reduction == Reduction::ExactMean)
    result.info["reduction"] = "fixed_point (GL has no exact mean; the fixed-point sum is its deterministic twin)";
  glCreateVertexArrays(1, &f.empty_vao);
  upload_diffuse_cone_block(f);
  shadow_pass(f);
  gbuffer_pass(f);
  voxel_passes(f);
  direct_pass(f);
  indirect_pass(f);
  particle_pass(f);
  glFinish();
  result.timings_ms = f.timers.collect();
  double total = 0.0;
  for (const auto& [name, ms] : result.timings_ms) total += ms;
  result.timings_ms["total"] = total;
  read_back(f);
  return result;
}

FrameResult render_gl_frame(const Scene& scene, const Settings& settings) {
  GlContext context;
  return render_gl_frame(context, scene, settings);
}

}  // namespace vct::gl
