#include "stages/pipeline.h"

#include <functional>
#include <string>

#include "core/memory_budget.h"
#include "io/run_dir.h"
#include "stages/composite.h"
#include "stages/coverage_ties.h"
#include "stages/direct.h"
#include "stages/direct_slack.h"
#include "stages/gbuffer.h"
#include "stages/indirect_pass.h"
#include "stages/multibounce.h"
#include "stages/particles.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/raster.h"
#include "stages/running_mean.h"
#include "stages/shadow_map.h"
#include "stages/shadow_map_ties.h"
#include "stages/soft_shadow.h"
#include "stages/voxelize.h"

namespace vct {

namespace {
// Runs one stage and records its wall time under `name`.
void timed(FrameResult& r, const std::string& name, const std::function<void()>& stage) {
  const Stopwatch sw;
  stage();
  r.timings_ms[name] += sw.ms();
}

Voxelization run_voxelizers(const Scene& scene, const VctSettings& s, const std::vector<vec2>& positions,
                            FrameResult& r) {
  Voxelization conservative;
  timed(r, "voxelize", [&] { conservative = voxelize_conservative(scene, s.grid); });
  r.conservative_occupancy = conservative.occupancy;
  if (s.voxelizer == Voxelizer::Conservative) {
    timed(r, "coverage_ties", [&] { add_coverage_ties(scene, conservative); });
    return conservative;
  }
  Voxelization gpu;
  timed(r, "voxelize_gpu_rule", [&] { gpu = voxelize_gpu_rule(scene, s.grid, positions); });
  timed(r, "coverage_ties", [&] { add_coverage_ties(scene, gpu); });
  timed(r, "holes", [&] { r.holes = hole_map(conservative, gpu); });
  return gpu;
}

// Reduction::RunningMeanHalf: the voxels keep the exact mean (a value the racy running mean can
// leave), and the interval of every value it can leave goes where the CAS interval goes, for the
// comparison (stages/running_mean.h). The fragments' light is the last frame's: with bounces > 1
// it includes the bounce light traced in the reference's previous frame (r.bounce_input, whose
// mips build_mips rebuilds bit for bit); the particles' light is added after the reduction, as
// the frame adds it (add_light_to_interval).
void add_running_mean_interval(const Scene& scene, const Voxelization& vox, const VctSettings& s, FrameResult& r) {
  timed(r, "running_mean_interval", [&] {
    std::vector<vec3> values;
    if (r.bounce_input.voxel_count() > 0) {
      const VoxelMips previous = build_mips(r.bounce_input, s.anisotropic);
      const BounceLight bounce = make_bounce_light(scene, previous, s);
      values = fragment_radiance(scene, vox, r.shadow_maps, s, &bounce);
    } else {
      values = fragment_radiance(scene, vox, r.shadow_maps, s);
    }
    running_mean_interval_volumes(vox, values, r.voxels.cas_lo, r.voxels.cas_hi);
    add_light_to_interval(particle_voxel_light(scene, s, vox.n), r.voxels.cas_lo, r.voxels.cas_hi);
  });
}
}  // namespace

void trace_cone_stages(const Scene& scene, const VctSettings& s, FrameResult& r, int march_end) {
  FrameImages& im = r.images;
  if (s.soft_shadows)
    timed(r, "direct_soft_shadows", [&] { im.direct = shade_direct_soft(scene, r.gbuffer, r.mips, s, &im.soft_shadow); });
  timed(r, "indirect_cones", [&] {
    IndirectImages ind = trace_indirect(scene, r.gbuffer, r.mips, s, march_end);
    im.indirect_diffuse = std::move(ind.diffuse);
    im.indirect_specular = std::move(ind.specular);
    im.diffuse_cones.assign(ind.diffuse_cones.begin(), ind.diffuse_cones.end());
  });
  timed(r, "composite", [&] { composite_frame(scene, r.gbuffer, s, im); });
}

FrameResult render_ref_frame(const Scene& scene, const Settings& settings) {
  return render_ref_frame(scene, settings, {});
}

FrameResult render_ref_frame(const Scene& scene, const Settings& settings, const std::vector<vec2>& sample_positions) {
  const VctSettings& s = settings.vct;
  FrameResult r;
  r.backend = "ref";
  // What the GPU-rule emulation sampled at (recorded even when the conservative voxelizer ran).
  r.facts.msaa_samples = sample_positions.empty() ? s.msaa_samples : int(sample_positions.size());
  r.facts.msaa_samples_requested = s.msaa_samples;
  r.facts.sample_positions = sample_positions.empty() ? standard_sample_positions(s.msaa_samples) : sample_positions;
  const Stopwatch total;
  timed(r, "shadow_maps", [&] { r.shadow_maps = render_shadow_maps(scene, s); });
  // The reference's own raster alternatives in light space, for judging a test's maps.
  timed(r, "shadow_tie_ranges", [&] { add_shadow_tie_ranges(scene, s, r.shadow_maps); });
  double ties_ms = 0.0;
  timed(r, "gbuffer", [&] { r.gbuffer = render_gbuffer(scene, s, &ties_ms); });
  r.timings_ms["gbuffer"] -= ties_ms;
  r.timings_ms["gbuffer_ties"] = ties_ms;
  const Voxelization vox = run_voxelizers(scene, s, r.facts.sample_positions, r);
  {
    // Earlier frames are kept for the dumps while they stay under 256 MiB (the memory estimate
    // counts them by the same rule).
    const bool keep = keeps_multibounce_frames(s);
    MultibounceResult mb = inject_with_multibounce(scene, vox, r.shadow_maps, s, keep);
    r.multibounce_frames = std::move(mb.earlier_frames);
    r.bounce_input = std::move(mb.bounce_input);
    for (const auto& [stage, ms] : mb.timings_ms) r.timings_ms[stage] += ms;
    r.voxels = std::move(mb.grid);
    r.mips = std::move(mb.mips);
    r.multibounce_energy = std::move(mb.energy);
    r.info["multibounce_frames"] = std::to_string(mb.frames);
  }
  if (s.reduction == Reduction::RunningMeanHalf) add_running_mean_interval(scene, vox, s, r);
  r.info["fragments"] = std::to_string(vox.fragments.size());
  r.info["covered_voxels"] = std::to_string(vox.covered);
  FrameImages& im = r.images;
  if (!s.soft_shadows) {
    timed(r, "direct", [&] { im.direct = shade_direct(scene, r.gbuffer, r.shadow_maps, s); });
    // The reference's own freedom for image.direct's bound (stages/direct_slack.h).
    timed(r, "direct_slack", [&] { add_direct_texture_slack(scene, r.shadow_maps, s, im.direct, r.gbuffer); });
  }
  timed(r, "particles", [&] { im.particles = render_particles(scene, r.gbuffer, s); });
  trace_cone_stages(scene, s, r);
  r.timings_ms["total"] = total.ms();
  // The frame without the oracle's own work (vct bench's "total, VCT work" row).
  double extras = 0.0;
  for (const char* stage : kOracleExtraStages) extras += r.timings_ms.count(stage) ? r.timings_ms.at(stage) : 0.0;
  r.timings_ms["total_vct"] = r.timings_ms["total"] - extras;
  return r;
}

}  // namespace vct
