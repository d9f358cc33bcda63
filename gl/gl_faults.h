// The GL build's deliberate faults, one table: each breaks the GL pipeline in one known way so the
// tests (tests/gl/gl_faults_test.cpp) and scripts/gpu_check.sh can prove that the comparison blames
// the stage the fault lives in (docs/compare.md, "Fault switch"). A shader fault reaches the GLSL as
// `#define VCT_FAULT_<NAME> 1`, prepended by the program builder (gl_program.h, ProgramBuilder);
// a host fault changes what the C++ passes do. The CPU reference knows nothing of them.
#pragma once

#include <string>

#include "stages/stage_registry.h"

namespace vct::gl {

struct GlFault {
  const char* name;    // the CLI / settings spelling
  const char* where;   // what it breaks, and in which file
  const char* blamed;  // the first stage a correct comparison fails
  bool host;           // a C++ fault (no #define)
  // False where a CPU rasterizer (llvmpipe) cannot show it: it serializes the fragments of one
  // voxel and finishes each pass before the next (docs/compare.md), so only a GPU can.
  bool visible_on_cpu_rasterizer = true;
};

inline constexpr GlFault kGlFaults[] = {
    {"half_texel", "voxel depth coordinate + 0.5 voxel (voxelize.frag)", stage_names::kVoxelOccupancy, false},
    {"wrong_axis", "dominant-axis x/y test swapped (voxelize.geom)", stage_names::kVoxelOccupancy, false},
    {"racy_average", "non-atomic load/add/store or load/average/store (voxelize.frag); invisible on llvmpipe",
     stage_names::kVoxelRadiance, false, false},
    {"lost_update", "last writer wins instead of the reduction (voxelize.frag)", stage_names::kVoxelRadiance, false},
    // Caught only by the exact voxels (voxel.exact): one half-ulp is within every shading bound.
    {"half_truncate", "the RGBA16F store truncates instead of rounding to nearest even (half_round.glsl)",
     stage_names::kVoxelRadiance, false},
    // Family members by their canonical names (stages/stage_registry.h: stage_name(row, level)).
    {"wrong_mip", "iso mip l built from level l-2 (mip_iso.comp)", "mip.iso.2", false},
    {"alpha_unclamped", "aniso compositing never clamps opacity (mip_aniso.comp; needs anisotropic)", "mip.posx.1",
     false},
    {"texture_level_zero", "material textures looked up at level 0, no mipmapping (textureLod(.., 0), surface.glsl)",
     stage_names::kGbufferNormal, false},
    // Issue 13 case 2: a one-pixel highlight 19 % too bright at an edge passed under the counted
    // shading share; judged on the GL frame's own G-buffer and shadow maps it fails.
    {"fresnel_exponent_4", "Schlick's Fresnel with (1 - cos)^4 instead of ^5 (vct_shared.h under GLSL)",
     stage_names::kImageDirect, false},
    {"cone_step", "the cone march starts one step late (cone.glsl)", stage_names::kImageIndirectDiffuse, false},
    // Issue 33: the soft-shadow cone traced away from the light moves occlusion everywhere; judged
    // on the test's own inputs image.direct has no PCF range to hide it in (docs/compare.md).
    {"soft_shadow_direction", "the soft-shadow cone is traced away from the light (direct.frag; needs soft_shadows)",
     stage_names::kImageDirect, false},
    // Issue 34 item 1: an sRGB decode one 8-bit step of the encoding high, twice what the precision
    // table allows (half a step); shows only on scenes with sRGB textures.
    {"srgb_decode_step", "sRGB base colour and emissive lookups decoded one 8-bit step high (surface.glsl)",
     stage_names::kVoxelRadiance, false},
    // Alpha-mask faults show only on scenes with alpha masks (scenes/foliage.gltf).
    {"alpha_shadow", "the depth pass ignores alphaMode MASK (depth_only.frag)", "shadow_map.0",
     false},
    {"alpha_voxel", "voxelization ignores alphaMode MASK (voxelize.frag)",
     stage_names::kVoxelOccupancy, false},
    // Issue 34 item 3: frame k's bounce light read from the texture frame k writes (its mips hold
    // frame k - 2, nothing in frame 2): the last frame is right on its own bounce input, so only
    // the earlier frames, judged each on the test's own previous frame, show it.
    {"bounce_reads_current_frame",
     "multibounce frames trace their bounce light in the frame being written instead of the previous one "
     "(gl_pass_voxel.cpp; needs bounces >= 3)",
     "voxel.frame.2", true},
    {"missing_barrier",
     "no glMemoryBarrier between the voxelization draw and the resolve dispatch (gl_pass_voxel.cpp); "
     "invisible on llvmpipe, which finishes each pass before the next",
     stage_names::kVoxelRadiance, true, false},
};

/// The table row of `name`, or nullptr ("" and unknown names).
const GlFault* find_gl_fault(const std::string& name);

/// Comma-separated names, for messages and --help.
std::string gl_fault_names();

/// Throws InputError(where, ...) unless `name` is "" or a row of kGlFaults.
void check_gl_fault(const std::string& name, const std::string& where);

}  // namespace vct::gl
