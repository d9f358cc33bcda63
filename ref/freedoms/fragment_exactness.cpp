#include "freedoms/fragment_exactness.h"

#include <cmath>

#include "core/parallel.h"
#include "freedoms/texture_slack.h"
#include "scene/surface.h"
#include "stages/light_sample.h"

namespace vct {

namespace {
// False only where no correct GL lets `light` add anything at p: behind the normal, outside a
// spot's outer cone or beyond a light's glTF range, each by kBehindLightMargin (the falloffs
// of vct_shared.h are exactly zero there).
bool light_may_reach(const Light& light, const VctSettings& settings, const vec3& p, const vec3& n) {
  const LightSample ls = sample_light(light, settings.light_model, p);
  if (glm::dot(n, ls.l) < -kBehindLightMargin) return false;
  if (light.is_spot() && glm::dot(-ls.l, light.direction) < std::cos(light.outer_cone_angle) - kBehindLightMargin)
    return false;
  // glTF's range window only (the seed model has no range).
  if (settings.light_model == LightModel::Gltf && !light.is_directional() && light.range > 0.0f &&
      ls.distance > light.range * (1.0f + kBehindLightMargin))
    return false;
  return true;
}
}  // namespace

bool fragment_light_is_exact(const Scene& scene, const VoxelFragment& f, const VctSettings& settings,
                             bool bounce) {
  if (bounce) return false;
  const Material& m = scene.materials[scene.triangle_material[f.triangle]];
  if (is_textured(m)) return false;
  const vec3 n = interpolate_surface(scene, f.triangle, f.b1, f.b2).normal;  // no normal map
  for (const Light& light : scene.lights)
    if (light_may_reach(light, settings, f.position, n)) return false;
  return true;
}

Volume voxel_exactness(const Scene& scene, const Voxelization& vox, const VctSettings& settings, bool bounce) {
  Volume v(vox.n, vox.n, vox.n, 1);
  v.channel_names = {"exact"};
  std::vector<uint8_t> exact(vox.fragments.size());
  parallel_for(int64_t(exact.size()), [&](int64_t i) {
    exact[size_t(i)] = fragment_light_is_exact(scene, vox.fragments[size_t(i)], settings, bounce);
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
