// How much memory a run will need, estimated up front, so a grid or image that cannot fit is
// refused with a clear message (issue 2) instead of dying in the allocator halfway through.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include "core/settings.h"
#include "core/steiner_count.h"

namespace vct {

/// The path tracer keeps each pixel's first vertex across its passes (pt::Integrator::FirstVertex,
/// at most this many bytes: ref/pt/path_tracer.cpp checks) while the image's total stays within
/// kPtFirstVertexBudget; larger images trace it per sample instead.
constexpr uint64_t kPtFirstVertexBytes = 256;
constexpr uint64_t kPtFirstVertexBudget = uint64_t(256) << 20;

/// Estimated peak resident bytes of the CPU pipelines for `s` (what the ref backend allocates; the
/// GL backend needs less host memory), derived from the buffers each stage keeps alive
/// (memory_budget.cpp lists them). The scene is not known up front: its fragments are assumed to
/// be those of a room (docs/performance.md, "Scale: memory predicted and measured"); with a scene,
/// its triangles' Steiner count (core/steiner_count.h).
struct MemoryEstimate {
  uint64_t baseline = 0;  // the process before any stage: libraries and a small scene (measured)
  uint64_t voxels = 0;    // peak of injection + mips: grids, mip pyramids (two with multibounce),
                          // kept multibounce frames, occupancy volumes, fragment lists
  uint64_t images = 0;    // shadow maps, G-buffer, frame component images
  uint64_t raster_scratch = 0;  // the G-buffer rasterizer's visibility buffer, and the per-triangle
                                // memory of loading and rasterizing the scene (kTransientBytesPerTriangle)
  uint64_t path_tracer = 0;     // path tracer accumulation and AOV images
  uint64_t scene = 0;           // the Scene's arrays (kSceneBytesPerTriangle) and decoded textures;
                                // 0 when the scene is not known
  /// The rasterizer's scratch and the per-triangle set-ups are freed before voxelization starts,
  /// so only the larger counts.
  uint64_t total() const {
    return baseline + scene + images + (voxels > raster_scratch ? voxels : raster_scratch) + path_tracer;
  }
};

/// What a loaded scene adds to the estimate (stages/scene_footprint.h makes one from a Scene).
/// The defaults are "not known yet": no scene term, and alpha masks assumed (their raster ties
/// need the most scratch).
struct SceneFootprint {
  int shadow_layers = 1;        // shadow_map_layers(scene)
  uint64_t triangles = 0;
  uint64_t texture_bytes = 0;   // decoded texels of every texture and its mip levels
  bool alpha_tested = true;     // any material with an alpha test (freedoms/raster_alternatives.h)
  bool particles = false;       // any particle emitter: the particle ties reduce the grid again
  /// Steiner's terms summed over the triangles, in units of the voxel volume's edge: the expected
  /// (triangle, voxel) pairs at any grid (fragment_count). Zero with no scene.
  SteinerTerms fragment_terms;
};

/// Fragments the voxel term counts at grid `n`: the scene's summed Steiner count, the expected
/// size of the conservative voxelizer's list, which bounds the GPU rule's (docs/performance.md,
/// "Validate's memory"); 8 n^2 (a room's walls) when the scene is not known.
uint64_t fragment_count(const SceneFootprint& scene, int n);

/// Bytes per triangle of `vct render --backend ref`, measured on the split Cornell box
/// (bench/memory_bench.py; docs/performance.md, "Validate's memory"), its fragments counted apart
/// (fragment_count): the Scene's arrays, alive all run (48 B per vertex at 0.58 vertices per
/// triangle, 16 B per triangle: 44 B), and what loading it, building the BVH and rasterizing it
/// hold before voxelization (the peak at grid 64 and 952 800 triangles less every counted term).
constexpr uint64_t kSceneBytesPerTriangle = 44;
constexpr uint64_t kTransientBytesPerTriangle = 435;

/// `shadow_layers`: square depth images the lights need (shadow_map_layers(scene): one per spot or
/// directional light, six per point light); 1 when the scene is not known yet.
MemoryEstimate estimate_memory(const Settings& s, int shadow_layers = 1);
/// The same with a loaded scene's triangles, textures and alpha masks counted.
MemoryEstimate estimate_memory(const Settings& s, const SceneFootprint& scene);

/// `vct render --backend gl`'s peak, and vct validate's while GL renders: llvmpipe keeps every
/// texture and buffer in host memory, beside the frame it reads back (docs/performance.md,
/// "Validate's memory"). Counted: the textures and the frame; measured: the driver's own and the
/// bytes per triangle.
struct GlMemoryEstimate {
  uint64_t baseline = 0;  // the process (MemoryEstimate::baseline) and llvmpipe's own (measured)
  uint64_t scene = 0;     // per triangle (measured) and the decoded textures
  uint64_t textures = 0;  // GL's textures: voxel volumes and their mips, shadow maps, G-buffer, images
  uint64_t frame = 0;     // the FrameResult read back: voxels, mips, shadow maps, G-buffer, images
  uint64_t total() const { return baseline + scene + textures + frame; }
};

GlMemoryEstimate estimate_gl_memory(const Settings& s, const SceneFootprint& scene);
/// The GL frame read back (FrameResult): its volumes, shadow maps, G-buffer and images.
uint64_t gl_frame_bytes(const VctSettings& v, int shadow_layers);
/// Its voxel grid's share of that: radiance and fragment count, 20 B per voxel.
uint64_t gl_grid_bytes(const VctSettings& v);

/// `vct validate`'s peak (issue 37 item 4): its renders run one after the other, and the GL frame
/// (read back into host memory) stays alive while the reference renders; then the two stage sets
/// and the comparison. Whichever of those two phases holds more is the peak (docs/performance.md,
/// "Validate's memory").
struct ValidateMemoryEstimate {
  MemoryEstimate ref;           // the reference frame's own estimate (render's), baseline included
  GlMemoryEstimate gl;          // the GL render's own (render --backend gl's); zero without GL
  uint64_t gl_frame = 0;        // the GL frame read back (voxels, mips, shadow maps, G-buffer, images)
  uint64_t gl_grid = 0;         // its voxel grid (radiance, fragments), moved into its stage set
                                // before the checks (compare/stage_set.h, stage_set_taking_voxels)
  uint64_t gl_during_ref = 0;   // what the GL driver still holds while the reference renders
  uint64_t stage_sets = 0;      // both stage sets' volumes (the reference's moved out of its frame)
  uint64_t judge_scratch = 0;   // the comparison's per-voxel masks and slack volumes
  uint64_t scene_kept = 0;      // the scene as loaded and as exposed (two copies) after the renders
  uint64_t after_renders = 0;   // the renderers' leftovers: GL driver, path tracer heaps (measured)
  uint64_t unexposed_scene = 0;  // the scene as loaded, kept beside the exposed one for a sweep
  uint64_t reinjection = 0;      // the re-judgement's voxelization and injection (estimate_validate_memory)
  /// While GL renders: its own estimate and the scene's second copy.
  uint64_t during_gl() const { return gl.total() > 0 ? gl.total() + unexposed_scene : 0; }
  uint64_t during_ref() const { return ref.total() + gl_during_ref + gl_frame; }
  uint64_t during_checks() const {
    return ref.baseline + scene_kept + ref.images + ref.path_tracer + after_renders + gl_frame - gl_grid +
           stage_sets + judge_scratch;
  }
  /// With multibounce voxel.radiance is always re-judged on GL's own bounce input
  /// (compare/isolated_stages.cpp): then the re-judgement's phase is known to come.
  bool rejudges_radiance = false;
  uint64_t phases() const { return std::max({during_gl(), during_ref(), during_checks()}); }
  uint64_t total() const { return rejudges_radiance ? with_reinjection() : phases(); }
  /// Where voxel.radiance is re-judged on the test's own shadow maps (with one bounce only when
  /// its end-to-end verdict counted shading ties: not known before the comparison), the
  /// reference's voxelization and injection run again beside the sets (compare/isolated_stages.h,
  /// VoxelInjection), after the end-to-end judges have freed their scratch.
  uint64_t with_reinjection() const {
    const uint64_t again = gl_frame > 0 ? during_checks() - judge_scratch + reinjection : 0;
    return std::max(again, phases());
  }
};

/// `gl`: whether the GL backend will run (without it only the reference's terms count).
ValidateMemoryEstimate estimate_validate_memory(const Settings& s, const SceneFootprint& scene, bool gl = true);

/// Whether the ref pipeline keeps the base level of every multibounce frame before the last (for
/// the dumps): only while they total at most 256 MiB. Shared so the estimate counts what is kept.
bool keeps_multibounce_frames(const VctSettings& v);

/// Physical memory of this machine in bytes (sysconf); 0 if unknown.
uint64_t physical_memory_bytes();

/// Throws InputError saying how much is needed when the estimate exceeds `available` bytes
/// (default: physical memory). Does nothing if `available` is 0 (unknown).
void check_memory_budget(const Settings& s, uint64_t available = physical_memory_bytes(), int shadow_layers = 1);

/// Prints "WHO: warning: ..." to stderr when `e` exceeds `available` bytes (default: physical
/// memory; 0 = unknown: silent): the run may not fit. Returns whether it warned.
bool warn_if_memory_short(const MemoryEstimate& e, const char* who, uint64_t available = physical_memory_bytes());
/// The same for the GL render's estimate (vct render --backend gl).
bool warn_if_memory_short(const GlMemoryEstimate& e, const char* who, uint64_t available = physical_memory_bytes());
/// The same for vct validate's estimate (its phases named).
bool warn_if_memory_short(const ValidateMemoryEstimate& e, const char* who,
                          uint64_t available = physical_memory_bytes());

/// Peak resident set size of this process so far in bytes (getrusage); 0 if unknown.
uint64_t peak_rss_bytes();

/// "1.5 GiB", "300 MiB", ...
std::string format_bytes(uint64_t bytes);

}  // namespace vct
