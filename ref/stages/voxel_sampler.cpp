#include "stages/voxel_sampler.h"

#include <algorithm>
#include <cmath>

namespace vct {

vec4 fetch_texel(const Volume& level, int i, int j, int k) {
  if (!level.contains(i, j, k)) return vec4(0.0f);  // CLAMP_TO_BORDER, border (0,0,0,0)
  return level.rgba(i, j, k);
}

vec4 sample_level_trilinear(const Volume& level, const vec3& uvw) {
  // GL §8.14.2: u = s*w_t - 1/2, i0 = floor(u), alpha = frac(u).
  const vec3 size(float(level.nx), float(level.ny), float(level.nz));
  const vec3 u = uvw * size - vec3(0.5f);
  const vec3 base = glm::floor(u);
  const vec3 f = u - base;
  const int i0 = int(base.x), j0 = int(base.y), k0 = int(base.z);
  const bool interior = i0 >= 0 && j0 >= 0 && k0 >= 0 && i0 + 1 < level.nx && j0 + 1 < level.ny && k0 + 1 < level.nz;
  vec4 result(0.0f);
  if (interior && level.channels == 4) {
    // Same weights and summation order as the general loop below (so the same bits), without the
    // per-texel border test: the common case inside the volume.
    const size_t sx = 4, sy = size_t(level.nx) * 4, sz = sy * size_t(level.ny);
    const float* p0 = &level.data[level.index(i0, j0, k0)];
    for (int dk = 0; dk < 2; ++dk) {
      const float wk = dk ? f.z : 1.0f - f.z;
      for (int dj = 0; dj < 2; ++dj) {
        const float wj = dj ? f.y : 1.0f - f.y;
        for (int di = 0; di < 2; ++di) {
          const float wi = di ? f.x : 1.0f - f.x;
          const float* t = p0 + size_t(dk) * sz + size_t(dj) * sy + size_t(di) * sx;
          result += (wi * wj * wk) * vec4(t[0], t[1], t[2], t[3]);
        }
      }
    }
    return result;
  }
  for (int dk = 0; dk < 2; ++dk) {
    const float wk = dk ? f.z : 1.0f - f.z;
    for (int dj = 0; dj < 2; ++dj) {
      const float wj = dj ? f.y : 1.0f - f.y;
      for (int di = 0; di < 2; ++di) {
        const float wi = di ? f.x : 1.0f - f.x;
        result += (wi * wj * wk) * fetch_texel(level, i0 + di, j0 + dj, k0 + dk);
      }
    }
  }
  return result;
}

vec4 sample_chain(const Volume* const* levels, int level_count, const vec3& uvw, float lod) {
  const int q = level_count - 1;
  // GL §8.14.3: lambda clamped to [0, q]; LINEAR_MIPMAP_LINEAR blends d1 = floor(lambda) and
  // d2 = d1 + 1 by frac(lambda); at or above q only level q is used.
  const float lambda = std::min(std::max(lod, 0.0f), float(q));
  if (lambda >= float(q)) return sample_level_trilinear(*levels[q], uvw);
  const int d1 = int(std::floor(lambda));
  const float f = lambda - float(d1);
  const vec4 t1 = sample_level_trilinear(*levels[d1], uvw);
  if (f == 0.0f) return t1;
  const vec4 t2 = sample_level_trilinear(*levels[d1 + 1], uvw);
  return (1.0f - f) * t1 + f * t2;
}

vec4 sample_isotropic(const VoxelMips& mips, const vec3& uvw, float lod) {
  const Volume* levels[16];
  const int count = std::min(int(mips.iso.size()), 16);
  for (int l = 0; l < count; ++l) levels[l] = &mips.iso[size_t(l)];
  return sample_chain(levels, count, uvw, lod);
}

namespace {
vec4 sample_direction_chain(const VoxelMips& mips, int d, const vec3& uvw, float lod) {
  const Volume* levels[16];
  levels[0] = &mips.iso[0];
  const int count = std::min(int(mips.aniso[size_t(d)].size()) + 1, 16);
  for (int l = 1; l < count; ++l) levels[l] = &mips.aniso[size_t(d)][size_t(l - 1)];
  return sample_chain(levels, count, uvw, lod);
}
}  // namespace

vec4 sample_anisotropic(const VoxelMips& mips, const vec3& uvw, float lod, const vec3& dir) {
  const vec3 w = dir * dir;
  vec4 result(0.0f);
  const int axis_dir[3] = {dir.x >= 0.0f ? kPosX : kNegX, dir.y >= 0.0f ? kPosY : kNegY,
                           dir.z >= 0.0f ? kPosZ : kNegZ};
  for (int a = 0; a < 3; ++a) {
    if (w[a] == 0.0f) continue;  // saves three of nine chain samples on axis-aligned cones
    result += w[a] * sample_direction_chain(mips, axis_dir[a], uvw, lod);
  }
  return result;
}

vec4 sample_voxels(const VoxelMips& mips, const vec3& uvw, float lod, const vec3& dir) {
  return mips.anisotropic() ? sample_anisotropic(mips, uvw, lod, dir) : sample_isotropic(mips, uvw, lod);
}

int max_mip_level(const VoxelMips& mips) {
  return mips.anisotropic() ? int(mips.aniso[0].size()) : int(mips.iso.size()) - 1;
}

}  // namespace vct
