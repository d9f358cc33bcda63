// The voxel mips prepared for the millions of lookups a frame's cone tracing makes (issue 16):
// the same GL §8.14 LINEAR_MIPMAP_LINEAR arithmetic as stages/voxel_sampler.h, in the same order,
// so every result has the same bits (tests/ref/mip_sampler_test.cpp checks), but
//  - per-level sizes and strides are computed once, not per lookup;
//  - the anisotropic sampler finds the texel cell and its eight weights once per level and reads
//    the three directional volumes with them (the six volumes of a level have one size), and
//    samples the shared base level once instead of once per axis;
//  - an occupancy byte per trilinear cell (any of its eight texels non-zero) lets a lookup in
//    empty space skip the eight texel reads: the filter of eight zero texels is exactly +0
//    (each weight is finite and >= 0, so every product is +-0 and the sum starting at +0 stays +0),
//    which is what the full computation returns.
// voxel_sampler.h stays the readable statement of the rules; this is the fast path of the frame.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "stages/stage_types.h"

namespace vct {

class MipSampler {
 public:
  /// Keeps pointers into `mips` (which must outlive the sampler and stay unchanged).
  explicit MipSampler(const VoxelMips& mips);
  MipSampler(const MipSampler&) = delete;  // Level::occupied points into this object's storage
  MipSampler& operator=(const MipSampler&) = delete;
  MipSampler(MipSampler&&) = default;      // moving the vectors keeps their buffers

  /// False when a volume is not RGBA (mips read from elsewhere): use voxel_sampler.h then.
  bool usable() const { return usable_; }

  /// == sample_voxels(mips, uvw, lod, dir), bit for bit, for uvw in [0,1]^3.
  vec4 sample(const vec3& uvw, float lod, const vec3& dir) const;

  int base_size() const { return base_size_; }  // mips.iso[0].nx (0 when empty)

  /// One level of a chain: its texels and what locating a cell needs.
  struct Level {
    const float* data = nullptr;
    int nx = 0, ny = 0, nz = 0;
    size_t sy = 0, sz = 0;      // floats per row, per slice (4 channels)
    vec3 size{0.0f};            // (nx, ny, nz) as floats, as sample_level_trilinear forms it
    std::array<float, 4> size4{};  // (nx, ny, nz, 0): the same for a four-lane load
    std::array<int, 4> last4{};    // (nx - 1, ny - 1, nz - 1, 0): the interior test's bounds
    const uint8_t* occupied = nullptr;  // (nx+1)(ny+1)(nz+1) cells, cell (i0,j0,k0) at i0+1, ...
    // occupied[cell_origin + k0 * cell_sz + j0 * cell_sy + i0] is cell (i0, j0, k0)'s byte.
    ptrdiff_t cell_sy = 0, cell_sz = 0, cell_origin = 0;
  };

 private:
  vec4 sample_isotropic(const vec3& uvw, float lod) const;
  vec4 sample_anisotropic(const vec3& uvw, float lod, const vec3& dir) const;

  int base_size_ = 0;
  bool usable_ = false;
  bool anisotropic_ = false;
  std::vector<Level> iso_;                   // iso_[k] = mips.iso[k]
  int iso_count_ = 0;                        // iso_.size() (isotropic mips only)
  std::array<std::vector<Level>, 6> aniso_;  // aniso_[d][k] = level k of direction d (k = 0: the base)
  std::vector<std::vector<uint8_t>> occupancy_;  // storage behind Level::occupied
};

}  // namespace vct

#include "stages/mip_sampler_lookup.h"  // the inline lookups
