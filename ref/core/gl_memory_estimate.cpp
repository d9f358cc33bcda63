// The GL render's host memory (core/memory_budget.h, GlMemoryEstimate): llvmpipe's textures and
// buffers live in host memory, so its peak is theirs plus the frame read back into FrameResult
// (gl/gl_readback.cpp). Counted from the passes' allocations (gl/gl_pass_*.cpp); the driver's own
// and the per-triangle bytes measured (docs/performance.md, "Validate's memory").
#include <algorithm>

#include "core/memory_budget.h"

namespace vct {

namespace {
constexpr uint64_t kMiB = 1024 * 1024;

// Measured: `vct render --backend gl` of the split Cornell box (bench/memory_bench.py's scenes,
// 256^2, 2 threads) at 2 382 triangles peaks 302 MiB at grid 64 and 1 634 MiB at grid 256; the
// counted terms below and the process baseline leave 88 MiB (64) and 89 MiB (256): llvmpipe's own
// (its JIT-compiled shaders, thread pools and set-up buffers).
constexpr uint64_t kLlvmpipeBaseline = 88 * kMiB;

// Measured: the same renders, less every counted term and the baseline, held 334-604 B per
// triangle at 152 k and 952 k triangles (64^3 and 256^3; not linear: llvmpipe's heap and its
// binned set-ups); the 952 k, 256^3 figure, 419 B (docs/performance.md, "GL's bytes per triangle"):
// the loader's and the Scene's arrays, GL's vertex and index buffers, the bins.
constexpr uint64_t kGlBytesPerTriangle = 420;

// Voxels in levels 1..log2 n of an n^3 pyramid.
uint64_t coarser_levels(uint64_t n3) { return (n3 - 1) / 7; }

// GL's textures per voxel (gl/gl_pass_voxel.cpp): four R32UI sums and three particle sums, the
// facing volume when it fills, two radiance textures with their mips (RGBA16F or RGBA8) and, for
// anisotropic mips, two sets of six directional pyramids from level 1.
uint64_t gl_voxel_texture_bytes(const VctSettings& v) {
  const uint64_t n = uint64_t(v.grid), n3 = n * n * n;
  const uint64_t texel = v.storage == VoxelStorage::Rgba8 ? 4 : 8;
  const bool facing = v.solid_voxelization || v.surface_thickening_voxels > 0;
  uint64_t bytes = n3 * (4 * 4 + 3 * 4 + (facing ? 4 : 0));
  bytes += 2 * texel * (n3 + coarser_levels(n3));
  if (v.anisotropic) bytes += 2 * 6 * texel * coarser_levels(n3);
  return bytes;
}

// The frame's volumes read back (gl/gl_readback.cpp, gl_pass_voxel.cpp): radiance (RGBA float) and
// fragment count, every iso level (level 0 again as iso[0]) and directional level, the bounce
// input and the earlier multibounce frames kept under the reference's rule.
uint64_t gl_frame_volume_bytes(const VctSettings& v) {
  const uint64_t n = uint64_t(v.grid), n3 = n * n * n;
  uint64_t bytes = n3 * (16 + 4) + 16 * (n3 + coarser_levels(n3));
  if (v.anisotropic) bytes += 6 * 16 * coarser_levels(n3);
  if (v.bounces > 1) bytes += 16 * n3 * (1 + (keeps_multibounce_frames(v) ? uint64_t(v.bounces - 1) : 0));
  return bytes;
}

uint64_t shadow_texels(const VctSettings& v, int layers) {
  return uint64_t(std::max(layers, 1)) * uint64_t(v.shadow_map_size) * uint64_t(v.shadow_map_size);
}
}  // namespace

uint64_t gl_frame_bytes(const VctSettings& v, int shadow_layers) {
  const uint64_t pixels = uint64_t(v.width) * uint64_t(v.height);
  // Per pixel: the G-buffer read back (position, normal, albedo, specular, emission RGB floats;
  // coverage and depth floats; material RGBA: 84 B) and the frame images (direct, the two indirect
  // images, the two terms, final, emission: 7 RGB floats, 84 B; soft-shadow visibility 4 B).
  const uint64_t per_pixel = 84 + 84 + (v.soft_shadows ? 4 : 0);
  return gl_frame_volume_bytes(v) + 4 * shadow_texels(v, shadow_layers) + pixels * per_pixel;
}

uint64_t gl_grid_bytes(const VctSettings& v) {
  const uint64_t n = uint64_t(v.grid);
  return n * n * n * (16 + 4);
}

GlMemoryEstimate estimate_gl_memory(const Settings& s, const SceneFootprint& scene) {
  const VctSettings& v = s.vct;
  const uint64_t pixels = uint64_t(v.width) * uint64_t(v.height);
  GlMemoryEstimate e;
  e.baseline = estimate_memory(s, scene).baseline + kLlvmpipeBaseline;
  e.scene = kGlBytesPerTriangle * scene.triangles + scene.texture_bytes;
  // Per pixel (gl_pass_raster.cpp, gl_pass_shading.cpp): six RGBA32F G-buffer targets and their
  // depth (100 B), the direct, soft-shadow and particle images and five shading images (RGBA32F,
  // 128 B); the shadow maps' DEPTH32F layers.
  e.textures = gl_voxel_texture_bytes(v) + 4 * shadow_texels(v, scene.shadow_layers) + pixels * (100 + 128);
  e.frame = gl_frame_bytes(v, scene.shadow_layers);
  return e;
}

}  // namespace vct
