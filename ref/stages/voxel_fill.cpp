#include "stages/voxel_fill.h"

#include <algorithm>

namespace vct {

namespace {

size_t linear(int x, int y, int z, int n) { return size_t(x) + size_t(n) * (size_t(y) + size_t(n) * size_t(z)); }

// Unit steps of the six directions, AnisoDir order.
constexpr int kStep[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

}  // namespace

int facing_direction(const vec3& v0, const vec3& v1, const vec3& v2) {
  // The same float cross product as dominant_axis and the GL geometry shader, so the axis and
  // its sign are the GPU's bit for bit.
  const int axis = dominant_axis(v0, v1, v2);
  const vec3 normal = glm::cross(v1 - v0, v2 - v0);
  return 2 * axis + (normal[axis] < 0.0f ? 1 : 0);
}

std::vector<uint8_t> facing_masks(const Scene& scene, const Voxelization& vox) {
  const int n = vox.n;
  std::vector<uint8_t> masks(size_t(n) * size_t(n) * size_t(n), 0);
  for (const VoxelFragment& f : vox.fragments) {
    const uvec3 t = scene.triangles[f.triangle];
    const int d = facing_direction(scene.positions[t.x], scene.positions[t.y], scene.positions[t.z]);
    masks[linear(f.voxel.x, f.voxel.y, f.voxel.z, n)] |= uint8_t(1u << d);
  }
  return masks;
}

std::vector<uint8_t> enclosed_voxels(const std::vector<uint8_t>& surface, int n) {
  // Per axis and per row along it, the first and last surface index; a voxel is enclosed along
  // that axis when it lies strictly between them. Rows are addressed by the two other coordinates.
  std::vector<uint8_t> out(surface.size(), 0);
  std::vector<int> first(size_t(3) * size_t(n) * size_t(n), n), last(first.size(), -1);
  auto row = [n](int axis, int x, int y, int z) {
    const int u = axis == 0 ? y : x, v = axis == 2 ? y : z;
    return size_t(axis) * size_t(n) * size_t(n) + size_t(u) + size_t(n) * size_t(v);
  };
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        if (!surface[linear(x, y, z, n)]) continue;
        const int c[3] = {x, y, z};
        for (int a = 0; a < 3; ++a) {
          const size_t r = row(a, x, y, z);
          first[r] = std::min(first[r], c[a]);
          last[r] = std::max(last[r], c[a]);
        }
      }
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const size_t i = linear(x, y, z, n);
        if (surface[i]) continue;
        const int c[3] = {x, y, z};
        bool enclosed = true;
        for (int a = 0; a < 3 && enclosed; ++a) {
          const size_t r = row(a, x, y, z);
          enclosed = first[r] < c[a] && c[a] < last[r];
        }
        out[i] = enclosed ? 1 : 0;
      }
  return out;
}

std::vector<uint8_t> thickened_voxels(const std::vector<uint8_t>& surface, const std::vector<uint8_t>& masks,
                                      int n, int k) {
  // Scatter from each surface voxel to the k voxels behind it (the GL pass gathers instead).
  std::vector<uint8_t> out(surface.size(), 0);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const size_t i = linear(x, y, z, n);
        if (!surface[i]) continue;
        for (int d = 0; d < 6; ++d) {
          if (!(masks[i] & (1u << d))) continue;
          for (int j = 1; j <= k; ++j) {
            const int bx = x - j * kStep[d][0], by = y - j * kStep[d][1], bz = z - j * kStep[d][2];
            if (bx < 0 || by < 0 || bz < 0 || bx >= n || by >= n || bz >= n) break;
            const size_t b = linear(bx, by, bz, n);
            if (!surface[b]) out[b] = 1;
          }
        }
      }
  return out;
}

int64_t fill_voxels(const Scene& scene, const Voxelization& vox, const VctSettings& settings, Volume& radiance) {
  const bool solid = settings.solid_voxelization;
  const int k = settings.surface_thickening_voxels;
  if (!solid && k <= 0) return 0;
  const int n = vox.n;
  std::vector<uint8_t> surface(size_t(n) * size_t(n) * size_t(n), 0);
  for (const VoxelFragment& f : vox.fragments) surface[linear(f.voxel.x, f.voxel.y, f.voxel.z, n)] = 1;
  std::vector<uint8_t> added(surface.size(), 0);
  if (solid) added = enclosed_voxels(surface, n);
  if (k > 0) {
    const std::vector<uint8_t> thick = thickened_voxels(surface, facing_masks(scene, vox), n, k);
    for (size_t i = 0; i < added.size(); ++i) added[i] |= thick[i];
  }
  int64_t count = 0;
  for (size_t i = 0; i < added.size(); ++i) {
    if (!added[i]) continue;
    radiance.data[i * size_t(radiance.channels) + 3] = 1.0f;
    ++count;
  }
  return count;
}

}  // namespace vct
