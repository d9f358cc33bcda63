// What each VCT stage computes, shared by the CPU reference (ref/) and the GL build (gl/), so that
// both backends hand the same types to the dump writer and to compare/.
// Coordinates: images row 0 = top; volumes x fastest; voxel (i,j,k) covers texture coordinates
// [i/N,(i+1)/N) x ... of the scene's VoxelVolume (docs/pipeline.md).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/math.h"
#include "core/volume.h"
#include "stages/backend_facts.h"

namespace vct {

/// Cube faces in GL's order (GL 4.5 Table 8.19: TEXTURE_CUBE_MAP_POSITIVE_X ... NEGATIVE_Z).
constexpr std::array<const char*, 6> kCubeFaceNames = {"posx", "negx", "posy", "negy", "posz", "negz"};

/// One light's depth map(s), GL window depth in [0,1] (depth range 0..1, cleared to 1), 1 channel,
/// row 0 = top = +y of the light's NDC. Spot (perspective) and directional (orthographic) lights
/// fill `depth`; a point light fills the six `cube` faces instead (docs/pipeline.md, "Shadow maps").
struct ShadowMap {
  Image depth;
  mat4 view_proj{1.0f};  // world -> light clip space
  std::array<Image, 6> cube;         // point lights: face f sees along its Table 8.19 major axis
  std::array<mat4, 6> cube_view_proj{};  // world -> face clip space (90 degree perspective)
  // Reference only (empty from GL): per texel the range [lo, hi] of the depth a correct GL may
  // store there under 2^-8 texel vertex snapping and alpha-test ties, of `depth` and of each
  // `cube` face (freedoms/shadow_map_ties.h); the comparison admits a value inside it.
  Image tie_range;
  std::array<Image, 6> cube_tie_range;
  bool is_cube() const { return !cube[0].empty(); }
};

/// Camera G-buffer, one value per pixel centre, row 0 = top. Pixels no triangle covers have
/// coverage 0 and zeros elsewhere.
struct GBuffer {
  Image position;   // 3: world position
  Image normal;     // 3: unit shading normal after normal mapping, facing the camera
  Image albedo;     // 3: linear base colour (factor x texture)
  Image material;   // 4: metallic, roughness, specular_factor, 0
  Image specular_color;  // 3: KHR_materials_specular colour (linear)
  Image emission;   // 3: emitted radiance (factor x texture x strength)
  Image depth;      // 1: window depth [0,1]
  Image coverage;   // 1: 1 where a triangle covers the pixel centre
  // Reference only (empty from GL): per textured attribute (normal, albedo, material, emission)
  // how far its value may move under a 2^-8 pixel sample shift (freedoms/texture_slack.h); the
  // comparison adds it to those stages' bounds.
  Image texture_slack;
  // Reference only (empty from GL): per G-buffer stage and channel the range [lo, hi] of the
  // values a correct GL may show here when its edges or a triangle's facing tie the other way
  // (freedoms/gbuffer_ties.h); the comparison admits a value inside it.
  Image tie_range;
  // Test frames only, where the re-trace reconstructs the engine's positions from its depth
  // (compare/partial_gbuffer.h): per axis how far (world units) the engine's own position may lie
  // from `position`; the march-end variants' start-face tie reads it (stages/cone_trace.h).
  Image position_margin;
};

/// Voxel occupancy and radiance at the base level (level 0, N^3).
struct VoxelGrid {
  int n = 0;
  Volume radiance;   // 4: RGB outgoing radiance, A opacity (0 or 1 at level 0)
  Volume fragments;  // 1: number of fragments (surface samples) that landed in each voxel
  // CAS RGBA8 model only: per voxel the lowest and highest value a correct GPU may store for any
  // fragment order (empty otherwise).
  Volume cas_lo, cas_hi;
  // Reference only: per voxel how far its mean may move under the shading freedoms GL leaves
  // the voxelization pass (position snapping, texture LOD, sub-texel weights;
  // freedoms/fragment_slack.h).
  Volume shading_slack;
  // Reference only: 1 where every fragment's light is computed bit for bit by any correct GL
  // (freedoms/fragment_exactness.h), so the fixed-point reduction must agree
  // exactly there.
  Volume exact;
  // Reference only: 1 where a correct GL may leave the voxel's occupancy otherwise than the
  // reference's: every fragment in it may drop, or a fragment GL may make lands in it while the
  // reference's is empty (the coverage ties, freedoms/coverage_ties.h).
  Volume occupancy_tie;
  // Reference only: per voxel the fewest and the most fragments a correct GL may average there
  // (channels lo, hi): the reference's count less those that may drop, plus those it may make
  // (freedoms/coverage_ties.h, fragment_count_ranges).
  Volume fragment_count_range;
};

/// Axis directions of the anisotropic volumes, in this order: +x, -x, +y, -y, +z, -z.
enum AnisoDir : int { kPosX = 0, kNegX, kPosY, kNegY, kPosZ, kNegZ };
constexpr std::array<const char*, 6> kAnisoDirNames = {"posx", "negx", "posy", "negy", "posz", "negz"};

/// Mip pyramids built from VoxelGrid::radiance. iso[0] is the base level itself.
/// aniso[d][0] is level 1 of direction d (the base level is shared with iso[0]: 1.5x memory).
struct VoxelMips {
  std::vector<Volume> iso;
  std::array<std::vector<Volume>, 6> aniso;
  bool anisotropic() const { return !aniso[0].empty(); }
};

/// The final frame and its components (all linear radiance, 3 channels, row 0 = top).
/// final = direct + kd*albedo*indirect_diffuse + F*indirect_specular + emission (+ particles).
struct FrameImages {
  Image direct;            // Cook–Torrance from the lights with shadow-map (or cone) visibility
  Image indirect_diffuse;  // cosine-weighted mean incident radiance from the diffuse cones
  Image indirect_specular; // incident radiance from the specular cone
  Image diffuse_term;      // kd * albedo * indirect_diffuse (what final adds)
  Image specular_term;     // F * indirect_specular (what final adds)
  Image emission;
  Image particles;         // additive particle layer
  Image soft_shadow;       // 1: cone-traced visibility (if enabled)
  Image final_image;
  std::vector<Image> diffuse_cones;  // ref only: each diffuse cone's (rgb, opacity), cone order of vct_shared.h
};

/// Everything one VCT frame computed; either backend fills what it ran.
struct FrameResult {
  std::string backend;  // "ref" or "gl"
  std::vector<ShadowMap> shadow_maps;
  GBuffer gbuffer;
  VoxelGrid voxels;
  Volume conservative_occupancy;  // 1: exact triangle-box voxelization (ref only)
  Volume holes;                   // 1: voxels the conservative set has and the GPU rule misses
  VoxelMips mips;
  FrameImages images;
  std::vector<double> multibounce_energy;  // total voxel radiance after each multibounce frame
  // ref only: the base level after each multibounce frame before the last (kept while small,
  // see stages/pipeline.cpp), for the dumps.
  std::vector<Volume> multibounce_frames;
  // The base level the last multibounce frame traced its bounce light from (the frame before the
  // last; empty after one frame): what voxel.radiance is judged on in bounce frames
  // (compare/isolated_stages.h).
  Volume bounce_input;
  std::map<std::string, double> timings_ms;  // stage name -> milliseconds
  BackendFacts facts;  // what ran and the driver's facts (typed; backend_facts.h)
  std::map<std::string, std::string> info;   // free-form notes only (counts, ...): nothing parses them
};

}  // namespace vct
