// 3D texture lookups on the voxel mips exactly as the GL specification (4.5 core, §8.14) defines
// them for textureLod() with LINEAR_MIPMAP_LINEAR minification, LINEAR magnification and
// CLAMP_TO_BORDER wrapping with border colour (0,0,0,0). Written from the specification, not from
// a shader, so the GL build can be checked against it (docs/pipeline.md, "Sampling conventions").
#pragma once

#include "core/math.h"
#include "core/volume.h"
#include "stages/stage_types.h"

namespace vct {

/// One texel, or the border colour (0,0,0,0) outside [0,n)^3 (CLAMP_TO_BORDER).
vec4 fetch_texel(const Volume& level, int i, int j, int k);

/// LINEAR filtering inside one level: texel centres at (i+0.5)/n, eight texels weighted by the
/// fractional parts of uvw*n - 0.5.
vec4 sample_level_trilinear(const Volume& level, const vec3& uvw);

/// LINEAR_MIPMAP_LINEAR over a chain of levels (level 0 first): lod clamped to [0, last level],
/// then a linear blend of floor(lod) and floor(lod)+1 by fract(lod). lod <= 0 is level 0 alone
/// (the magnification filter, LINEAR, is the same filter).
vec4 sample_chain(const Volume* const* levels, int level_count, const vec3& uvw, float lod);

/// Isotropic mips: textureLod(voxels, uvw, lod).
vec4 sample_isotropic(const VoxelMips& mips, const vec3& uvw, float lod);

/// Anisotropic mips seen along the unit direction `dir` (the direction the cone marches).
/// Each axis contributes the volume facing the march (dir.x >= 0 -> +x, else -x) with weight
/// dir.x^2 (the weights sum to 1). Each directional volume is sampled as the chain
/// [base level, aniso[d][0], aniso[d][1], ...], so below lod 1 the result blends the shared base
/// level with level 1 by fract(lod), exactly as a full mip chain with a shared level 0 would.
vec4 sample_anisotropic(const VoxelMips& mips, const vec3& uvw, float lod, const vec3& dir);

/// Isotropic or anisotropic, whichever the mips hold.
vec4 sample_voxels(const VoxelMips& mips, const vec3& uvw, float lod, const vec3& dir);

/// Highest usable level index of the mips (iso.size()-1, or the aniso chain length).
int max_mip_level(const VoxelMips& mips);

}  // namespace vct
