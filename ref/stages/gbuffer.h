// The camera G-buffer: the software rasterizer's closest surface per pixel centre, then the one
// surface definition (scene/surface.h: interpolation, textures, normal mapping) evaluated there.
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "stages/raster.h"
#include "stages/stage_types.h"

namespace vct {

/// Every G-buffer stage's value at one pixel centre (the channels of GBuffer's images, in the
/// order coverage, depth, position, normal, albedo, material, specular colour, emission).
constexpr int kGbufferSampleValues = 1 + 1 + 3 + 3 + 3 + 4 + 3 + 3;
struct GBufferSample {
  float values[kGbufferSampleValues] = {};  // zero coverage, depth 1: an empty pixel
  GBufferSample() { values[1] = 1.0f; }
};

/// What the G-buffer holds at image pixel (x, row) (row 0 = top) of a width x height view when
/// `triangle` covers it with window depth `depth` and perspective-correct barycentrics `bary` at
/// the centre, facing as given (render_gbuffer's per-pixel evaluation).
GBufferSample gbuffer_sample(const Scene& scene, const mat4& view_proj, int width, int height, int x, int row,
                             uint32_t triangle, const vec3& bary, float depth, bool front_facing);

/// The material `triangle` shows at image pixel (x, row)'s centre (barycentrics `bary`) and the
/// texture LODs it was looked up at (the G-buffer's own; the texture slack tries the others).
struct PixelMaterial {
  SurfaceMaterial material;
  SurfaceLods lods;
};
PixelMaterial pixel_material(const Scene& scene, const mat4& view_proj, int width, int height, int x, int row,
                             uint32_t triangle, const vec3& bary);

/// pixel_material, with the LODs computed only where the material reads them: an untextured
/// material gets default lods (any lods give it, bit for bit: scene/surface.h, material_reads_lods).
/// For callers that use the lods only through evaluate_material (the G-buffer, the texture slack).
PixelMaterial pixel_material_lods_if_read(const Scene& scene, const mat4& view_proj, int width, int height, int x,
                                          int row, uint32_t triangle, const vec3& bary);

/// The material of a G-buffer pixel, as the BRDF sees it (direct light, soft shadows, their ties).
SurfaceMaterial gbuffer_material(const GBuffer& g, int x, int y);

/// settings.width x settings.height view through scene.camera (projection aspect = width/height).
/// Normals face the camera: back-facing triangles (clockwise in window space, GL's
/// gl_FrontFacing == false) get their shading normal negated.
/// The judge's images beside it (texture_slack, tie_range) are the oracle's own work
/// (freedoms/gbuffer_freedoms.h); `visibility`, when given, receives the raster they start from.
GBuffer render_gbuffer(const Scene& scene, const VctSettings& settings, VisibilityBuffer* visibility = nullptr);

}  // namespace vct
