#include "stages/multibounce.h"

#include <cmath>
#include <memory>

#include "io/run_dir.h"
#include "stages/cone_sets.h"
#include "stages/mips.h"
#include "stages/particles.h"

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
  add_particles_to_voxels(scene, s, g.radiance);
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
  r.grid = inject_and_reduce(scene, vox, shadow_maps, s, nullptr, &r.last_values);
  r.timings_ms["inject"] = sw.ms();
  finish_frame(scene, s, r);
  for (int frame = 1; frame < s.bounces; ++frame) {
    if (keep_frames) r.earlier_frames.push_back(r.grid.radiance);
    r.bounce_input = r.grid.radiance;
    const VoxelMips previous = std::move(r.mips);
    const BounceLight bounce = make_bounce_light(scene, previous, s);
    sw = Stopwatch();
    r.grid = inject_and_reduce(scene, vox, shadow_maps, s, &bounce, &r.last_values);
    r.timings_ms["bounce_inject"] += sw.ms();
    finish_frame(scene, s, r);
    if (multibounce_converged(r.energy, s.convergence_tolerance)) break;
  }
  return r;
}

}  // namespace vct
