#include "core/memory_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sys/resource.h>
#include <unistd.h>

#include "core/declared_cones.h"
#include "core/error.h"

namespace vct {

namespace {

constexpr uint64_t kMiB = 1024 * 1024;

// `vct render` of a 16^3 grid, 16^2 image and 64^2 shadow map peaks at 135 MiB on the project
// machine: nearly all of it the shared libraries (OpenImageIO and its codecs, OpenCV, Embree).
constexpr uint64_t kProcessBaseline = 136 * kMiB;

// Fragments per N^2 the voxelizer emits when the scene is not known yet: a room is mostly its
// walls, N^2 voxels each. The built-in Cornell box gives 7.1 N^2 at 64^3 and 5.8 (GPU rule) / 6.5
// (conservative) N^2 at 256^3. With a scene its Steiner count replaces it (fragment_count).
constexpr uint64_t kFragmentsPerSlice = 8;

// Per fragment: the sorted VoxelFragment list (48 B), the per-triangle lists it was gathered from
// (48 B: freed, but as small blocks in the worker threads' heaps, which are not returned to the
// system), its may_drop flag (1 B, freedoms/coverage_ties.h) and the last frame's radiance (vec3,
// 12 B: kept for the freedoms after the frame, stages/pipeline.h FrameIntermediates); then the
// larger of two phases: the coverage ties, which hold one re-voxelization's sorted list at a time
// (48 B; its per-triangle lists reuse the heap blocks above), and the reduction's voxel start
// index (8 B).
constexpr uint64_t kBytesPerFragment = 48 + 48 + 1 + 12 + std::max<uint64_t>(48, 8);

// One frame's VoxelMips: iso[0] is a copy of the base level (RGBA float, 16 B/voxel) and every
// pyramid's levels 1..log2 N hold (N^3 - 1) / 7 voxels; anisotropic adds six directional pyramids.
uint64_t mip_bytes(uint64_t n3, bool anisotropic) {
  const uint64_t coarser = (n3 - 1) / 7;
  return 16 * n3 + 16 * coarser * (anisotropic ? 7 : 1);
}

// Peak of inject_with_multibounce (stages/multibounce.cpp) with what pipeline.cpp holds around it.
// Voxelization before it needs less: 16 B/voxel of occupancy volumes and two fragment lists.
uint64_t voxel_bytes(const VctSettings& v, uint64_t fragments, bool particles) {
  const uint64_t n = uint64_t(v.grid), n3 = n * n * n;
  // 1-channel float volumes alive all frame: Voxelization::occupancy, the FrameResult's copy of
  // the conservative occupancy and, with the GPU rule, the hole map.
  const uint64_t occupancy = n3 * (4 + 4 + (v.voxelizer == Voxelizer::GpuEmulation ? 4 : 0));
  // VoxelGrid: RGBA float radiance + fragment count and the reference's freedoms
  // (freedoms/voxel_freedoms.cpp: shading slack, exactness and occupancy tie, a float each, and the
  // fragment count range, two); the CAS and running-mean models add their lo/hi RGBA bounds.
  const uint64_t freedoms = 4 + 4 + 4 + 8;
  const uint64_t cas = v.reduction == Reduction::CasRgba8 || v.reduction == Reduction::RunningMeanHalf ? 32 : 0;
  const uint64_t grid = n3 * (16 + 4 + freedoms + cas);
  const uint64_t mips = mip_bytes(n3, v.anisotropic);
  uint64_t bytes = occupancy + grid + mips + fragments * kBytesPerFragment;
  // With particle emitters the particle ties (freedoms/reference_freedoms.cpp) reduce the fragments
  // again beside the finished frame: a second radiance and count (and CAS bounds). demo_room at
  // 256^3 held ~230 MiB more than the built-in scene for it (docs/performance.md, "Validate's memory").
  if (particles && v.particles) bytes += n3 * (16 + 4 + cas);
  // Solid voxelization / thickening (stages/voxel_fill.cpp), during injection: byte masks for the
  // surface, the facing, the closed rays, each fill's result and their union.
  if (v.solid_voxelization || v.surface_thickening_voxels > 0) bytes += 6 * n3;
  if (v.bounces > 1) {
    // A bounce frame traces the previous mips while it reduces a new grid (the old grid is
    // replaced only when the new one is done) and then builds new mips (the previous ones still
    // alive): the larger of grid and mips is there twice.
    bytes += mips > grid ? mips : grid;
    if (keeps_multibounce_frames(v)) bytes += 16 * n3 * uint64_t(v.bounces - 1);  // RGBA float each
  }
  return bytes;
}

// Alive from the G-buffer on; `shadow_layers` square float depth images (1 when the scene's lights
// are not known yet; a point light's cube counts six), each with its reference-only range of
// alternatives (two floats per texel: freedoms/shadow_map_ties.h).
uint64_t image_bytes(const VctSettings& v, int shadow_layers) {
  const uint64_t pixels = uint64_t(v.width) * uint64_t(v.height);
  const uint64_t shadow =
      uint64_t(std::max(shadow_layers, 0)) * uint64_t(v.shadow_map_size) * uint64_t(v.shadow_map_size) * (4 + 8);
  // G-buffer 21 floats (84 B), the raster it came from (kept for the freedoms: depth, triangle,
  // barycentrics, facing and its tie, 22 B), its texture slack (6 floats, 24 B) and
  // raster-alternative range (42 floats, 168 B: freedoms/gbuffer_ties.h); FrameImages: 8 RGB float
  // images (96 B), one RGBA image per diffuse cone (16 B each) and their source in IndirectImages
  // while they are copied (as much again; the composite images do not exist yet then, so this is
  // 60 B/pixel high at the seed's 5 cones); the soft-shadow visibility.
  const size_t declared = parse_declared_cones(v.diffuse_cone_set).size();  // an engine's set, if given
  const uint64_t cones = declared > 0 ? uint64_t(declared) : uint64_t(v.diffuse_cone_count);
  const uint64_t cone_images = 2 * 16 * (v.diffuse_cones ? cones : 0);
  const uint64_t per_pixel = 84 + 22 + 24 + 168 + 96 + cone_images + (v.soft_shadows ? 4 : 0);
  return shadow + pixels * per_pixel;
}

}  // namespace

uint64_t fragment_count(const SceneFootprint& scene, int n) {
  const uint64_t g = uint64_t(n);
  if (scene.triangles == 0) return kFragmentsPerSlice * g * g;
  // The conservative list holds one fragment per (triangle, voxel) it meets: the Steiner count in
  // expectation. The GPU rule's list is no longer: each of its fragments is one covered pixel of
  // the triangle's dominant-axis projection, a pixel the projection touches, i.e. a column of
  // voxels along that axis of which the triangle meets at least one (docs/performance.md,
  // "Validate's memory": 0.2-1.1 of it measured on the split box and the heightfields).
  return uint64_t(std::ceil(steiner_voxels(scene.fragment_terms, scene.triangles, n)));
}

bool keeps_multibounce_frames(const VctSettings& v) {
  const uint64_t n = uint64_t(v.grid), frame_bytes = n * n * n * 16;
  return v.bounces > 1 && frame_bytes * uint64_t(v.bounces - 1) <= 256 * kMiB;
}

MemoryEstimate estimate_memory(const Settings& s, const SceneFootprint& scene) {
  const VctSettings& v = s.vct;
  MemoryEstimate e;
  e.baseline = kProcessBaseline;
  e.voxels = voxel_bytes(v, fragment_count(scene, v.grid), scene.particles);
  e.images = image_bytes(v, scene.shadow_layers);
  // Besides the G-buffer's VisibilityBuffer (counted in the images: it is kept for the freedoms),
  // while the raster alternatives are found (freedoms/gbuffer_ties.h) up to two more of 22 B/pixel
  // (a shifted sample's, the depth-tied surfaces' first layer, or with alpha masks the unmasked
  // front and the surfaces behind) with two doubles per pixel (the depth ties' ceiling and a flag),
  // all freed when the G-buffer is done. A further layer of 22 B/pixel exists only where three or
  // more surfaces tie in depth at one pixel (raster_alternatives.h, depth_tied_surfaces): not
  // counted. Shadow maps are rasterized depth-only (stages/depth_raster.h) into
  // the map itself, counted in the images. Before the G-buffer, one map (or face) at a time, its
  // range of alternatives (freedoms/shadow_map_ties.h) is written straight into its image (counted
  // there) through one band of scratch per thread; with alpha masks the alpha ties add the
  // masked front, the front that may be kept and the surfaces behind with their doubles: the
  // camera's VisibilityBuffer and two more, 3 x 22 + 16 B per texel of the map.
  const uint64_t camera = (2 * 22 + 16) * uint64_t(v.width) * uint64_t(v.height);
  // Without alpha masks a shadow map's ties need no more than its band of scratch per thread.
  const uint64_t light =
      scene.alpha_tested ? (3 * 22 + 16) * uint64_t(v.shadow_map_size) * uint64_t(v.shadow_map_size) : 0;
  e.raster_scratch = std::max(camera, light) + kTransientBytesPerTriangle * scene.triangles;
  // Path tracer: 16 double accumulators (mean and variance of the AOVs) per pixel, and each
  // pixel's first vertex while they fit in their budget.
  const uint64_t pt_pixels = uint64_t(s.pt.width) * uint64_t(s.pt.height);
  e.path_tracer = pt_pixels * 16 * 8;
  if (pt_pixels * kPtFirstVertexBytes <= kPtFirstVertexBudget) e.path_tracer += pt_pixels * kPtFirstVertexBytes;
  e.scene = scene.triangles * kSceneBytesPerTriangle + scene.texture_bytes;
  return e;
}

namespace {
// Per voxel, the volumes both frames share as stages: radiance (RGBA float) and fragment count,
// the coarser mip levels (iso[0] is no stage), and with multibounce the bounce input and the kept
// frames (RGBA float each).
uint64_t shared_stage_bytes(const VctSettings& v) {
  const uint64_t n = uint64_t(v.grid), n3 = n * n * n;
  uint64_t bytes = n3 * (16 + 4) + mip_bytes(n3, v.anisotropic) - 16 * n3;
  if (v.bounces > 1) bytes += 16 * n3 * (1 + (keeps_multibounce_frames(v) ? uint64_t(v.bounces - 1) : 0));
  return bytes;
}

// The reference's own voxel stages: shading slack, exactness, occupancy tie, conservative
// occupancy (1 float each), the fragment count range (2), the hole map with the GPU rule, the CAS
// bounds (2 RGBA floats).
uint64_t ref_only_stage_bytes(const VctSettings& v) {
  const uint64_t n = uint64_t(v.grid), n3 = n * n * n;
  return n3 * (4 * 4 + 8 + (v.voxelizer == Voxelizer::GpuEmulation ? 4 : 0) +
               (v.reduction == Reduction::CasRgba8 ? 32 : 0));
}

// Measured with the built-in scene (2 k and 1 M triangles, grids 64-256; docs/performance.md,
// "Validate's memory"): while the reference renders, the GL driver (llvmpipe) still holds ~60 MiB
// beside the frame it read back; after the renders, the driver's and the path tracer's leftovers
// (their heaps are not returned to the system) hold ~150 MiB. The scene's arrays, twice (as
// loaded, for an exposure sweep, and as exposed), ~160 B per triangle: the peak RSS after loading
// 952 800 triangles. The judge's masks and slack volumes, ~12 B per voxel: the occupancy judges'
// byte masks (missing, extra, surface, both occupancies) and the mip judge's per-voxel slack
// floats, alive one stage at a time.
constexpr uint64_t kGlDuringRef = 60 * kMiB;
constexpr uint64_t kAfterRenders = 150 * kMiB;
constexpr uint64_t kSceneKeptPerTriangle = 160;
constexpr uint64_t kJudgeBytesPerVoxel = 12;
}  // namespace

namespace {
// The re-judgement of voxel.radiance on GL's own inputs (compare/isolated_stages.cpp,
// VoxelInjection and judged_voxels): one voxelization with its occupancy (4 B per voxel) and its
// fragments, one judged grid with its freedoms (as voxel_bytes counts it) and the copy of its
// radiance kept around the particles (16 B, freedoms/voxel_freedoms.cpp); with a bounce input, that
// input's mips. No second pyramid, hole map or kept frames: built-in scene at 256^3 with 2 bounces,
// 4 976 MiB measured against 4 677 predicted so (5 637 when it counted the frame's whole voxel
// peak again; docs/performance.md, "Validate's memory").
uint64_t reinjection_bytes(const VctSettings& v, uint64_t fragments) {
  const uint64_t n = uint64_t(v.grid), n3 = n * n * n;
  const uint64_t cas = v.reduction == Reduction::CasRgba8 || v.reduction == Reduction::RunningMeanHalf ? 32 : 0;
  uint64_t bytes = n3 * (4 + (16 + 4 + 4 + 4 + 4 + 8 + cas) + 16) + fragments * kBytesPerFragment;
  if (v.bounces > 1) bytes += mip_bytes(n3, v.anisotropic);
  return bytes;
}
}  // namespace

ValidateMemoryEstimate estimate_validate_memory(const Settings& s, const SceneFootprint& scene, bool gl) {
  const VctSettings& v = s.vct;
  const uint64_t n = uint64_t(v.grid), n3 = n * n * n;
  ValidateMemoryEstimate e;
  e.ref = estimate_memory(s, scene);
  const uint64_t shared = shared_stage_bytes(v);
  e.stage_sets = shared + ref_only_stage_bytes(v);
  e.scene_kept = kSceneKeptPerTriangle * scene.triangles + 2 * scene.texture_bytes;
  e.after_renders = kAfterRenders;
  if (gl) {
    e.gl = estimate_gl_memory(s, scene);
    e.unexposed_scene = kSceneKeptPerTriangle / 2 * scene.triangles + scene.texture_bytes;
    e.gl_during_ref = kGlDuringRef;
    e.gl_frame = gl_frame_bytes(v, scene.shadow_layers);  // its mips' base level too: the re-trace reads it
    e.gl_grid = gl_grid_bytes(v);
    e.rejudges_radiance = v.bounces >= 2;
    e.reinjection = reinjection_bytes(v, fragment_count(scene, v.grid));
    e.stage_sets += shared;
    e.judge_scratch = kJudgeBytesPerVoxel * n3;
  }
  return e;
}

MemoryEstimate estimate_memory(const Settings& s, int shadow_layers) {
  SceneFootprint unknown;
  unknown.shadow_layers = shadow_layers;
  return estimate_memory(s, unknown);
}

uint64_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : 0;
}

uint64_t peak_rss_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return uint64_t(u.ru_maxrss) * 1024;  // Linux reports kilobytes
}

std::string format_bytes(uint64_t bytes) {
  char buf[64];
  const double b = double(bytes);
  if (b >= 1024.0 * 1024.0 * 1024.0) std::snprintf(buf, sizeof buf, "%.1f GiB", b / (1024.0 * 1024.0 * 1024.0));
  else if (b >= 1024.0 * 1024.0) std::snprintf(buf, sizeof buf, "%.1f MiB", b / (1024.0 * 1024.0));
  else std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024.0);
  return buf;
}

bool warn_if_memory_short(const MemoryEstimate& e, const char* who, uint64_t available) {
  if (available == 0 || e.total() <= available) return false;
  std::fprintf(stderr, "%s: warning: this run needs about %s (scene %s, voxels %s, images %s), but this machine has %s\n",
               who, format_bytes(e.total()).c_str(), format_bytes(e.scene).c_str(), format_bytes(e.voxels).c_str(),
               format_bytes(e.images).c_str(), format_bytes(available).c_str());
  return true;
}

bool warn_if_memory_short(const GlMemoryEstimate& e, const char* who, uint64_t available) {
  if (available == 0 || e.total() <= available) return false;
  std::fprintf(stderr, "%s: warning: this run needs about %s (scene %s, GL textures %s, frame read back %s), but this "
               "machine has %s\n", who, format_bytes(e.total()).c_str(), format_bytes(e.scene).c_str(),
               format_bytes(e.textures).c_str(), format_bytes(e.frame).c_str(), format_bytes(available).c_str());
  return true;
}

bool warn_if_memory_short(const ValidateMemoryEstimate& e, const char* who, uint64_t available) {
  if (available == 0 || e.with_reinjection() <= available) return false;
  std::fprintf(stderr,
               "%s: warning: this run needs about %s (while GL renders %s; while the reference renders beside the "
               "GL frame %s; while the stage sets are compared %s, %s where voxel.radiance is re-judged on GL's "
               "own shadow maps; scene %s), but this machine has %s\n",
               who, format_bytes(e.total()).c_str(), format_bytes(e.during_gl()).c_str(),
               format_bytes(e.during_ref()).c_str(),
               format_bytes(e.during_checks()).c_str(), format_bytes(e.with_reinjection()).c_str(),
               format_bytes(e.ref.scene).c_str(), format_bytes(available).c_str());
  return true;
}

void check_memory_budget(const Settings& s, uint64_t available, int shadow_layers) {
  if (available == 0) return;
  const MemoryEstimate e = estimate_memory(s, shadow_layers);
  if (e.total() <= available) return;
  const VctSettings& v = s.vct;
  throw InputError("", "settings need about " + format_bytes(e.total()) + " (process " + format_bytes(e.baseline) +
                           "; grid " + std::to_string(v.grid) + "^3" +
                           (v.anisotropic ? " anisotropic" : "") + ": " + format_bytes(e.voxels) + "; images " +
                           std::to_string(v.width) + "x" + std::to_string(v.height) + " and shadow map " +
                           std::to_string(v.shadow_map_size) + "^2: " + format_bytes(e.images) + "; path tracer " +
                           std::to_string(s.pt.width) + "x" + std::to_string(s.pt.height) + ": " +
                           format_bytes(e.path_tracer) + "), but this machine has " + format_bytes(available) +
                           " of memory; use a smaller --grid or image size");
}

}  // namespace vct
