#include "freedoms/gbuffer_freedoms.h"

#include <vector>

#include "core/parallel.h"
#include "freedoms/alpha_ties.h"
#include "freedoms/gbuffer_ties.h"
#include "freedoms/texel_pieces.h"
#include "freedoms/texture_slack.h"
#include "freedoms/window_barycentrics.h"
#include "scene/alpha_mask.h"
#include "stages/gbuffer.h"

namespace vct {

namespace {
Image make_texture_slack(int w, int h) {
  Image slack(w, h, kSlackChannels);
  slack.channel_names = {"normal", "albedo", "material", "emission", "direct", "alpha_tie"};
  return slack;
}

// kSlackNormal..kSlackEmission at every covered pixel, against the material the G-buffer looked up,
// and the tie range's own part (start_tie_range) at every pixel: both read the pixel's shifted
// surface points, made once here.
void add_texture_slack_and_start_ties(const Scene& scene, const mat4& view_proj, const WindowBarycentrics& wb,
                                      const VisibilityBuffer& vb, GBuffer& g) {
  const int w = g.depth.width, h = g.depth.height;
  parallel_rows(h, [&](int row) {
    for (int x = 0; x < w; ++x) {
      const size_t i = vb.index(x, row);
      if (vb.triangle[i] < 0) {
        start_tie_range(view_proj, vb, x, row, nullptr, 0, g);
        continue;
      }
      const uint32_t tri = uint32_t(vb.triangle[i]);
      const PixelMaterial centre = pixel_material_lods_if_read(scene, view_proj, w, h, x, row, tri, vb.bary[i]);
      // The texture slack also at a point in every NEAREST texel piece of the snap square
      // (freedoms/texel_pieces.h); the tie range's positions from the first n, the centre and the
      // corners (linear there).
      thread_local std::vector<SurfacePoint> points;
      const int n = snap_surface_points(scene, wb, x, row, tri, vb.bary[i], centre.lods, points);
      const vec4 slack = texture_slack(scene, points.data(), int(points.size()), tri, centre.material, centre.lods);
      for (int c = 0; c < 4; ++c) g.texture_slack.at(x, row, c) = slack[c];
      vec3 positions[kSlackShifts];
      for (int k = 0; k < n; ++k) positions[k] = points[k].position;
      start_tie_range(view_proj, vb, x, row, positions, n, g);
    }
  });
}

// kSlackAlphaTie: pixels whose front-most surface, masks ignored, is alpha tested with an alpha
// within its freedom of the cutoff: a correct GL may show that surface or what lies behind it.
void mark_alpha_ties(const Scene& scene, const mat4& view_proj, const WindowBarycentrics& wb, GBuffer& g) {
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

void add_gbuffer_freedoms(const Scene& scene, const VctSettings& settings, const VisibilityBuffer& vb, GBuffer& g) {
  const int w = settings.width, h = settings.height;
  const mat4 view_proj = scene.camera.projection(float(w) / float(h)) * scene.camera.view();
  const WindowBarycentrics wb(view_proj, w, h);
  g.texture_slack = make_texture_slack(w, h);
  make_tie_ranges(w, h, g);
  add_texture_slack_and_start_ties(scene, view_proj, wb, vb, g);  // add_tie_ranges' first part
  widen_tie_ranges_by_alternatives(scene, view_proj, vb, g);      // and the rest
  if (scene_has_alpha_test(scene)) mark_alpha_ties(scene, view_proj, wb, g);
}

GBuffer render_gbuffer_with_freedoms(const Scene& scene, const VctSettings& settings) {
  VisibilityBuffer vb;
  GBuffer g = render_gbuffer(scene, settings, &vb);
  add_gbuffer_freedoms(scene, settings, vb, g);
  return g;
}

}  // namespace vct
