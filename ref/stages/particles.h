// Fire particles (docs/pipeline.md, "Particles"): the stateless particle function lives in
// vct_shared.h (the GL build runs the same one); here the CPU renders them additively over the
// opaque frame and adds their light into the voxels.
#pragma once

#include <vector>

#include "core/image.h"
#include "core/settings.h"
#include "core/volume.h"
#include "scene/scene.h"
#include "shared/vct_shared.h"
#include "stages/stage_types.h"

namespace vct {

/// The shared-layout block of an emitter.
sh::ParticleEmitterBlock emitter_block(const ParticleEmitter& e);

/// Every particle of every emitter at `time`, emitter by emitter, id by id.
std::vector<sh::ParticleState> particles_at(const Scene& scene, float time);

/// The additive particle layer (3 channels): each particle is a disc facing the eye (plane
/// perpendicular to eye -> centre) hit by each pixel-centre ray; it contributes
/// colour * particle_profile(rho, r) where the hit is nearer than the G-buffer depth
/// (depth test LESS against the opaque surface, no depth write). Summed in particle order.
Image render_particles(const Scene& scene, const GBuffer& g, const VctSettings& s);

/// Adds sh::particle_voxel_radiance of each particle into the RGB of the base voxel holding its
/// centre (opacity untouched: fire is translucent). Particles outside the volume are skipped.
void add_particles_to_voxels(const Scene& scene, const VctSettings& s, Volume& radiance);

/// What add_particles_to_voxels adds to an n^3 grid, particle by particle in its order: the base
/// voxel holding each particle's centre and sh::particle_voxel_radiance (particles outside the
/// volume skipped; none when the scene has no emitters or s.particles is off).
std::vector<std::pair<ivec3, vec3>> particle_voxel_light(const Scene& scene, const VctSettings& s, int n);

}  // namespace vct
