#include "stages/indirect_pass.h"

#include "core/parallel.h"

namespace vct {

vec3 view_vector(const Scene& scene, const vec3& p) { return scene.camera.to_eye(p); }

IndirectImages trace_indirect(const Scene& scene, const GBuffer& g, const VoxelMips& mips, const VctSettings& s,
                              int march_end) {
  const int w = g.coverage.width, h = g.coverage.height;
  IndirectImages out;
  out.diffuse = Image(w, h, 3);
  out.specular = Image(w, h, 3);
  out.diffuse.channel_names = out.specular.channel_names = {"R", "G", "B"};
  ConeFrame cones(mips, scene.volume, s);  // once per frame: the per-pixel loop only traces
  cones.set_march_end(march_end);
  out.diffuse_cones.assign(size_t(cones.diffuse_count()), Image(w, h, 4));
  for (auto& img : out.diffuse_cones) img.channel_names = {"R", "G", "B", "A"};
  parallel_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.0f) continue;
      const vec3 p = g.position.rgb(x, y);
      const vec3 n = g.normal.rgb(x, y);
      const vec3 margin = g.position_margin.empty() ? vec3(0.0f) : g.position_margin.rgb(x, y);
      if (s.diffuse_cones) {
        const DiffuseConeSet set = cones.diffuse(p, n, cones.rotation_for_pixel(x, y), nullptr, margin);
        out.diffuse.set_rgb(x, y, set.radiance * s.indirect_diffuse_gain);  // an engine's gain (settings.h)
        for (int i = 0; i < set.count; ++i) {
          float* px = out.diffuse_cones[size_t(i)].pixel(x, y);
          for (int c = 0; c < 4; ++c) px[c] = set.cones[size_t(i)][c];
        }
      }
      if (s.specular_cones) {
        const float roughness = g.material.at(x, y, 1);
        const vec3 v = view_vector(scene, cones.specular_view_point(p, n));
        out.specular.set_rgb(x, y, vec3(cones.specular(p, n, v, roughness, nullptr, margin)));
      }
    }
  });
  return out;
}

}  // namespace vct
