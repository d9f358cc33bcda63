#include "stages/multibounce.h"

#include <cmath>
#include <memory>

#include "io/run_dir.h"
#include "stages/cone_sets.h"
#include "stages/mips.h"
#include "stages/particles.h"
#include "stages/running_mean.h"

namespace vct {

BounceLight make_bounce_light(const Scene& scene, const VoxelMips& previous, const VctSettings& s) {
  // Built once per bounce frame, shared by every copy of the callback (the voxel loop only traces).
  const auto cones = std::make_shared<const ConeFrame>(previous, scene.volume, s, kBounceMinLod);
  return [cones, s](const VoxelFragment& f, const SurfaceMaterial& m) -> vec3 {
    const DiffuseConeSet set = cones->diffuse(f.position, m.shading_normal, 0.0f);
    return s.restitution * m.albedo * set.radiance;
  };
}

double total_energy(const Volume& radiance) {
  double sum = 0.0;
  const size_t count = radiance.voxel_count();
  for (size_t i = 0; i < count; ++i) {
    const float* p = &radiance.data[i * size_t(radiance.channels)];
    sum += double(p[0]) + double(p[1]) + double(p[2]);
  }
  return sum;
}

void add_particles_to_grid(const Scene& scene, const VctSettings& s, VoxelGrid& g) {
  if (scene.emitters.empty()) return;
  const Volume before = g.radiance;
  add_particles_to_voxels(scene, s, g.radiance);
  if (g.cas_lo.voxel_count() == g.radiance.voxel_count() && g.cas_hi.voxel_count() == g.radiance.voxel_count())
    add_light_to_interval(particle_voxel_light(scene, s, g.radiance.nx), g.cas_lo, g.cas_hi);
  if (g.exact.voxel_count() != g.radiance.voxel_count()) return;
  for (size_t i = 0; i < g.exact.voxel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      if (g.radiance.data[i * 4 + size_t(c)] != before.data[i * 4 + size_t(c)]) g.exact.data[i] = 0.0f;
}

namespace {
void finish_frame(const Scene& scene, const VctSettings& s, MultibounceResult& r) {
  Stopwatch sw;
  add_particles_to_grid(scene, s, r.grid);
  r.timings_ms["particles_voxels"] += sw.ms();
  sw = Stopwatch();
  r.mips = build_mips(r.grid.radiance, s.anisotropic);
  r.timings_ms["mips"] += sw.ms();
  r.energy.push_back(total_energy(r.grid.radiance));
  ++r.frames;
}
}  // namespace

bool multibounce_converged(const std::vector<double>& energy, float tolerance) {
  if (tolerance <= 0.0f || energy.size() < 2) return false;
  const double before = energy[energy.size() - 2], now = energy.back();
  return std::abs(now - before) <= double(tolerance) * std::abs(before);
}

MultibounceResult inject_with_multibounce(const Scene& scene, const Voxelization& vox,
                                          const std::vector<ShadowMap>& shadow_maps, const VctSettings& s,
                                          bool keep_frames) {
  MultibounceResult r;
  Stopwatch sw;
  // Only the last frame's voxels are judged; which frame is last is known in advance unless the
  // loop may stop early on convergence.
  const auto judged = [&](int frame) { return frame == s.bounces - 1 || s.convergence_tolerance > 0.0f; };
  double slack_ms = 0.0;
  r.grid = inject_and_reduce(scene, vox, shadow_maps, s, nullptr, {judged(0), &slack_ms});
  r.timings_ms["inject"] = sw.ms() - slack_ms;
  r.timings_ms["voxel_slack"] = slack_ms;
  finish_frame(scene, s, r);
  for (int frame = 1; frame < s.bounces; ++frame) {
    if (keep_frames) r.earlier_frames.push_back(r.grid.radiance);
    r.bounce_input = r.grid.radiance;
    const VoxelMips previous = std::move(r.mips);
    const BounceLight bounce = make_bounce_light(scene, previous, s);
    sw = Stopwatch();
    r.grid = inject_and_reduce(scene, vox, shadow_maps, s, &bounce, {judged(frame), &slack_ms});
    r.timings_ms["bounce_inject"] += sw.ms() - slack_ms;
    r.timings_ms["voxel_slack"] += slack_ms;
    finish_frame(scene, s, r);
    if (multibounce_converged(r.energy, s.convergence_tolerance)) break;
  }
  return r;
}

}  // namespace vct
