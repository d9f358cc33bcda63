// Temporal multibounce (docs/pipeline.md, "Multibounce"): frame 1 injects direct light and
// emission; frame k injects, in addition, restitution x albedo x the diffuse cone set traced in
// frame k-1's mips at level >= 1. Particles are added after every reduction.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/inject.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// Level the bounce cones start at: the seed rewrites level 0 while it voxelizes, so only the
/// coarser levels of the previous frame are readable; we keep that rule.
constexpr float kBounceMinLod = 1.0f;

/// The light a fragment gets from the previous frame's mips: restitution x albedo x (diffuse cone
/// set at the fragment, normal = the material's shading normal, no rotation, lod >= 1).
/// The light reads `previous` when called: it must outlive the BounceLight (a temporary may not
/// bind, hence the deleted overload; ASan found a test that passed build_mips(...) directly).
BounceLight make_bounce_light(const Scene& scene, const VoxelMips& previous, const VctSettings& s);
BounceLight make_bounce_light(const Scene& scene, VoxelMips&& previous, const VctSettings& s) = delete;

/// Adds the particles' light to a reduced grid as the frame does (add_particles_to_voxels); what
/// that does to the judge's volumes beside it is freedoms/voxel_freedoms.h's add_particle_freedoms.
void add_particles_to_grid(const Scene& scene, const VctSettings& s, VoxelGrid& g);

/// Total RGB radiance summed over the base level (the energy recorded per frame), in a fixed
/// order (double accumulation, voxel order).
double total_energy(const Volume& radiance);

/// The one stop rule both backends use (the GL pass calls it too, so near the threshold both run
/// the same number of frames): true when tolerance > 0, at least two frames ran, and
/// |E_k - E_{k-1}| <= tolerance * E_{k-1} (a dark scene, E = 0 twice, has converged).
bool multibounce_converged(const std::vector<double>& energy, float tolerance);

struct MultibounceResult {
  VoxelGrid grid;   // the last frame's base level (particles included)
  VoxelMips mips;   // its mips
  std::vector<double> energy;  // total_energy after each frame
  std::vector<Volume> earlier_frames;  // base level of each frame before the last (if kept)
  Volume bounce_input;  // the base level the last frame's bounce light came from (frames > 1)
  std::vector<vec3> last_values;  // the last frame's fragment light (inject_and_reduce's values_out)
  int frames = 0;
  std::map<std::string, double> timings_ms;  // "inject", "mips", "particles_voxels", "bounce_inject"
};

/// Runs frame 1 and then up to settings.bounces - 1 bounce frames; stops early when
/// convergence_tolerance > 0 and |E_k - E_{k-1}| <= tolerance * E_{k-1}.
/// `keep_frames`: also return the earlier frames' base levels (for dumps).
MultibounceResult inject_with_multibounce(const Scene& scene, const Voxelization& vox,
                                          const std::vector<ShadowMap>& shadow_maps, const VctSettings& s,
                                          bool keep_frames = false);

}  // namespace vct
