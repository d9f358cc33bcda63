#include "stages/pipeline.h"

#include <string>

#include "core/memory_budget.h"  // keeps_multibounce_frames
#include "io/run_dir.h"  // Stopwatch, timed
#include "stages/composite.h"
#include "stages/direct.h"
#include "stages/gbuffer.h"
#include "stages/indirect_pass.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/multibounce.h"
#include "stages/particles.h"
#include "stages/shadow_map.h"
#include "stages/soft_shadow.h"
#include "stages/voxelize.h"

namespace vct {

namespace {
// The voxelization the frame injects. The conservative one always runs: its occupancy is a
// reference-only stage (voxel.conservative_occupancy) the judge reads for both voxelizers.
Voxelization run_voxelizers(const Scene& scene, const VctSettings& s, const std::vector<vec2>& positions,
                            FrameResult& r) {
  Voxelization conservative;
  timed(r.timings_ms, "voxelize", [&] { conservative = voxelize_conservative(scene, s.grid); });
  r.conservative_occupancy = conservative.occupancy;
  if (s.voxelizer == Voxelizer::Conservative) return conservative;
  Voxelization gpu;
  timed(r.timings_ms, "voxelize_gpu_rule", [&] { gpu = voxelize_gpu_rule(scene, s.grid, positions); });
  return gpu;
}

// Injection, reduction, multibounce, particles and mips into r; returns the last frame's light per
// fragment.
std::vector<vec3> run_voxel_light(const Scene& scene, const Voxelization& vox, const VctSettings& s, FrameResult& r) {
  // Earlier frames are kept for the dumps while they stay under 256 MiB (the memory estimate
  // counts them by the same rule).
  MultibounceResult mb = inject_with_multibounce(scene, vox, r.shadow_maps, s, keeps_multibounce_frames(s));
  r.multibounce_frames = std::move(mb.earlier_frames);
  r.bounce_input = std::move(mb.bounce_input);
  for (const auto& [stage, ms] : mb.timings_ms) r.timings_ms[stage] += ms;
  r.voxels = std::move(mb.grid);
  r.mips = std::move(mb.mips);
  r.multibounce_energy = std::move(mb.energy);
  r.info["multibounce_frames"] = std::to_string(mb.frames);
  r.info["fragments"] = std::to_string(vox.fragments.size());
  r.info["covered_voxels"] = std::to_string(vox.covered);
  return std::move(mb.last_values);
}
}  // namespace

void trace_cone_stages(const Scene& scene, const VctSettings& s, FrameResult& r, int march_end) {
  trace_cone_stages(scene, s, r, r.mips, march_end);
}

void trace_cone_stages(const Scene& scene, const VctSettings& s, FrameResult& r, const VoxelMips& mips,
                       int march_end) {
  FrameImages& im = r.images;
  if (s.soft_shadows)
    timed(r.timings_ms, "direct_soft_shadows",
          [&] { im.direct = shade_direct_soft(scene, r.gbuffer, mips, s, &im.soft_shadow); });
  timed(r.timings_ms, "indirect_cones", [&] {
    IndirectImages ind = trace_indirect(scene, r.gbuffer, mips, s, march_end);
    im.indirect_diffuse = std::move(ind.diffuse);
    im.indirect_specular = std::move(ind.specular);
    im.diffuse_cones.assign(ind.diffuse_cones.begin(), ind.diffuse_cones.end());
  });
  timed(r.timings_ms, "composite", [&] { composite_frame(scene, r.gbuffer, s, im); });
}

VctFrame run_vct_frame(const Scene& scene, const Settings& settings, const std::vector<vec2>& sample_positions) {
  const VctSettings& s = settings.vct;
  VctFrame frame;
  FrameResult& r = frame.result;
  r.backend = "ref";
  // What the GPU-rule emulation sampled at (recorded even when the conservative voxelizer ran).
  r.facts.msaa_samples = sample_positions.empty() ? s.msaa_samples : int(sample_positions.size());
  r.facts.msaa_samples_requested = s.msaa_samples;
  r.facts.sample_positions = sample_positions.empty() ? standard_sample_positions(s.msaa_samples) : sample_positions;
  const Stopwatch total;
  timed(r.timings_ms, "shadow_maps", [&] { r.shadow_maps = render_shadow_maps(scene, s); });
  timed(r.timings_ms, "gbuffer", [&] { r.gbuffer = render_gbuffer(scene, s, &frame.intermediates.camera); });
  frame.intermediates.voxels = run_voxelizers(scene, s, r.facts.sample_positions, r);
  frame.intermediates.fragment_light = run_voxel_light(scene, frame.intermediates.voxels, s, r);
  FrameImages& im = r.images;
  if (!s.soft_shadows) timed(r.timings_ms, "direct", [&] { im.direct = shade_direct(scene, r.gbuffer, r.shadow_maps, s); });
  timed(r.timings_ms, "particles", [&] { im.particles = render_particles(scene, r.gbuffer, s); });
  trace_cone_stages(scene, s, r);
  r.timings_ms["total_vct"] = total.ms();
  return frame;
}

}  // namespace vct
