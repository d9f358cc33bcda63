#include "stages/gbuffer.h"

#include "core/parallel.h"
#include "scene/surface.h"
#include "stages/raster.h"
#include "stages/uv_derivatives.h"

namespace vct {

namespace {
GBuffer make_gbuffer(int w, int h) {
  GBuffer g;
  g.position = Image(w, h, 3);
  g.position.channel_names = {"X", "Y", "Z"};
  g.normal = Image(w, h, 3);
  g.normal.channel_names = {"X", "Y", "Z"};
  g.albedo = Image(w, h, 3);
  g.albedo.channel_names = {"R", "G", "B"};
  g.material = Image(w, h, 4);
  g.material.channel_names = {"metallic", "roughness", "specular", "unused"};
  g.specular_color = Image(w, h, 3);
  g.specular_color.channel_names = {"R", "G", "B"};
  g.emission = Image(w, h, 3);
  g.emission.channel_names = {"R", "G", "B"};
  g.depth = Image(w, h, 1, 1.0f);
  g.depth.channel_names = {"Z"};
  g.coverage = Image(w, h, 1);
  g.coverage.channel_names = {"Y"};
  return g;
}
GBufferSample evaluate_pixel(const Scene& scene, const mat4& view_proj, int w, int h, int x, int row, uint32_t tri,
                             const vec3& bary, float depth, bool front_facing) {
  const SurfacePoint sp = interpolate_surface(scene, tri, bary.y, bary.z);
  // Untextured: the material at sp itself (pixel_material_lods_if_read's, without interpolating again).
  const SurfaceMaterial m = material_reads_lods(scene.materials[scene.triangle_material[tri]])
                                ? pixel_material(scene, view_proj, w, h, x, row, tri, bary).material
                                : evaluate_material(scene, sp);
  const vec3 n = front_facing ? m.shading_normal : -m.shading_normal;
  GBufferSample s;
  float* v = s.values;
  *v++ = 1.0f;  // coverage
  *v++ = depth;
  for (int c = 0; c < 3; ++c) *v++ = sp.position[c];
  for (int c = 0; c < 3; ++c) *v++ = n[c];
  for (int c = 0; c < 3; ++c) *v++ = m.albedo[c];
  *v++ = m.metallic;
  *v++ = m.roughness;
  *v++ = m.specular_factor;
  *v++ = 0.0f;
  for (int c = 0; c < 3; ++c) *v++ = m.specular_color[c];
  for (int c = 0; c < 3; ++c) *v++ = m.emission[c];
  return s;
}

void write_sample(const GBufferSample& s, int x, int row, GBuffer& g) {
  const float* v = s.values;
  Image* images[] = {&g.coverage, &g.depth, &g.position, &g.normal, &g.albedo, &g.material, &g.specular_color, &g.emission};
  for (Image* im : images)
    for (int c = 0; c < im->channels; ++c) im->at(x, row, c) = *v++;
}

}  // namespace

GBufferSample gbuffer_sample(const Scene& scene, const mat4& view_proj, int width, int height, int x, int row,
                             uint32_t triangle, const vec3& bary, float depth, bool front_facing) {
  return evaluate_pixel(scene, view_proj, width, height, x, row, triangle, bary, depth, front_facing);
}

PixelMaterial pixel_material(const Scene& scene, const mat4& view_proj, int width, int height, int x, int row,
                             uint32_t triangle, const vec3& bary) {
  const SurfacePoint sp = interpolate_surface(scene, triangle, bary.y, bary.z);
  PixelMaterial p;
  // Texture LOD from the exact screen-space UV derivatives at the pixel centre (GL 4.5 §8.14).
  p.lods = pixel_lods(scene, triangle, ScreenBarycentrics(scene, triangle, view_proj, width, height), x,
                      height - 1 - row);
  p.material = evaluate_material(scene, sp, p.lods.exact);
  return p;
}

PixelMaterial pixel_material_lods_if_read(const Scene& scene, const mat4& view_proj, int width, int height, int x,
                                          int row, uint32_t triangle, const vec3& bary) {
  if (material_reads_lods(scene.materials[scene.triangle_material[triangle]]))
    return pixel_material(scene, view_proj, width, height, x, row, triangle, bary);
  PixelMaterial p;
  p.material = evaluate_material(scene, interpolate_surface(scene, triangle, bary.y, bary.z));
  return p;
}

GBuffer render_gbuffer(const Scene& scene, const VctSettings& settings, VisibilityBuffer* visibility) {
  const int w = settings.width, h = settings.height;
  const mat4 view_proj = scene.camera.projection(float(w) / float(h)) * scene.camera.view();
  // Alpha-masked fragments are discarded (gbuffer.frag does the same): what lies behind shows.
  const VisibilityBuffer vb =
      render_visibility(scene.positions, scene.triangles, view_proj, w, h, &scene);
  GBuffer g = make_gbuffer(w, h);
  parallel_rows(h, [&](int row) {
    for (int x = 0; x < w; ++x) {
      const size_t i = vb.index(x, row);
      if (vb.triangle[i] < 0) continue;
      const uint32_t tri = uint32_t(vb.triangle[i]);
      write_sample(evaluate_pixel(scene, view_proj, w, h, x, row, tri, vb.bary[i], vb.depth[i], vb.front_facing[i] != 0),
                   x, row, g);
    }
  });
  if (visibility) *visibility = vb;
  return g;
}

SurfaceMaterial gbuffer_material(const GBuffer& g, int x, int y) {
  SurfaceMaterial m;
  m.albedo = g.albedo.rgb(x, y);
  m.metallic = g.material.at(x, y, 0);
  m.roughness = g.material.at(x, y, 1);
  m.specular_factor = g.material.at(x, y, 2);
  m.specular_color = g.specular_color.rgb(x, y);
  // A partial G-buffer (an engine's stage set, docs/external_format.md) may have no emission.
  if (!g.emission.empty()) m.emission = g.emission.rgb(x, y);
  m.shading_normal = g.normal.rgb(x, y);
  return m;
}

}  // namespace vct
