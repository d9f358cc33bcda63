// The lamp-near-a-wall case of issue 35 (docs/pipeline.md, "Normal offset"), shared by the
// reference's and GL's normal-offset tests: the scene and how much of it the direct light lights.
#pragma once

#include "stage_test_scene.h"
#include "stages/direct.h"
#include "stages/gbuffer.h"

namespace vct::test {

// A 4 x 3 m wall at z = -1 facing +z, a point lamp 0.4 m in front of it at eye height, and a
// camera 3.5 m away looking at it: the wall leaves the lamp's front cube face and runs into the
// four side faces at grazing angles, where the constant bias alone shadows it (docs/pipeline.md).
inline Scene lamp_near_a_wall() {
  Scene s;
  s.source = "test:lamp_near_a_wall";
  const uint32_t m = add_material(s, vec3(0.5f));
  s.materials[m].specular_factor = 0.0f;  // Lambertian: direct = albedo / pi x E x n.l x visibility
  add_quad(s, {-2, 0, -1}, {2, 0, -1}, {2, 3, -1}, {-2, 3, -1}, {0, 0, 1}, m);
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.0f, 1.5f, -0.6f);
  l.intensity = 2.0f;
  s.lights.push_back(l);
  s.volume = fit_volume(s.bounds);
  front_camera(s, vec3(0.0f, 1.5f, 2.5f), 1.0f, 0.5f);
  return s;
}

/// Fraction of the covered pixels whose direct light is the unshadowed light (within 10^-4):
/// the wall faces the lamp and nothing stands between, so every pixel is lit in truth.
inline double lit_fraction(const Scene& scene, const VctSettings& s, const GBuffer& g, const Image& direct) {
  int covered = 0, lit = 0;
  for (int y = 0; y < direct.height; ++y)
    for (int x = 0; x < direct.width; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.0f) continue;
      const vec3 p = g.position.rgb(x, y), n = g.normal.rgb(x, y);
      const SurfaceMaterial m = gbuffer_material(g, x, y);
      const vec3 open = unshadowed_light(scene, 0, s, p, n, scene.camera.to_eye(p), surface_of(m));
      ++covered;
      lit += direct.at(x, y, 0) >= open.x * (1.0f - 1e-4f) ? 1 : 0;
    }
  return covered ? double(lit) / double(covered) : 0.0;
}

}  // namespace vct::test
