#include "stages/gbuffer.h"

#include "core/parallel.h"
#include "scene/alpha_mask.h"
#include "scene/surface.h"
#include "stages/alpha_ties.h"
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

}  // namespace

GBuffer render_gbuffer(const Scene& scene, const VctSettings& settings) {
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
      const SurfacePoint sp = interpolate_surface(scene, tri, vb.bary[i].y, vb.bary[i].z);
      // Texture LOD from the exact screen-space UV derivatives at the pixel centre (GL 4.5 §8.14).
      const SurfaceLods lods =
          pixel_lods(scene, tri, ScreenBarycentrics(scene, tri, view_proj, w, h), x, h - 1 - row);
      const SurfaceMaterial m = evaluate_material(scene, sp, lods.exact);
      const vec3 n = vb.front_facing[i] ? m.shading_normal : -m.shading_normal;
      g.position.set_rgb(x, row, sp.position);
      g.normal.set_rgb(x, row, n);
      g.albedo.set_rgb(x, row, m.albedo);
      float* mat = g.material.pixel(x, row);
      mat[0] = m.metallic;
      mat[1] = m.roughness;
      mat[2] = m.specular_factor;
      g.specular_color.set_rgb(x, row, m.specular_color);
      g.emission.set_rgb(x, row, m.emission);
      g.depth.at(x, row, 0) = vb.depth[i];
      g.coverage.at(x, row, 0) = 1.0f;
      const vec4 slack = texture_slack(scene, wb, x, row, tri, vb.bary[i], m, lods);
      for (int c = 0; c < 4; ++c) g.texture_slack.at(x, row, c) = slack[c];  // kSlackDirect: later
    }
  });
  if (scene_has_alpha_test(scene)) mark_alpha_ties(scene, view_proj, wb, g);
  return g;
}

}  // namespace vct
