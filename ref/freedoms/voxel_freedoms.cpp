#include "freedoms/voxel_freedoms.h"

#include "freedoms/coverage_ties.h"  // widen_for_coverage_ties
#include "freedoms/fragment_exactness.h"
#include "freedoms/fragment_slack.h"
#include "freedoms/reduction_interval.h"
#include "stages/multibounce.h"
#include "stages/particles.h"

namespace vct {

void add_voxel_freedoms(const Scene& scene, const Voxelization& vox, const std::vector<vec3>& values,
                        const std::vector<ShadowMap>& maps, const VctSettings& settings, const BounceLight* bounce,
                        VoxelGrid& g) {
  const std::vector<float> slack = fragment_shading_slack(scene, vox, maps, settings, bounce);
  g.shading_slack = voxel_shading_slack(vox, slack);
  g.exact = voxel_exactness(scene, vox, settings, bounce && *bounce);
  widen_for_coverage_ties(scene, vox, values, slack, maps, settings, bounce, g.shading_slack, g.exact);
  g.fragment_count_range = fragment_count_ranges(vox);
  add_reduction_interval(vox, values, settings, g);
}

void add_particle_freedoms(const Scene& scene, const VctSettings& settings, const Volume& before, VoxelGrid& g) {
  const auto light = particle_voxel_light(scene, settings, g.radiance.nx);
  if (light.empty()) return;
  if (g.cas_lo.voxel_count() == g.radiance.voxel_count() && g.cas_hi.voxel_count() == g.radiance.voxel_count())
    add_light_to_interval(light, g.cas_lo, g.cas_hi);
  if (g.exact.voxel_count() != g.radiance.voxel_count()) return;
  for (size_t i = 0; i < g.exact.voxel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      if (g.radiance.data[i * 4 + size_t(c)] != before.data[i * 4 + size_t(c)]) g.exact.data[i] = 0.0f;
}

VoxelGrid judged_voxels(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                        const VctSettings& settings, const BounceLight* bounce) {
  std::vector<vec3> values;
  VoxelGrid g = inject_and_reduce(scene, vox, maps, settings, bounce, &values);
  add_voxel_freedoms(scene, vox, values, maps, settings, bounce, g);
  const Volume before = g.radiance;
  add_particles_to_grid(scene, settings, g);
  add_particle_freedoms(scene, settings, before, g);
  return g;
}

}  // namespace vct
