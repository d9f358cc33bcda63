#include "stages/direct_ties.h"

#include <algorithm>

#include "core/parallel.h"
#include "stages/direct.h"
#include "stages/gbuffer.h"
#include "stages/gbuffer_ties.h"
#include "stages/shadow_ties.h"

namespace vct {

namespace {

constexpr const char* kGroups[2] = {"image.direct", "image.emission"};

// [lo, hi] of the direct light at a covered pixel: each light's unshadowed term times the ends
// of its admissible visibility.
void direct_range_at(const Scene& scene, const GBuffer& g, const std::vector<ShadowMap>& maps, const VctSettings& s,
                     int x, int y, vec3& lo, vec3& hi) {
  const SurfaceMaterial m = gbuffer_material(g, x, y);
  const sh::SurfacePbr pbr = surface_of(m);
  const vec3 p = g.position.rgb(x, y);
  const vec3 v = scene.camera.to_eye(p);
  lo = hi = vec3(0.0f);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const vec3 c = unshadowed_light(scene, i, s, p, m.shading_normal, v, pbr);
    if (c == vec3(0.0f)) continue;
    const VisibilityRange r =
        i < maps.size() ? light_visibility_range(maps[i], scene.lights[i], p, s) : VisibilityRange{};
    lo += c * r.lo;
    hi += c * r.hi;
  }
}

}  // namespace

Image shading_tie_range(const Scene& scene, const GBuffer& g, const std::vector<ShadowMap>& maps,
                        const VctSettings& settings, const Image& direct, const Image& emission) {
  const int w = g.coverage.width, h = g.coverage.height;
  Image out(w, h, 12);
  out.channel_names.clear();
  for (const char* group : kGroups)
    for (int c = 0; c < 3; ++c)
      for (bool upper : {false, true}) out.channel_names.push_back(tie_range_channel_name(group, c, upper));
  parallel_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      vec3 lo(0.0f), hi(0.0f);
      if (g.coverage.at(x, y, 0) > 0.0f) direct_range_at(scene, g, maps, settings, x, y, lo, hi);
      const vec3 d = direct.empty() ? vec3(0.0f) : direct.rgb(x, y);
      const vec3 e = emission.empty() ? vec3(0.0f) : emission.rgb(x, y);
      for (int c = 0; c < 3; ++c) {
        // Channel order: group, channel, lo then hi (as the names above).
        out.at(x, y, 2 * c) = std::min(lo[c], d[c]);
        out.at(x, y, 2 * c + 1) = std::max(hi[c], d[c]);
        out.at(x, y, 6 + 2 * c) = e[c];
        out.at(x, y, 6 + 2 * c + 1) = e[c];
      }
    }
  });
  return out;
}

}  // namespace vct
