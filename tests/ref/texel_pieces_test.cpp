// freedoms/texel_pieces.h: the camera's NEAREST texel pieces inside the snap square, on the case
// that needed them (scenes/regressions/seed-259-medium).
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

#include "freedoms/texel_pieces.h"
#include "freedoms/window_barycentrics.h"
#include "scene/gltf_loader.h"
#include "scene/surface.h"
#include "stages/raster.h"

namespace vct {
namespace {

float distance_inf(const vec3& a, const vec3& b) {
  const vec3 d = glm::abs(a - b);
  return std::max(d.x, std::max(d.y, d.z));
}

// One fold triangle with a 5 x 32 normal map, NEAREST without mipmaps, 114 texel rows over a few
// pixels of a 42 x 77 image. At pixel (4, row 60) llvmpipe showed the normal (-0.7716, 0.3958,
// 0.4980): no point among the centre and the snap square's corners reads its texel; a point of
// one of the square's texel pieces does.
TEST(TexelPieces, ReachTheTexelLlvmpipeReadBetweenTheCorners) {
  const Scene s = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-259-medium/scene.gltf");
  const int w = 42, h = 77, x = 4, row = 60;  // the camera's aspectRatio (0.545) sets the width
  const mat4 view_proj = s.camera.projection(float(w) / float(h)) * s.camera.view();
  const VisibilityBuffer vb = render_visibility(s.positions, s.triangles, view_proj, w, h);
  const size_t i = vb.index(x, row);
  ASSERT_GE(vb.triangle[i], 0);
  const uint32_t tri = uint32_t(vb.triangle[i]);
  const WindowBarycentrics wb(view_proj, w, h);
  const vec3 gl_normal(-0.7716134f, 0.3957756f, 0.4979702f);
  const auto normal_at = [&](const SurfacePoint& p) {
    const vec3 n = evaluate_material(s, p, SlotLods()).shading_normal;
    return vb.front_facing[i] ? n : -n;
  };
  SurfacePoint corners[kSlackShifts];
  const int n = shifted_surface_points(s, wb, x, row, tri, vb.bary[i], corners);
  ASSERT_EQ(n, kSlackShifts);
  float corner_best = INFINITY;
  for (int k = 0; k < n; ++k) corner_best = std::min(corner_best, distance_inf(normal_at(corners[k]), gl_normal));
  EXPECT_GT(corner_best, 0.1f);  // the corners miss it
  std::vector<SurfacePoint> pieces;
  texel_piece_points(s, wb, x, row, tri, vb.bary[i], SurfaceLods(), pieces);
  EXPECT_GT(pieces.size(), 4u);
  float piece_best = INFINITY;
  for (const SurfacePoint& p : pieces) piece_best = std::min(piece_best, distance_inf(normal_at(p), gl_normal));
  EXPECT_LT(piece_best, 0.01f);  // a piece reads it (8-bit texels: within a step's effect)
}

}  // namespace
}  // namespace vct
