#include "stages/voxel_lod.h"

#include <cmath>

#include "core/parallel.h"
#include "stages/voxelize.h"

namespace vct {

SurfaceLods voxel_lods(const Scene& scene, uint32_t triangle, int n) {
  SurfaceLods out;
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  const uvec3 t = scene.triangles[triangle];
  const vec3 &p0 = scene.positions[t.x], &p1 = scene.positions[t.y], &p2 = scene.positions[t.z];
  // The projection's window axes (voxelize.geom): z -> (x, y), x -> (y, z), y -> (x, z).
  const int axis = dominant_axis(p0, p1, p2);
  const int ax = axis == 0 ? 1 : 0, ay = axis == 2 ? 1 : 2;
  const glm::dvec3 e1 = glm::dvec3(p1) - glm::dvec3(p0), e2 = glm::dvec3(p2) - glm::dvec3(p0);
  // (b1, b2) -> window position is the 2x2 matrix [e1 e2] restricted to (ax, ay); its inverse
  // gives the barycentric change per world unit along each window axis.
  const double a = e1[ax], b = e2[ax], c = e1[ay], d = e2[ay];
  const double det = a * d - b * c;
  if (!(std::abs(det) > 0.0)) return out;
  const double voxel = double(scene.volume.size) / double(n);   // world units per pixel
  const glm::dvec3 bx(0.0, d / det * voxel, -c / det * voxel);  // d(b0, b1, b2) / d window x
  const glm::dvec3 by(0.0, -b / det * voxel, a / det * voxel);  // d(b0, b1, b2) / d window y
  UvDerivatives uv;
  const std::vector<vec2>* sets[2] = {&scene.uv0, &scene.uv1};
  for (int set = 0; set < 2; ++set) {
    const std::vector<vec2>& u = *sets[set];
    if (u.empty()) continue;
    const glm::dvec2 du1 = glm::dvec2(u[t.y]) - glm::dvec2(u[t.x]),
                     du2 = glm::dvec2(u[t.z]) - glm::dvec2(u[t.x]);
    uv.dx[set] = vec2(bx.y * du1 + bx.z * du2);
    uv.dy[set] = vec2(by.y * du1 + by.z * du2);
  }
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    const TextureRef* ref = slot_texture(m, slot);
    if (!ref || size_t(ref->texture) >= scene.textures.size()) continue;
    const TexelDerivatives td = texel_derivatives(scene.textures[size_t(ref->texture)], *ref, uv);
    out.exact.lambda[slot] = exact_lod(td);
    RhoBounds rho;
    rho.add_x(td.dx);
    rho.add_y(td.dy);
    out.range[slot] = rho.range();
  }
  return out;
}

std::vector<SurfaceLods> voxel_lods_per_triangle(const Scene& scene, int n) {
  std::vector<SurfaceLods> out(scene.triangles.size());
  parallel_for(int64_t(out.size()),
               [&](int64_t i) { out[size_t(i)] = voxel_lods(scene, uint32_t(i), n); });
  return out;
}

}  // namespace vct
