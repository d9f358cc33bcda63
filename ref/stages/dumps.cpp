#include "stages/dumps.h"

#include <algorithm>
#include <string>

namespace vct {

namespace {

// Range of the values a mask says are meaningful (for PNG previews of depth and positions).
void value_range(const Image& img, float& lo, float& hi, float empty_value) {
  lo = 1e30f;
  hi = -1e30f;
  for (float v : img.data) {
    if (v == empty_value) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (lo > hi) lo = 0.0f, hi = 1.0f;
  if (lo == hi) hi = lo + 1.0f;
}

void write_shadow_maps(RunDir& dir, const FrameResult& f) {
  for (size_t i = 0; i < f.shadow_maps.size(); ++i) {
    float lo, hi;
    value_range(f.shadow_maps[i].depth, lo, hi, 1.0f);
    dir.write_data("shadow_map_" + std::to_string(i), f.shadow_maps[i].depth, lo, 1.0f);
  }
}

void write_gbuffer(RunDir& dir, const GBuffer& g, const Scene& scene) {
  if (g.coverage.empty()) return;
  const float lo = std::min({scene.bounds.lo.x, scene.bounds.lo.y, scene.bounds.lo.z});
  const float hi = std::max({scene.bounds.hi.x, scene.bounds.hi.y, scene.bounds.hi.z});
  dir.write_data("gbuffer_position", g.position, lo, hi);
  dir.write_data("gbuffer_normal", g.normal, -1.0f, 1.0f);
  dir.write_color("gbuffer_albedo", g.albedo);
  dir.write_data("gbuffer_material", g.material, 0.0f, 1.0f);
  dir.write_color("gbuffer_specular_color", g.specular_color);
  dir.write_color("gbuffer_emission", g.emission);
  float dlo, dhi;
  value_range(g.depth, dlo, dhi, 1.0f);
  dir.write_data("gbuffer_depth", g.depth, dlo, 1.0f);
  dir.write_data("gbuffer_coverage", g.coverage, 0.0f, 1.0f);
}

void write_volumes(RunDir& dir, const FrameResult& f, const Scene& scene) {
  const VoxelGrid& v = f.voxels;
  if (v.n <= 0) return;
  const float spacing0 = scene.volume.size / float(v.n);
  if (!v.fragments.data.empty()) {
    Volume occ(v.n, v.n, v.n, 1);
    occ.channel_names = {"occupancy"};
    for (size_t i = 0; i < occ.data.size(); ++i) occ.data[i] = v.fragments.data[i] > 0.0f ? 1.0f : 0.0f;
    dir.write_volume("voxels_occupancy", occ, spacing0);
    dir.write_volume("voxels_fragments", v.fragments, spacing0);
  }
  if (!f.conservative_occupancy.data.empty())
    dir.write_volume("voxels_conservative_occupancy", f.conservative_occupancy, spacing0);
  if (!f.holes.data.empty()) dir.write_volume("holes", f.holes, spacing0);
  if (!v.cas_lo.data.empty()) dir.write_volume("voxels_cas_lo", v.cas_lo, spacing0);
  if (!v.cas_hi.data.empty()) dir.write_volume("voxels_cas_hi", v.cas_hi, spacing0);
  if (f.mips.iso.empty()) {
    if (!v.radiance.data.empty()) dir.write_volume("voxels_radiance_L0", v.radiance, spacing0);
  } else {
    for (size_t k = 0; k < f.mips.iso.size(); ++k)
      dir.write_volume("voxels_radiance_L" + std::to_string(k), f.mips.iso[k], scene.volume.size / float(f.mips.iso[k].nx));
  }
  for (size_t d = 0; d < 6; ++d)
    for (size_t k = 0; k < f.mips.aniso[d].size(); ++k) {
      const Volume& a = f.mips.aniso[d][k];
      dir.write_volume(std::string("aniso_") + kAnisoDirNames[d] + "_L" + std::to_string(k + 1), a,
                       scene.volume.size / float(a.nx));
    }
}

void write_images(RunDir& dir, const FrameImages& im) {
  const std::pair<const char*, const Image*> color[] = {
      {"direct", &im.direct},           {"indirect_diffuse", &im.indirect_diffuse},
      {"indirect_specular", &im.indirect_specular}, {"diffuse_term", &im.diffuse_term},
      {"specular_term", &im.specular_term}, {"emission", &im.emission},
      {"particles", &im.particles},     {"final", &im.final_image}};
  for (const auto& [name, img] : color)
    if (!img->empty()) dir.write_color(name, *img);
  if (!im.soft_shadow.empty()) dir.write_data("soft_shadow", im.soft_shadow, 0.0f, 1.0f);
}

}  // namespace

void write_frame_dumps(RunDir& dir, const FrameResult& frame, const Scene& scene, const VctSettings& settings) {
  (void)settings;
  write_shadow_maps(dir, frame);
  write_gbuffer(dir, frame.gbuffer, scene);
  write_images(dir, frame.images);
  write_volumes(dir, frame, scene);
  for (const auto& [stage, ms] : frame.timings_ms) dir.add_timing(frame.backend, stage, ms);
  for (const auto& [key, value] : frame.info) dir.json()["info"][frame.backend][key] = value;
  if (!frame.multibounce_energy.empty()) dir.json()["multibounce_energy"][frame.backend] = frame.multibounce_energy;
  dir.save();
}

}  // namespace vct
