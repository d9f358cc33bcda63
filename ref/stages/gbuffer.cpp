#include "stages/gbuffer.h"

#include "core/parallel.h"
#include "io/run_dir.h"  // Stopwatch
#include "scene/alpha_mask.h"
#include "scene/surface.h"
#include "stages/alpha_ties.h"
#include "stages/gbuffer_ties.h"
#include "stages/raster.h"
#include "stages/texture_slack.h"
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
  g.texture_slack = Image(w, h, kSlackChannels);
  g.texture_slack.channel_names = {"normal", "albedo", "material", "emission", "direct", "alpha_tie"};
  return g;
}
// kSlackAlphaTie: pixels whose front-most surface, masks ignored, is alpha tested with an alpha
// within its freedom of the cutoff: a correct GL may show that surface or what lies behind it.
void mark_alpha_ties(const Scene& scene, const mat4& view_proj, const WindowBarycentrics& wb,
                     GBuffer& g) {
  const int w = g.depth.width, h = g.depth.height;
  const VisibilityBuffer front = render_visibility(scene.positions, scene.triangles, view_proj, w, h);
  parallel_rows(h, [&](int row) {
    for (int x = 0; x < w; ++x) {
      const size_t i = front.index(x, row);
      if (front.triangle[i] < 0) continue;
      const bool tie = alpha_test_may_flip(scene, wb, x, row, uint32_t(front.triangle[i]), front.bary[i]);
      g.texture_slack.at(x, row, kSlackAlphaTie) = tie ? 1.0f : 0.0f;
    }
  });
}

GBufferSample evaluate_pixel(const Scene& scene, const mat4& view_proj, int w, int h, int x, int row, uint32_t tri,
                             const vec3& bary, float depth, bool front_facing, SurfaceMaterial& m, SurfaceLods& lods) {
  const SurfacePoint sp = interpolate_surface(scene, tri, bary.y, bary.z);
  // Texture LOD from the exact screen-space UV derivatives at the pixel centre (GL 4.5 §8.14).
  lods = pixel_lods(scene, tri, ScreenBarycentrics(scene, tri, view_proj, w, h), x, h - 1 - row);
  m = evaluate_material(scene, sp, lods.exact);
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
  SurfaceMaterial m;
  SurfaceLods lods;
  return evaluate_pixel(scene, view_proj, width, height, x, row, triangle, bary, depth, front_facing, m, lods);
}

GBuffer render_gbuffer(const Scene& scene, const VctSettings& settings, double* ties_ms) {
  const int w = settings.width, h = settings.height;
  const mat4 view_proj = scene.camera.projection(float(w) / float(h)) * scene.camera.view();
  // Alpha-masked fragments are discarded (gbuffer.frag does the same): what lies behind shows.
  const VisibilityBuffer vb =
      render_visibility(scene.positions, scene.triangles, view_proj, w, h, &scene);
  GBuffer g = make_gbuffer(w, h);
  const WindowBarycentrics wb(view_proj, w, h);
  parallel_rows(h, [&](int row) {
    for (int x = 0; x < w; ++x) {
      const size_t i = vb.index(x, row);
      if (vb.triangle[i] < 0) continue;
      const uint32_t tri = uint32_t(vb.triangle[i]);
      SurfaceMaterial m;
      SurfaceLods lods;
      const GBufferSample sample =
          evaluate_pixel(scene, view_proj, w, h, x, row, tri, vb.bary[i], vb.depth[i], vb.front_facing[i] != 0, m, lods);
      write_sample(sample, x, row, g);
      const vec4 slack = texture_slack(scene, wb, x, row, tri, vb.bary[i], m, lods);
      for (int c = 0; c < 4; ++c) g.texture_slack.at(x, row, c) = slack[c];  // kSlackDirect: later
    }
  });
  const Stopwatch ties;
  add_tie_ranges(scene, view_proj, vb, g);
  if (scene_has_alpha_test(scene)) mark_alpha_ties(scene, view_proj, wb, g);
  if (ties_ms) *ties_ms = ties.ms();
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
