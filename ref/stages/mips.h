// Pre-filtered voxel levels (docs/pipeline.md, "Mips"): the isotropic 2x2x2 box filter and the six
// anisotropic directional pyramids of front-to-back composited pairs.
#pragma once

#include <cstdint>

#include "core/settings.h"
#include "core/volume.h"
#include "stages/stage_types.h"

namespace vct {

/// iso[0] = base; iso[k+1] = 2x2x2 mean of iso[k] (RGBA, opacity averaged) down to 1^3. Level
/// sizes follow GL: max(1, floor(n/2)). If `anisotropic`, aniso[d][k-1] is level k of direction d
/// (levels 1..L; level 0 is the shared base). Throws std::invalid_argument unless 4 channels.
VoxelMips build_mips(const Volume& base_rgba, bool anisotropic);

/// One isotropic reduction step.
Volume downsample_iso(const Volume& v);
/// One anisotropic step for direction d (AnisoDir): each pair along d's axis composited
/// front-to-back as seen looking along d (c = c_f + (1 - a_f) c_b, a likewise), the four pairs
/// averaged, alpha clamped to 1.
Volume downsample_aniso(const Volume& v, int d);

/// Memory a GPU keeps: the isotropic pyramid, or (anisotropic) the base plus the six directional
/// pyramids (1 + 6/7 = 1.86x the base; 6 x (1/8 + 1/64 + ...)). Voxel count, the bytes a GPU needs
/// in the given storage format (4 or 8 bytes per voxel) and the bytes the reference holds (float).
struct MipMemory {
  int64_t voxels = 0;
  int64_t gpu_bytes = 0;
  int64_t ref_bytes = 0;
};
MipMemory mips_memory(const VoxelMips& mips, VoxelStorage storage);

}  // namespace vct
