#include "stages/mips.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

#include "core/parallel.h"

namespace vct {

namespace {

Volume half_size(const Volume& v) {
  Volume out(std::max(1, v.nx / 2), std::max(1, v.ny / 2), std::max(1, v.nz / 2), v.channels);
  out.channel_names = v.channel_names;
  return out;
}

// Small levels run on the calling thread: a parallel region costs more than their work (and the
// result is the same either way: each slice is written by one body).
void for_each_slice(const Volume& out, const std::function<void(int64_t)>& body) {
  if (out.voxel_count() < (size_t(1) << 15)) {
    for (int64_t z = 0; z < out.nz; ++z) body(z);
  } else {
    parallel_for(out.nz, body);
  }
}

// Child index 2i + o along an axis, clamped for levels of size 1.
int child(int i, int o, int n) { return std::min(2 * i + o, n - 1); }

// RGBA access without Volume::rgba's per-channel loop (the pyramids are always 4 channels).
vec4 load4(const Volume& v, int x, int y, int z) {
  const float* p = v.voxel(x, y, z);
  return vec4(p[0], p[1], p[2], p[3]);
}
void store4(Volume& v, int x, int y, int z, const vec4& c) {
  float* p = v.voxel(x, y, z);
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
  p[3] = c.a;
}

}  // namespace

Volume downsample_iso(const Volume& v) {
  Volume out = half_size(v);
  for_each_slice(out, [&](int64_t zz) {
    const int z = int(zz);
    for (int y = 0; y < out.ny; ++y)
      for (int x = 0; x < out.nx; ++x) {
        vec4 sum(0.0f);
        for (int o = 0; o < 8; ++o)
          sum += load4(v, child(x, o & 1, v.nx), child(y, (o >> 1) & 1, v.ny), child(z, o >> 2, v.nz));
        store4(out, x, y, z, sum * 0.125f);
      }
  });
  return out;
}

Volume downsample_aniso(const Volume& v, int d) {
  Volume out = half_size(v);
  const int axis = d / 2;
  const bool positive = d % 2 == 0;  // looking along +axis: the lower child is in front
  const int u_axis = (axis + 1) % 3, w_axis = (axis + 2) % 3;
  const int dims[3] = {v.nx, v.ny, v.nz};
  for_each_slice(out, [&](int64_t zz) {
    ivec3 o;
    o.z = int(zz);
    for (o.y = 0; o.y < out.ny; ++o.y)
      for (o.x = 0; o.x < out.nx; ++o.x) {
        vec4 sum(0.0f);
        for (int p = 0; p < 4; ++p) {
          ivec3 front, back;
          front[u_axis] = back[u_axis] = child(o[u_axis], p & 1, dims[u_axis]);
          front[w_axis] = back[w_axis] = child(o[w_axis], p >> 1, dims[w_axis]);
          front[axis] = child(o[axis], positive ? 0 : 1, dims[axis]);
          back[axis] = child(o[axis], positive ? 1 : 0, dims[axis]);
          const vec4 f = load4(v, front.x, front.y, front.z), b = load4(v, back.x, back.y, back.z);
          sum += f + (1.0f - f.a) * b;
        }
        vec4 r = sum * 0.25f;
        r.a = std::min(r.a, 1.0f);
        store4(out, o.x, o.y, o.z, r);
      }
  });
  return out;
}

VoxelMips build_mips(const Volume& base_rgba, bool anisotropic) {
  if (base_rgba.channels != 4) throw std::invalid_argument("build_mips needs an RGBA volume");
  VoxelMips m;
  m.iso.push_back(base_rgba);
  while (m.iso.back().nx > 1 || m.iso.back().ny > 1 || m.iso.back().nz > 1) m.iso.push_back(downsample_iso(m.iso.back()));
  if (!anisotropic) return m;
  for (int d = 0; d < 6; ++d) {
    m.aniso[size_t(d)].reserve(m.iso.size());
    const Volume* prev = &base_rgba;
    for (size_t k = 1; k < m.iso.size(); ++k) {
      m.aniso[size_t(d)].push_back(downsample_aniso(*prev, d));
      prev = &m.aniso[size_t(d)].back();
    }
  }
  return m;
}

MipMemory mips_memory(const VoxelMips& mips, VoxelStorage storage) {
  MipMemory mem;
  auto add = [&](const Volume& v) {
    mem.voxels += int64_t(v.voxel_count());
    mem.ref_bytes += int64_t(v.bytes());
  };
  // What a GPU keeps: the isotropic pyramid, or the shared base plus the six directional ones.
  if (mips.anisotropic()) {
    if (!mips.iso.empty()) add(mips.iso[0]);
  } else {
    for (const Volume& v : mips.iso) add(v);
  }
  for (const auto& dir : mips.aniso)
    for (const Volume& v : dir) add(v);
  mem.gpu_bytes = mem.voxels * (storage == VoxelStorage::Rgba8 ? 4 : 8);
  return mem;
}

}  // namespace vct
