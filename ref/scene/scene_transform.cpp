#include "scene/scene_transform.h"

#include <algorithm>
#include <cmath>

namespace vct {

namespace {

Bounds3 bounds_of(const std::vector<vec3>& positions) {
  Bounds3 b;
  for (const vec3& p : positions) b.add(p);
  return b;
}

// Multiples of a power of two: p / q and the product are exact, so only the rounding moves p.
vec3 snap(const vec3& p, float quantum) {
  return glm::round(p / quantum) * quantum;
}

// Every point of the scene through `point`, every direction through `dir` (normals, tangents,
// spot axes, the camera frame, particle velocities).
template <class PointFn, class DirFn>
Scene mapped(const Scene& scene, PointFn point, DirFn dir) {
  Scene s = scene;
  for (vec3& p : s.positions) p = point(p);
  for (vec3& n : s.normals) n = dir(n);
  for (vec4& t : s.tangents) t = vec4(dir(vec3(t)), t.w);  // a turn keeps the handedness
  s.camera.position = point(s.camera.position);
  s.camera.forward = dir(s.camera.forward);
  s.camera.up = dir(s.camera.up);
  for (Light& l : s.lights) {
    l.position = point(l.position);
    l.direction = dir(l.direction);
  }
  for (ParticleEmitter& e : s.emitters) {
    e.origin = point(e.origin);
    e.velocity_min = dir(e.velocity_min);
    e.velocity_max = dir(e.velocity_max);
    e.acceleration = dir(e.acceleration);
    // A negated extent is exact: (2r - 1) * (-e) = -((2r - 1) * e) (vct_shared.h particle_state).
    e.spawn_extent = dir(e.spawn_extent);
  }
  s.bounds = bounds_of(s.positions);
  return s;
}

vec3 identity(const vec3& v) {
  return v;
}

}  // namespace

Scene on_voxel_lattice(const Scene& scene, int grid, int room_voxels) {
  const Bounds3 b = bounds_of(scene.positions);
  const vec3 lo = b.empty() ? vec3(0.0f) : b.lo, extent = b.empty() ? vec3(0.0f) : b.extent();
  const float largest = std::max({extent.x, extent.y, extent.z, 1e-6f});
  float size = std::exp2(std::ceil(std::log2(largest)));
  // One voxel below the scene, the origin rounded down to the lattice (up to one more voxel),
  // the room, and one voxel above.
  while (largest + float(3 + room_voxels) * size / float(grid) > size) size *= 2.0f;
  const float voxel = size / float(grid);
  Scene s = mapped(
      scene, [&](const vec3& p) { return snap(p, voxel / kLatticeStepsPerVoxel); }, identity);
  s.volume.size = size;
  // Off the voxel lattice by 1/2, 1/4, 1/8 of a lattice step per axis: no lattice position (an
  // axis-aligned wall, a vertex) lies on a voxel face, and a 45-degree edge between lattice
  // points (a quad's diagonal) misses the lines where faces meet. There, which voxel holds a
  // point is a rounding tie that a mirror (a turn) resolves the other way. Still exact:
  // positions minus origin are multiples of 1/8 step.
  const float step = voxel / kLatticeStepsPerVoxel;
  s.volume.origin =
      glm::floor((lo - vec3(voxel)) / voxel) * voxel - vec3(0.5f, 0.25f, 0.125f) * step;
  s.volume.overridden = true;
  return s;
}

Scene translated(const Scene& scene, const vec3& t, bool move_volume) {
  Scene s = mapped(scene, [&](const vec3& p) { return p + t; }, identity);
  if (move_volume) s.volume.origin += t;
  return s;
}

vec3 turn90(const vec3& v, int axis) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;  // e_b -> e_c, e_c -> -e_b
  vec3 r = v;
  r[c] = v[b];
  r[b] = -v[c];
  return r;
}

vec3 unturn90(const vec3& v, int axis) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  vec3 r = v;
  r[b] = v[c];
  r[c] = -v[b];
  return r;
}

Scene turned90(const Scene& scene, int axis) {
  auto turn = [axis](const vec3& v) { return turn90(v, axis); };
  Scene s = mapped(scene, turn, turn);
  // The turned cube spans the turned corners; its new origin is their minimum (exact: negation).
  const vec3 a = turn(scene.volume.origin), z = turn(scene.volume.origin + vec3(scene.volume.size));
  s.volume.origin = glm::min(a, z);
  return s;
}

Scene light_scaled(const Scene& scene, float factor) {
  Scene s = scene;
  for (Material& m : s.materials) m.emissive_strength *= factor;
  for (Light& l : s.lights) l.intensity *= factor;
  for (ParticleEmitter& e : s.emitters) {
    e.color_start *= factor;
    e.color_end *= factor;
  }
  return s;
}

}  // namespace vct
