#include "stages/inject.h"

#include <algorithm>

#include "core/parallel.h"
#include "core/pcf_taps.h"
#include "stages/direct.h"
#include "stages/reduction.h"
#include "stages/voxel_fill.h"
#include "stages/voxel_lod.h"

namespace vct {

vec3 light_leaving(const Scene& scene, const VoxelFragment& f, const SurfaceMaterial& m,
                   const std::vector<ShadowMap>& maps, const VctSettings& settings,
                   const BounceLight* bounce) {
  vec3 l =
      diffuse_outgoing_radiance(scene, maps, settings, f.position, m.shading_normal, m.albedo) +
      m.emission;
  if (bounce && *bounce) l += (*bounce)(f, m);
  return l;
}

std::vector<vec3> fragment_radiance(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                                    const VctSettings& frame_settings, const BounceLight* bounce) {
  // The voxelizer's own PCF taps where the engine declares them (issue 39).
  const VctSettings settings = voxel_pass_settings(frame_settings);
  const std::vector<SurfaceLods> lods = voxel_lods_per_triangle(scene, vox.n);
  std::vector<vec3> out(vox.fragments.size());
  parallel_for(int64_t(out.size()), [&](int64_t i) {
    const VoxelFragment& f = vox.fragments[size_t(i)];
    const SlotLods& l =
        lods[f.triangle].exact;  // the voxel raster's implicit LOD (stages/voxel_lod.h)
    const SurfaceMaterial m =
        evaluate_material(scene, interpolate_surface(scene, f.triangle, f.b1, f.b2), l);
    out[size_t(i)] = light_leaving(scene, f, m, maps, settings, bounce);
  });
  return out;
}

namespace {

Volume rgba_volume(int n) {
  Volume v(n, n, n, 4);
  v.channel_names = {"R", "G", "B", "A"};
  return v;
}

float reduce_channel(const std::vector<float>& v, Reduction r) {
  switch (r) {
    case Reduction::FixedPoint: return fixed_point_mean(v);
    case Reduction::CasRgba8: return cas_sequential(v);
    case Reduction::ExactMean:
    default: return exact_mean(v);
  }
}

}  // namespace

VoxelGrid reduce_fragments(const Voxelization& vox, const std::vector<vec3>& values, const VctSettings& settings) {
  const int n = vox.n;
  VoxelGrid g;
  g.n = n;
  g.radiance = rgba_volume(n);
  g.fragments = Volume(n, n, n, 1);
  g.fragments.channel_names = {"fragments"};
  // Fragments are sorted by voxel: each run is one voxel, reduced independently.
  std::vector<size_t> starts;
  for (size_t i = 0; i < vox.fragments.size(); ++i)
    if (i == 0 || vox.fragments[i].voxel != vox.fragments[i - 1].voxel) starts.push_back(i);
  starts.push_back(vox.fragments.size());
  parallel_for(int64_t(starts.size()) - 1, [&](int64_t r) {
    const size_t b = starts[size_t(r)], e = starts[size_t(r) + 1];
    const ivec3 c = vox.fragments[b].voxel;
    vec4 out(0.0f, 0.0f, 0.0f, 1.0f);
    std::vector<float> ch(e - b);
    for (int k = 0; k < 3; ++k) {
      for (size_t i = b; i < e; ++i) ch[i - b] = values[i][k];
      out[k] = quantize_storage(reduce_channel(ch, settings.reduction), settings.storage);
    }
    g.radiance.set_rgba(c.x, c.y, c.z, out);
    *g.fragments.voxel(c.x, c.y, c.z) = float(e - b);
  });
  return g;
}

VoxelGrid reduce_and_fill(const Scene& scene, const Voxelization& vox, const std::vector<vec3>& values,
                          const VctSettings& settings) {
  VoxelGrid g = reduce_fragments(vox, values, settings);
  // Solid interior and thickening (voxel_fill.h) add opacity before particles and mips.
  fill_voxels(scene, vox, settings, g.radiance);
  return g;
}

VoxelGrid inject_and_reduce(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                            const VctSettings& settings, const BounceLight* bounce, std::vector<vec3>* values_out) {
  std::vector<vec3> values = fragment_radiance(scene, vox, maps, settings, bounce);
  VoxelGrid g = reduce_and_fill(scene, vox, values, settings);
  if (values_out) *values_out = std::move(values);
  return g;
}

}  // namespace vct
