#include "freedoms/reference_freedoms.h"

#include "freedoms/coverage_ties.h"
#include "freedoms/direct_slack.h"
#include "freedoms/fill_ties.h"
#include "freedoms/gbuffer_freedoms.h"
#include "freedoms/shadow_map_ties.h"
#include "freedoms/voxel_freedoms.h"
#include "io/run_dir.h"  // timed
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/multibounce.h"

namespace vct {

namespace {
using Inputs = FrameIntermediates;

void shadow_tie_ranges(const Scene& scene, const VctSettings& s, Inputs&, FrameResult& r) {
  add_shadow_tie_ranges(scene, s, r.shadow_maps);
}

void gbuffer_ties(const Scene& scene, const VctSettings& s, Inputs& in, FrameResult& r) {
  add_gbuffer_freedoms(scene, s, in.camera, r.gbuffer);
}

// With soft shadows image.direct is cone-traced: no shadow map decides it (image_judge.cpp).
void direct_slack(const Scene& scene, const VctSettings& s, Inputs& in, FrameResult& r) {
  if (!s.soft_shadows) add_direct_texture_slack(scene, r.shadow_maps, s, r.images.direct, r.gbuffer, &in.camera);
}

void coverage_ties(const Scene& scene, const VctSettings& s, Inputs& in, FrameResult& r) {
  add_coverage_ties(scene, in.voxels);
  r.voxels.occupancy_tie = occupancy_ties_with_fills(scene, in.voxels, s);
}

// The last frame's: its bounce light is rebuilt from the frame before it (r.bounce_input) as
// inject_with_multibounce built it, bit for bit (build_mips is deterministic).
void voxel_slack(const Scene& scene, const VctSettings& s, Inputs& in, FrameResult& r) {
  if (r.bounce_input.voxel_count() == 0) {
    add_voxel_freedoms(scene, in.voxels, in.fragment_light, r.shadow_maps, s, nullptr, r.voxels);
  } else {
    const VoxelMips previous = build_mips(r.bounce_input, s.anisotropic);
    const BounceLight bounce = make_bounce_light(scene, previous, s);
    add_voxel_freedoms(scene, in.voxels, in.fragment_light, r.shadow_maps, s, &bounce, r.voxels);
  }
}

// The particles' light reached the frame's voxels after the reduction: the grid without it is
// the reduction of the same fragment light again.
void particle_ties(const Scene& scene, const VctSettings& s, Inputs& in, FrameResult& r) {
  if (scene.emitters.empty() || !s.particles) return;
  const Volume before = reduce_and_fill(scene, in.voxels, in.fragment_light, s).radiance;
  add_particle_freedoms(scene, s, before, r.voxels);
}

void holes(const Scene&, const VctSettings& s, Inputs& in, FrameResult& r) {
  if (s.voxelizer == Voxelizer::GpuEmulation) r.holes = hole_map(r.conservative_occupancy, in.voxels.occupancy);
}
}  // namespace

const std::vector<FreedomStep>& freedom_steps() {
  static const std::vector<FreedomStep> steps = {
      {"shadow_tie_ranges", shadow_tie_ranges}, {"gbuffer_ties", gbuffer_ties},   {"direct_slack", direct_slack},
      {"coverage_ties", coverage_ties},         {"voxel_slack", voxel_slack},     {"particle_ties", particle_ties},
      {"holes", holes},
  };
  return steps;
}

void add_reference_freedoms(const Scene& scene, const VctSettings& settings, VctFrame& frame) {
  auto& timings = frame.result.timings_ms;
  double total = 0.0;
  for (const FreedomStep& step : freedom_steps()) {
    timed(timings, step.timing, [&] { step.add(scene, settings, frame.intermediates, frame.result); });
    total += timings[step.timing];
  }
  timings["total_oracle"] = total;  // the steps' sum: `vct bench`'s oracle group adds up to it
}

}  // namespace vct
