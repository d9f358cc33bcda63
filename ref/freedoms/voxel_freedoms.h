// The judge's volumes beside the reduced voxels (docs/compare.md, "Voxel shading slack", "Exact
// voxels", "Coverage ties", "cas-rgba8-interval"): how far each voxel's light may move between
// correct GLs, which voxels must match bit for bit, and the interval a racy reduction may leave.
// The oracle's own work: the injection (stages/inject.h) computes none of it.
#pragma once

#include <vector>

#include "core/settings.h"
#include "core/volume.h"
#include "scene/scene.h"
#include "stages/inject.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// Fills g.shading_slack, g.exact and g.fragment_count_range for the grid inject_and_reduce made from the fragments' light
/// `values` on `vox` (whose coverage ties freedoms/coverage_ties.h has added) with `maps` and
/// `bounce`, widened where the coverage ties let the fragment set change, and g.cas_lo / g.cas_hi
/// for a racy reduction (freedoms/reduction_interval.h). Before the particles' light.
void add_voxel_freedoms(const Scene& scene, const Voxelization& vox, const std::vector<vec3>& values,
                        const std::vector<ShadowMap>& maps, const VctSettings& settings, const BounceLight* bounce,
                        VoxelGrid& g);

/// What the particles' light (stages/multibounce.h add_particles_to_grid) does to those volumes:
/// a voxel whose radiance it changed (`before`, the radiance without it, against g.radiance) is no
/// longer exact (float arithmetic on both sides), and the reduction's interval moves with it,
/// since GL's resolve adds the particles to the reduced value (gl/shaders/voxel_resolve.comp; an
/// interval without them fails every voxel near a fire: demo_room, docs/compare.md's
/// `cas-rgba8-interval` row).
void add_particle_freedoms(const Scene& scene, const VctSettings& settings, const Volume& before, VoxelGrid& g);

/// The grid as the judge reads it: inject_and_reduce on `vox` (whose coverage ties
/// add_coverage_ties has added), its freedoms, then the particles and theirs.
VoxelGrid judged_voxels(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                        const VctSettings& settings, const BounceLight* bounce = nullptr);

}  // namespace vct
