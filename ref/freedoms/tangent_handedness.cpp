#include "freedoms/tangent_handedness.h"

namespace vct {

bool tangent_handedness_mixed(const Scene& scene, uint32_t triangle) {
  if (scene.tangents.empty()) return false;
  const uvec3 t = scene.triangles[triangle];
  const bool neg0 = scene.tangents[t.x].w < 0.0f;
  return (scene.tangents[t.y].w < 0.0f) != neg0 || (scene.tangents[t.z].w < 0.0f) != neg0;
}

bool handedness_may_flip(const Scene& scene, uint32_t triangle) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  return m.normal_texture.present() && tangent_handedness_mixed(scene, triangle);
}

SurfacePoint with_other_handedness(SurfacePoint p) {
  p.tangent.w = -p.tangent.w;
  return p;
}

}  // namespace vct
