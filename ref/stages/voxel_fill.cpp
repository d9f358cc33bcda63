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

std::vector<uint8_t> enclosed_voxels(const std::vector<uint8_t>& surface, const std::vector<uint8_t>& masks, int n) {
  // Per direction, the first surface voxel along it from every voxel, found by one sweep per row
  // against the direction (the GL pass walks each ray instead). A ray is closed when it meets a
  // surface voxel that does not face back toward the start (no triangle there facing -d).
  std::vector<uint8_t> out(surface.size(), 0);
  std::vector<uint8_t> closed(surface.size(), 0);  // bit d: the ray along direction d is closed
  for (int d = 0; d < 6; ++d) {
    const int axis = d / 2, sign = d % 2 == 0 ? 1 : -1;
    const uint8_t facing_back = uint8_t(1u << (d ^ 1));
    for (int v = 0; v < n; ++v)
      for (int u = 0; u < n; ++u) {
        int hit = -1;  // linear index of the nearest surface voxel ahead, -1 = none
        // Walk the row from its far end (in direction d) back to the start.
        for (int step = 0; step < n; ++step) {
          const int w = sign > 0 ? n - 1 - step : step;
          int c[3];
          c[axis] = w;
          c[axis == 0 ? 1 : 0] = u;
          c[axis == 2 ? 1 : 2] = v;
          const size_t i = linear(c[0], c[1], c[2], n);
          if (hit >= 0 && !(masks[size_t(hit)] & facing_back)) closed[i] |= uint8_t(1u << d);
          if (surface[i]) hit = int(i);
        }
      }
  }
  for (size_t i = 0; i < out.size(); ++i) out[i] = !surface[i] && closed[i] == 0x3F ? 1 : 0;
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
  const std::vector<uint8_t> masks = facing_masks(scene, vox);
  std::vector<uint8_t> added(surface.size(), 0);
  if (solid) added = enclosed_voxels(surface, masks, n);
  if (k > 0) {
    const std::vector<uint8_t> thick = thickened_voxels(surface, masks, n, k);
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
