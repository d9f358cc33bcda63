#include "freedoms/fragment_exactness.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"
#include "freedoms/snap_window.h"
#include "freedoms/texture_slack.h"
#include "scene/surface.h"
#include "stages/light_sample.h"

namespace vct {

namespace {
// The fragment's point at one corner of its snap square (freedoms/snap_window.h): its position and
// its interpolated normal before normalisation, Σ b_i n_i, which is affine in the window offset.
struct SnapCorner {
  vec3 position{0.0f};
  glm::dvec3 normal{0.0};
};

// The point at fragment g's barycentrics.
SnapCorner corner_of(const Scene& scene, const VoxelFragment& g) {
  const uvec3 t = scene.triangles[g.triangle];
  const double b1 = double(g.b1), b2 = double(g.b2);
  return {g.position, (1.0 - b1 - b2) * glm::dvec3(scene.normals[t.x]) + b1 * glm::dvec3(scene.normals[t.y]) +
                          b2 * glm::dvec3(scene.normals[t.z])};
}

// The fragment's own point: shifted_fragment at offset (0, 0), without the window.
SnapCorner snap_corner_at_centre(const Scene& scene, const VoxelFragment& f) {
  VoxelFragment g = f;
  g.position = interpolate_surface(scene, f.triangle, f.b1, f.b2).position;
  return corner_of(scene, g);
}

SnapCorner snap_corner(const Scene& scene, const SnapWindow& w, const VoxelFragment& f, double du, double dv) {
  return corner_of(scene, shifted_fragment(scene, w, f, du, dv));
}

// False only where no correct GL lets `light` add anything anywhere the snap may put the fragment:
// behind the normal, outside a spot's outer cone or beyond a light's glTF range over the whole
// snap square, each by kBehindLightMargin (the falloffs of vct_shared.h are exactly zero there).
// The normal's n.l is affine over the square for a fixed light direction and |n| convex, so
// n.l / |n| <= M / N, M the largest corner n.l (< 0) and N the largest corner |n|; the light
// direction's own change over the square (|Δp| / distance) is added to the margin, twice.
bool light_may_reach(const Light& light, const VctSettings& settings, const SnapCorner* corners, int count) {
  const bool ranged = settings.light_model == LightModel::Gltf && !light.is_directional() && light.range > 0.0f;
  bool outside_cone = light.is_spot(), beyond_range = ranged;
  double top = -std::numeric_limits<double>::infinity(), longest = 0.0, moved = 0.0;
  for (int k = 0; k < count; ++k) {
    const LightSample ls = sample_light(light, settings.light_model, corners[k].position);
    outside_cone = outside_cone &&
                   glm::dot(-ls.l, light.direction) < std::cos(light.outer_cone_angle) - kBehindLightMargin;
    beyond_range = beyond_range && ls.distance > light.range * (1.0f + kBehindLightMargin);
    top = std::max(top, glm::dot(corners[k].normal, glm::dvec3(ls.l)));
    longest = std::max(longest, glm::length(corners[k].normal));
    if (!light.is_directional())
      moved = std::max(moved, double(glm::length(corners[k].position - corners[0].position)) / double(ls.distance));
  }
  const bool behind = top < -(double(kBehindLightMargin) + 2.0 * moved) * longest;
  return !(behind || outside_cone || beyond_range);
}
}  // namespace

bool fragment_light_is_exact(const Scene& scene, const VoxelFragment& f, const VctSettings& settings, int grid,
                             bool bounce) {
  if (bounce) return false;
  const Material& m = scene.materials[scene.triangle_material[f.triangle]];
  if (is_textured(m)) return false;
  // A light that reaches the reference's own point reaches the square (its corners' largest n.l
  // and |n| are at least the centre's): most fragments are lit, and end here without the square.
  const SnapCorner centre = snap_corner_at_centre(scene, f);
  for (const Light& light : scene.lights)
    if (light_may_reach(light, settings, &centre, 1)) return false;
  if (scene.lights.empty()) return true;
  // Where the snap's reach has no bound (a sliver, SnapWindow::bounded) GL's point may lie anywhere
  // in the triangle's plane: the light there is not certain.
  SnapWindow w;
  if (!snap_window(scene, grid, f, w) || !w.bounded) return false;
  const double r = w.reach;
  const SnapCorner corners[5] = {centre, snap_corner(scene, w, f, -r, -r), snap_corner(scene, w, f, r, -r),
                                 snap_corner(scene, w, f, -r, r), snap_corner(scene, w, f, r, r)};
  for (const Light& light : scene.lights)
    if (light_may_reach(light, settings, corners, 5)) return false;
  return true;
}

Volume voxel_exactness(const Scene& scene, const Voxelization& vox, const VctSettings& settings, bool bounce) {
  Volume v(vox.n, vox.n, vox.n, 1);
  v.channel_names = {"exact"};
  std::vector<uint8_t> exact(vox.fragments.size());
  parallel_for(int64_t(exact.size()), [&](int64_t i) {
    exact[size_t(i)] = fragment_light_is_exact(scene, vox.fragments[size_t(i)], settings, vox.n, bounce);
  });
  // Runs of fragments per voxel (sorted by voxel): exact when all of them are.
  size_t b = 0;
  while (b < vox.fragments.size()) {
    size_t e = b;
    bool all = true;
    for (; e < vox.fragments.size() && vox.fragments[e].voxel == vox.fragments[b].voxel; ++e)
      all = all && exact[e] != 0;
    const ivec3 c = vox.fragments[b].voxel;
    *v.voxel(c.x, c.y, c.z) = all ? 1.0f : 0.0f;
    b = e;
  }
  return v;
}

}  // namespace vct
