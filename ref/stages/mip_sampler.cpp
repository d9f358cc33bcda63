#include "stages/mip_sampler.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"

namespace vct {

namespace {

using Level = MipSampler::Level;

// Slices in parallel above this many cells (the result is the same either way).
constexpr size_t kParallelCells = size_t(1) << 15;

void for_slices(int64_t slices, size_t cells, const std::function<void(int64_t)>& body) {
  if (cells < kParallelCells) {
    for (int64_t z = 0; z < slices; ++z) body(z);
  } else {
    parallel_for(slices, body);
  }
}

// occupied[cell] for cells (i0, j0, k0) in [-1, n-1]^3 (stored at +1): 1 when any of the texels
// (i0..i0+1, j0..j0+1, k0..k0+1) inside the level has a channel != 0 (NaN counts as non-zero).
// Texels outside are the border colour (0,0,0,0). Built separably: OR of two neighbours along x,
// then y, then z.
std::vector<uint8_t> cell_occupancy(const Volume& v) {
  const int nx = v.nx, ny = v.ny, nz = v.nz;
  const size_t cx = size_t(nx) + 1, cy = size_t(ny) + 1, cz = size_t(nz) + 1;
  std::vector<uint8_t> along_x(cx * size_t(ny) * size_t(nz), 0);
  for_slices(nz, along_x.size(), [&](int64_t z) {
    for (int y = 0; y < ny; ++y) {
      uint8_t* row = &along_x[(size_t(z) * size_t(ny) + size_t(y)) * cx];
      for (int x = 0; x < nx; ++x) {
        const float* p = v.voxel(x, y, int(z));
        const uint8_t nonzero = p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f || p[3] != 0.0f;
        row[x] |= nonzero;      // cell x - 1 + 1: this texel is its upper x neighbour
        row[x + 1] |= nonzero;  // cell x + 1: its lower one
      }
    }
  });
  std::vector<uint8_t> along_y(cx * cy * size_t(nz), 0);
  for_slices(nz, along_y.size(), [&](int64_t z) {
    for (int y = 0; y < ny; ++y) {
      const uint8_t* in = &along_x[(size_t(z) * size_t(ny) + size_t(y)) * cx];
      uint8_t* lo = &along_y[(size_t(z) * cy + size_t(y)) * cx];
      uint8_t* hi = lo + cx;
      for (size_t x = 0; x < cx; ++x) {
        lo[x] |= in[x];
        hi[x] |= in[x];
      }
    }
  });
  std::vector<uint8_t> cells(cx * cy * cz, 0);
  const size_t slice = cx * cy;
  for (int z = 0; z < nz; ++z) {  // a memory-bound OR of two slices: not worth threads
    const uint8_t* in = &along_y[size_t(z) * slice];
    uint8_t* lo = &cells[size_t(z) * slice];
    uint8_t* hi = lo + slice;
    for (size_t i = 0; i < slice; ++i) {
      lo[i] |= in[i];
      hi[i] |= in[i];
    }
  }
  return cells;
}


Level make_level(const Volume& v, const std::vector<uint8_t>& occupied) {
  Level L;
  L.data = v.data.data();
  L.nx = v.nx, L.ny = v.ny, L.nz = v.nz;
  L.sy = size_t(v.nx) * 4;
  L.sz = L.sy * size_t(v.ny);
  L.size = vec3(float(v.nx), float(v.ny), float(v.nz));
  L.size4 = {float(v.nx), float(v.ny), float(v.nz), 0.0f};
  L.last4 = {v.nx - 1, v.ny - 1, v.nz - 1, 0};
  L.cell_sy = ptrdiff_t(v.nx) + 1;
  L.cell_sz = L.cell_sy * (ptrdiff_t(v.ny) + 1);
  L.cell_origin = L.cell_sz + L.cell_sy + 1;
  L.occupied = occupied.data();
  return L;
}

}  // namespace

MipSampler::MipSampler(const VoxelMips& mips) {
  if (mips.iso.empty()) return;
  for (const Volume& v : mips.iso)
    if (v.channels != 4) return;
  // The anisotropic path locates one cell per level for all six directions: level k must have
  // one size in every direction (as build_mips makes them).
  for (const auto& chain : mips.aniso) {
    if (chain.size() != mips.aniso[0].size()) return;
    for (size_t k = 0; k < chain.size(); ++k) {
      const Volume& v = chain[k];
      const Volume& first = mips.aniso[0][k];
      if (v.channels != 4 || v.nx != first.nx || v.ny != first.ny || v.nz != first.nz) return;
    }
  }
  usable_ = true;
  base_size_ = mips.iso[0].nx;
  anisotropic_ = mips.anisotropic();
  const auto add = [&](const Volume& v) {
    occupancy_.push_back(cell_occupancy(v));
    return make_level(v, occupancy_.back());
  };
  // Same level limit as voxel_sampler.cpp (16 entries: grids up to 2^15).
  occupancy_.reserve(16 * 7);
  if (!anisotropic_) {
    for (size_t k = 0; k < std::min<size_t>(mips.iso.size(), 16); ++k) iso_.push_back(add(mips.iso[k]));
    iso_count_ = int(iso_.size());
    return;
  }
  const Level base = add(mips.iso[0]);
  iso_.push_back(base);
  for (int d = 0; d < 6; ++d) {
    aniso_[size_t(d)].push_back(base);
    const auto& chain = mips.aniso[size_t(d)];
    for (size_t k = 0; k + 1 < std::min<size_t>(chain.size() + 1, 16); ++k) aniso_[size_t(d)].push_back(add(chain[k]));
  }
}

}  // namespace vct
