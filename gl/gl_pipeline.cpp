#include "gl_pipeline.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/error.h"
#include "gl_context.h"
#include "gl_device.h"
#include "gl_facts.h"
#include "gl_faults.h"
#include "gl_frame.h"
#include "gl_labels.h"
#include "gl_program.h"
#include "gl_renderdoc.h"
#include "stages/cube_map.h"
#include "stages/shadow_map.h"

namespace vct::gl {

std::vector<mat4> shadow_layer_view_proj(const Scene& scene, const VctSettings& settings, std::vector<int>* light_layer) {
  std::vector<mat4> layers;
  for (const Light& light : scene.lights) {
    light_layer->push_back(int(layers.size()));
    if (light.is_point()) {
      const vec2 range = light_depth_range(light, scene.bounds);
      for (int face = 0; face < 6; ++face) layers.push_back(cube_face_view_proj(face, light.position, range.x, range.y));
    } else if (light.is_directional()) {
      layers.push_back(directional_light_view_proj(light, scene.volume));
    } else {
      layers.push_back(spot_light_view_proj(light, scene.bounds, settings));
    }
  }
  return layers;
}

namespace {

bool is_cpu_rasterizer(const std::string& renderer) {
  return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

// The facts of this frame: the driver's (gl_facts.h) plus what the GL path substitutes.
BackendFacts frame_facts(const GlContext& context, const VctSettings& s, const std::string& fault) {
  BackendFacts facts = read_driver_facts(context, s.msaa_samples);
  facts.gl_fault = fault;
  if (s.reduction == Reduction::ExactMean) {
    facts.reduction = "fixed_point";
    facts.reduction_note = "GL has no exact mean; the fixed-point sum is its deterministic twin";
  }
  if (s.reduction == Reduction::RunningMeanHalf) {
    // The racy running mean is another engine's convention (stages/running_mean.h), not ours.
    facts.reduction = "fixed_point";
    facts.reduction_note = "GL does not run the racy running mean; the fixed-point sum is its deterministic twin";
  }
  return facts;
}

}  // namespace

void check_gl_accepts(const Scene& scene, const Settings& settings, const GlOptions& options) {
  if (scene.lights.size() > size_t(kMaxLights))
    throw InputError(scene.source, "the GL backend takes at most " + std::to_string(kMaxLights) + " lights, the scene has " +
                                       std::to_string(scene.lights.size()));
  check_gl_fault(options.fault, "--gl-fault");
  parse_device_spec(options.device);
  if (!settings.vct.pcf_taps.empty() || settings.vct.shadow_compare != ShadowCompare::Nearest ||
      settings.vct.shadow_depth_format != ShadowDepthFormat::Depth32f)
    // An engine's PCF (issue 21) is reproduced by the reference only; GL runs the oracle's own.
    throw InputError("settings", "the GL backend runs the pcf_kernel square with nearest compare; "
                                 "pcf_taps, shadow_compare=linear and "
                                 "shadow_depth_format other than depth32f are for the reference");
  const VctSettings& pcf = settings.vct;
  if (!pcf.voxel_pcf_taps.empty() || pcf.shadow_filter_order != ShadowFilterOrder::CompareThenFilter ||
      pcf.pcf_tap_unit != PcfTapUnit::Texel || pcf.pcf_tap_scale != PcfTapScale::None ||
      pcf.shadow_border != ShadowBorder::Clamp)
    // The rest of an engine's PCF (issue 39): lights.glsl runs one texel kernel for both passes,
    // clamped to edge; the variants are the reference's only.
    throw InputError("settings", "the GL backend runs one texel PCF kernel, clamped to edge, for both passes; "
                                 "voxel_pcf_taps, shadow_filter_order, pcf_tap_unit, pcf_tap_scale and "
                                 "shadow_border are for the reference");
  if (!settings.vct.diffuse_cone_set.empty() || settings.vct.cone_tangent_frame != ConeTangentFrame::Branchless ||
      !settings.vct.shadow_view_proj.empty() || !settings.vct.shadow_ortho_box.empty())
    // An engine's cone set, march rule and light matrices (issue 21) are reproduced by the reference only.
    throw InputError("settings", "the GL backend runs the oracle's cone set and light frusta; "
                                 "diffuse_cone_set, cone_tangent_frame, shadow_view_proj and "
                                 "shadow_ortho_box are for the reference");
  if (settings.vct.indirect_fresnel != IndirectFresnel::Schlick)
    // The composite's Fresnel is the shared sh::fresnel_schlick in indirect.frag; an engine's
    // other one (issue 21) is the reference's only.
    throw InputError("settings", "the GL backend runs the oracle's composite Fresnel; indirect_fresnel = "
                                 "schlick_roughness is for the reference");
  const VctSettings& v = settings.vct;
  if (v.specular_offset_voxels >= 0.0f || v.specular_quality > 0.0f || v.specular_aperture != SpecularAperture::Ggx ||
      v.specular_view != SpecularView::Surface)
    // indirect.frag traces the specular cone with the diffuse cones' march and the shared
    // sh::specular_cone_aperture; an engine's own specular cone (issue 21) is the reference's only.
    throw InputError("settings", "the GL backend runs the oracle's specular cone; specular_offset_voxels, "
                                 "specular_quality, specular_aperture and specular_view are for the reference");
}

FrameResult render_gl_frame(GlContext& context, const Scene& scene, const Settings& settings, const GlOptions& options) {
  check_gl_accepts(scene, settings, options);
  FrameResult result;
  result.backend = "gl";
  result.facts = frame_facts(context, settings.vct, options.fault);
  const ConservativeSetup conservative = conservative_setup(settings.vct, result.facts);
  GlFrame f(scene, settings.vct, result, options.fault);
  f.conservative = conservative;
  // The conservative modes rasterize single-sampled: coverage is the pixel square's, not samples'.
  f.samples = conservative.mode == ConservativeRaster::Off ? result.facts.msaa_samples : 1;
  f.timers.set_finish_each_stage(is_cpu_rasterizer(context.renderer()));
  if (f.samples != settings.vct.msaa_samples)
    result.info["msaa_note"] = "requested " + std::to_string(settings.vct.msaa_samples) +
                               " samples; the driver's GL_MAX_FRAMEBUFFER_SAMPLES is " +
                               std::to_string(context.max_framebuffer_samples());
  if (conservative.mode != ConservativeRaster::Off)
    result.info["voxelizer"] = "conservative (" + result.facts.conservative_params + ")";
  else if (settings.vct.voxelizer == Voxelizer::Conservative)
    result.info["voxelizer"] = "gpu rule (dominant axis + MSAA; conservative_raster = gs | nv | intel for a conservative GL mode)";
  {
    // One capture of the frame when RenderDoc is injected (gl_renderdoc.h), unless the program
    // embedding the frame brackets its own (options.renderdoc_capture).
    std::optional<RenderDocFrame> capture;
    if (options.renderdoc_capture) capture.emplace();
    glCreateVertexArrays(1, &f.empty_vao);
    upload_diffuse_cone_block(f);
    shadow_pass(f);
    gbuffer_pass(f);
    voxel_passes(f);
    direct_pass(f);
    indirect_pass(f);
    particle_pass(f);
    if (options.extra_passes) options.extra_passes(f);
    label_frame_textures(f);
    glFinish();
    if (capture) capture->end();
  }
  result.timings_ms = f.timers.collect();
  double total = 0.0;
  for (const auto& [name, ms] : result.timings_ms) total += ms;
  result.timings_ms["total"] = total;
  read_back(f);
  return result;
}

FrameResult render_gl_frame(const Scene& scene, const Settings& settings, const GlOptions& options) {
  check_gl_accepts(scene, settings, options);
  GlContext context(options.device);
  return render_gl_frame(context, scene, settings, options);
}

}  // namespace vct::gl
