#include "stages/voxelize.h"

#include <algorithm>
#include <cmath>

namespace vct {

glm::dvec3 to_voxel_space(const Scene& scene, int n, const vec3& world) {
  return (glm::dvec3(world) - glm::dvec3(scene.volume.origin)) / double(scene.volume.size) * double(n);
}

int dominant_axis(const vec3& v0, const vec3& v1, const vec3& v2) {
  const vec3 p = glm::abs(glm::cross(v1 - v0, v2 - v0));
  if (p.z > p.x && p.z > p.y) return 2;
  if (p.x > p.y) return 0;
  return 1;
}

namespace {

// Projections of the triangle and the box (centre c, half-extents h) onto axis a are disjoint.
bool separated(const glm::dvec3 t[3], const glm::dvec3& c, const glm::dvec3& h, const glm::dvec3& a) {
  if (a.x == 0.0 && a.y == 0.0 && a.z == 0.0) return false;  // parallel edges: no axis
  const double p0 = glm::dot(t[0] - c, a), p1 = glm::dot(t[1] - c, a), p2 = glm::dot(t[2] - c, a);
  const double r = h.x * std::abs(a.x) + h.y * std::abs(a.y) + h.z * std::abs(a.z);
  return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

}  // namespace

bool triangle_meets_box(const glm::dvec3 tri[3], const glm::dvec3& lo, const glm::dvec3& hi) {
  if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return false;
  const glm::dvec3 c = (lo + hi) * 0.5, h = (hi - lo) * 0.5;
  const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const glm::dvec3 e[3] = {tri[1] - tri[0], tri[2] - tri[1], tri[0] - tri[2]};
  for (const glm::dvec3& a : axes)
    if (separated(tri, c, h, a)) return false;
  if (separated(tri, c, h, glm::cross(e[0], e[1]))) return false;
  for (const glm::dvec3& a : axes)
    for (const glm::dvec3& ed : e)
      if (separated(tri, c, h, glm::cross(a, ed))) return false;
  return true;
}

bool triangle_overlaps_voxel(const glm::dvec3 tri[3], const glm::dvec3& lo) {
  const glm::dvec3 hi = lo + glm::dvec3(1.0);
  const glm::dvec3 e[3] = {tri[1] - tri[0], tri[2] - tri[1], tri[0] - tri[2]};
  glm::dvec3 axes[13] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, glm::cross(e[0], e[1])};
  int count = 4;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) axes[count++] = glm::cross(glm::dvec3(i == 0, i == 1, i == 2), e[j]);
  for (const glm::dvec3& a : axes) {
    // Box [lo, hi): the projection's min is attained only if no component of a is negative
    // (those pick hi, which the box excludes); likewise the max needs no positive component.
    double bmin = 0.0, bmax = 0.0;
    bool min_closed = true, max_closed = true;
    for (int c = 0; c < 3; ++c) {
      if (a[c] > 0.0) {
        bmin += a[c] * lo[c];
        bmax += a[c] * hi[c];
        max_closed = false;
      } else if (a[c] < 0.0) {
        bmin += a[c] * hi[c];
        bmax += a[c] * lo[c];
        min_closed = false;
      }
    }
    const double t0 = glm::dot(a, tri[0]), t1 = glm::dot(a, tri[1]), t2 = glm::dot(a, tri[2]);
    const double tmin = std::min({t0, t1, t2}), tmax = std::max({t0, t1, t2});
    if (tmax < bmin || (tmax == bmin && !min_closed)) return false;
    if (tmin > bmax || (tmin == bmax && !max_closed)) return false;
  }
  return true;
}

glm::dvec2 closest_point_barycentrics(const glm::dvec3 tri[3], const glm::dvec3& p) {
  const glm::dvec3 &a = tri[0], &b = tri[1], &c = tri[2];
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {0.0, 0.0};
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {d1 / (d1 - d3), 0.0};
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {0.0, d2 / (d2 - d6)};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {1.0 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  return {vb * denom, vc * denom};
}

Voxelization finish_voxelization(int n, std::vector<VoxelFragment> fragments) {
  Voxelization v;
  v.n = n;
  v.fragments = std::move(fragments);
  // Keys are unique (one fragment per triangle and voxel), so the order is total.
  std::sort(v.fragments.begin(), v.fragments.end(),
            [n](const VoxelFragment& a, const VoxelFragment& b) { return fragment_before(n, a, b); });
  v.occupancy = Volume(n, n, n, 1);
  v.occupancy.channel_names = {"occupancy"};
  for (const VoxelFragment& f : v.fragments) {
    float& o = *v.occupancy.voxel(f.voxel.x, f.voxel.y, f.voxel.z);
    if (o == 0.0f) ++v.covered;
    o = 1.0f;
  }
  return v;
}

Voxelization voxelize(const Scene& scene, const VctSettings& settings) {
  return settings.voxelizer == Voxelizer::Conservative ? voxelize_conservative(scene, settings.grid)
                                                       : voxelize_gpu_rule(scene, settings.grid, settings.msaa_samples);
}

Volume hole_map(const Voxelization& conservative, const Voxelization& gpu) {
  return hole_map(conservative.occupancy, gpu.occupancy);
}

Volume hole_map(const Volume& conservative_occupancy, const Volume& gpu_occupancy) {
  Volume h(conservative_occupancy.nx, conservative_occupancy.ny, conservative_occupancy.nz, 1);
  h.channel_names = {"hole"};
  for (size_t i = 0; i < h.data.size(); ++i)
    h.data[i] = (conservative_occupancy.data[i] > 0.0f && gpu_occupancy.data[i] == 0.0f) ? 1.0f : 0.0f;
  return h;
}

}  // namespace vct
