#include "stages/stage_registry.h"

#include <cstdlib>
#include <stdexcept>

namespace vct {

namespace {

// Slot accessors. Single stages ignore the index; families grow on demand when asked to.
template <Image GBuffer::*M>
Image* gbuffer(FrameResult& f, int, bool) { return &(f.gbuffer.*M); }
template <Image FrameImages::*M>
Image* frame_image_slot(FrameResult& f, int, bool) { return &(f.images.*M); }
template <Volume VoxelGrid::*M>
Volume* voxels(FrameResult& f, int, bool) { return &(f.voxels.*M); }

Image* shadow_map(FrameResult& f, int i, bool grow) {
  if (i < 0) return nullptr;
  if (size_t(i) >= f.shadow_maps.size()) {
    if (!grow) return nullptr;
    f.shadow_maps.resize(size_t(i) + 1);
  }
  return &f.shadow_maps[size_t(i)].depth;
}
// Member light * 6 + face of a point light's cube; spot and directional lights hold empty faces.
Image* cube_face(FrameResult& f, int i, bool grow) {
  if (i < 0) return nullptr;
  const size_t light = size_t(i / 6);
  if (light >= f.shadow_maps.size()) {
    if (!grow) return nullptr;
    f.shadow_maps.resize(light + 1);
  }
  return &f.shadow_maps[light].cube[size_t(i % 6)];
}
// The reference's light-space raster alternatives beside each map (freedoms/shadow_map_ties.h).
Image* shadow_tie_range(FrameResult& f, int i, bool grow) {
  Image* map = shadow_map(f, i, grow);
  return map ? &f.shadow_maps[size_t(i)].tie_range : nullptr;
}
Image* cube_face_tie_range(FrameResult& f, int i, bool grow) {
  Image* face = cube_face(f, i, grow);
  return face ? &f.shadow_maps[size_t(i / 6)].cube_tie_range[size_t(i % 6)] : nullptr;
}
Volume* conservative(FrameResult& f, int, bool) { return &f.conservative_occupancy; }
Volume* holes(FrameResult& f, int, bool) { return &f.holes; }
Volume* bounce_input(FrameResult& f, int, bool) { return &f.bounce_input; }
// Multibounce frame k >= 1 (before the last) is multibounce_frames[k - 1].
Volume* bounce_frame(FrameResult& f, int frame, bool grow) {
  if (frame < 1) return nullptr;
  if (size_t(frame) > f.multibounce_frames.size()) {
    if (!grow) return nullptr;
    f.multibounce_frames.resize(size_t(frame));
  }
  return &f.multibounce_frames[size_t(frame) - 1];
}
// iso[0] is the base level itself (voxel.radiance); the family starts at level 1.
Volume* iso_level(FrameResult& f, int level, bool grow) {
  if (level < 1) return nullptr;
  if (size_t(level) >= f.mips.iso.size()) {
    if (!grow) return nullptr;
    f.mips.iso.resize(size_t(level) + 1);
  }
  return &f.mips.iso[size_t(level)];
}
// aniso[d][0] is level 1 of direction d (the base level is shared with iso[0]).
template <int D>
Volume* aniso_level(FrameResult& f, int level, bool grow) {
  auto& chain = f.mips.aniso[size_t(D)];
  if (level < 1) return nullptr;
  if (size_t(level) > chain.size()) {
    if (!grow) return nullptr;
    chain.resize(size_t(level));
  }
  return &chain[size_t(level) - 1];
}

using K = StageKind;
using X = StageIndex;
using R = StageRole;
using P = Preview;
using T = ToleranceModel;
using C = ConeInput;
namespace st = stage_names;

// clang-format off
const std::vector<StageRow> kRows = {
  // name                        dump stem                        kind       index        role          preview      model              own    cone input            ch PT AOV                  image slot                                         volume slot
  //  what it holds, docs/pipeline.md section, reference source, GL source, report walkthrough step (one
  //  anisotropic direction stands for all six there)
  {st::kShadowMap,             "shadow_map_{}",                 K::Image,  X::Light,    R::Judged,    P::Depth,    T::Depth,          false, C::No,                1, "",                     shadow_map,                                        nullptr,
   "a spot (perspective) or directional (orthographic) light's D32F depth map", "Shadow maps", "ref/stages/shadow_map.cpp", "gl/gl_pass_raster.cpp (shadow_pass), gl/shaders/depth_only.frag", "shadow"},
  {st::kShadowMapCube,         "shadow_map_cube_{}",            K::Image,  X::CubeFace, R::Judged,    P::Depth,    T::Depth,          false, C::No,                1, "",                     cube_face,                                         nullptr,
   "one face of a point light's D32F cube (member light x 6 + face, GL's face order +x -x +y -y +z -z)", "Shadow maps", "ref/stages/shadow_map.cpp, ref/stages/cube_map.cpp", "gl/gl_pass_raster.cpp (shadow_pass), gl/shaders/depth_only.frag", "shadow"},
  {st::kShadowMapTieRange,     "",                              K::Image,  X::Light,    R::Auxiliary, P::Unit,     T::None,           false, C::No,                0, "",                     shadow_tie_range,                                  nullptr,
   "per texel of a spot or directional light's map, the range of the depths a correct GL may store under 2^-8 texel vertex snapping and alpha-test ties (reference only)", "Shadow maps", "ref/freedoms/shadow_map_ties.cpp, ref/freedoms/raster_alternatives.cpp", "-", "shadow"},
  {st::kShadowMapCubeTieRange, "",                              K::Image,  X::CubeFace, R::Auxiliary, P::Unit,     T::None,           false, C::No,                0, "",                     cube_face_tie_range,                               nullptr,
   "the same range per texel of one face of a point light's cube (member light x 6 + face; reference only)", "Shadow maps", "ref/freedoms/shadow_map_ties.cpp, ref/freedoms/raster_alternatives.cpp", "-", "shadow"},
  {st::kGbufferCoverage,       "gbuffer_coverage",              K::Image,  X::None,     R::Judged,    P::Unit,     T::Coverage,       false, C::Always,            1, "",                     gbuffer<&GBuffer::coverage>,                       nullptr,
   "the camera G-buffer's coverage per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferDepth,          "gbuffer_depth",                 K::Image,  X::None,     R::Judged,    P::Depth,    T::Depth,          false, C::No,                1, "",                     gbuffer<&GBuffer::depth>,                          nullptr,
   "the camera G-buffer's window depth per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferPosition,       "gbuffer_position",              K::Image,  X::None,     R::Judged,    P::Position, T::Position,       false, C::Always,            3, "",                     gbuffer<&GBuffer::position>,                       nullptr,
   "the camera G-buffer's world position per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferNormal,         "gbuffer_normal",                K::Image,  X::None,     R::Judged,    P::Signed,   T::NormalMap,      false, C::Always,            3, "",                     gbuffer<&GBuffer::normal>,                         nullptr,
   "the camera G-buffer's shading normal (after normal mapping) per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferAlbedo,         "gbuffer_albedo",                K::Image,  X::None,     R::Judged,    P::Color,    T::Texture,        false, C::Always,            3, "",                     gbuffer<&GBuffer::albedo>,                         nullptr,
   "the camera G-buffer's linear base colour per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferMaterial,       "gbuffer_material",              K::Image,  X::None,     R::Judged,    P::Unit,     T::Texture,        false, C::Always,            4, "",                     gbuffer<&GBuffer::material>,                       nullptr,
   "the camera G-buffer's metallic, roughness, specular factor per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferSpecularColor,  "gbuffer_specular_color",        K::Image,  X::None,     R::Judged,    P::Color,    T::Texture,        false, C::Always,            3, "",                     gbuffer<&GBuffer::specular_color>,                 nullptr,
   "the camera G-buffer's specular colour per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferEmission,       "gbuffer_emission",              K::Image,  X::None,     R::Judged,    P::Color,    T::Texture,        false, C::Always,            3, "",                     gbuffer<&GBuffer::emission>,                       nullptr,
   "the camera G-buffer's emitted radiance per pixel centre", "G-buffer and direct light", "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag", "gbuffer"},
  {st::kGbufferTextureSlack,   "",                              K::Image,  X::None,     R::Auxiliary, P::Unit,     T::None,           false, C::No,                0, "",                     gbuffer<&GBuffer::texture_slack>,                  nullptr,
   "how far each textured G-buffer value moves under a 2^-8 px sample shift and any admissible texture LOD (reference only)", "G-buffer and direct light", "ref/freedoms/texture_slack.cpp, ref/stages/uv_derivatives.cpp", "-", "gbuffer"},
  {st::kGbufferTieRange,       "",                              K::Image,  X::None,     R::Auxiliary, P::Unit,     T::None,           false, C::No,                0, "",                     gbuffer<&GBuffer::tie_range>,                      nullptr,
   "per G-buffer stage and channel, the range of the values a correct GL may show where an edge or a triangle's facing ties under 2^-8 px vertex snapping (reference only)", "G-buffer and direct light", "ref/freedoms/gbuffer_ties.cpp", "-", "gbuffer"},
  {st::kImageDirect,           "direct",                        K::Image,  X::None,     R::Judged,    P::Color,    T::Shading,        false, C::UnlessSoftShadows, 3, "pt_direct",            frame_image_slot<&FrameImages::direct>,            nullptr,
   "Cook-Torrance direct light with shadow-map (or cone) visibility", "G-buffer and direct light", "ref/stages/direct.cpp", "gl/gl_pass_shading.cpp (direct_pass), gl/shaders/direct.frag", "direct"},
  {st::kVoxelOccupancy,        "voxels_occupancy",              K::Volume, X::None,     R::Derived,   P::Volume,   T::VoxelOccupancy, false, C::No,                0, "",                     nullptr,                                           nullptr,
   "which voxels the voxelizer's coverage rule fills", "Voxelizers", "ref/stages/voxelize_gpu.cpp", "gl/gl_pass_voxel.cpp (voxelize), gl/shaders/voxelize.geom", ""},
  {st::kVoxelFrame,            "multibounce_frame_{}",          K::Volume, X::Frame,    R::Judged,    P::Volume,   T::VoxelFrame,     false, C::No,                4, "",                     nullptr,                                           bounce_frame,
   "multibounce: the base level after frame <frame> (1 = direct light only; every frame before the last), judged like voxel.radiance on the test's own previous frame (compare/bounce_frames.h)", "Temporal multibounce", "ref/stages/multibounce.cpp", "gl/gl_pass_voxel.cpp (voxel_passes)", ""},
  {st::kVoxelRadiance,         "voxels_radiance_L0",            K::Volume, X::None,     R::Judged,    P::Volume,   T::VoxelRadiance,  false, C::Always,            4, "",                     nullptr,                                           voxels<&VoxelGrid::radiance>,
   "injected voxel radiance (RGB) and opacity (A), averaged per voxel", "Reduction", "ref/stages/voxelize.cpp, ref/stages/inject.cpp, ref/stages/reduction.cpp", "gl/gl_pass_voxel.cpp (voxelize, resolve), gl/shaders/voxelize.frag, gl/shaders/voxel_resolve.comp", "inject"},
  {st::kVoxelEnergy,           "",                              K::Volume, X::None,     R::Derived,   P::Volume,   T::VoxelEnergy,    false, C::No,                0, "",                     nullptr,                                           nullptr,
   "multibounce: the total RGB radiance after each frame (run.json's multibounce_energy), each frame judged against the reference's frame on the test's own inputs within the sum of its voxels' bounds", "Temporal multibounce", "ref/stages/multibounce.cpp (total_energy)", "gl/gl_pass_voxel.cpp (voxel_passes)", ""},
  {st::kVoxelFragments,        "voxels_fragments",              K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           voxels<&VoxelGrid::fragments>,
   "fragments (surface samples) per voxel", "Voxelizers", "ref/stages/voxelize_gpu.cpp", "gl/gl_pass_voxel.cpp (voxelize)", "voxelize"},
  {st::kVoxelCasLo,            "voxels_cas_lo",                 K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           voxels<&VoxelGrid::cas_lo>,
   "lowest value a correct CAS running average may store (reference only)", "Reduction", "ref/freedoms/reduction_interval.cpp, ref/stages/reduction.cpp", "-", ""},
  {st::kVoxelCasHi,            "voxels_cas_hi",                 K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           voxels<&VoxelGrid::cas_hi>,
   "highest value a correct CAS running average may store (reference only)", "Reduction", "ref/freedoms/reduction_interval.cpp, ref/stages/reduction.cpp", "-", ""},
  {st::kVoxelShadingSlack,     "voxels_shading_slack",          K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           voxels<&VoxelGrid::shading_slack>,
   "how far each voxel's mean light may move under GL's shading freedoms: 2^-8 voxel position snapping, texture LOD, sub-texel weights, and which fragments the snapped raster averages (reference only)", "Reduction", "ref/freedoms/fragment_slack.cpp, ref/stages/voxel_lod.cpp, ref/freedoms/coverage_ties.cpp", "-", ""},
  {st::kVoxelExact,            "voxels_exact",                  K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           voxels<&VoxelGrid::exact>,
   "1 where every fragment's light is bit-determined (emission from constants, no light reaching the fragment, no bounce, no particles): the fixed-point reduction must agree exactly there (reference only)", "Reduction", "ref/freedoms/fragment_exactness.cpp", "-", ""},
  {st::kVoxelOccupancyTie,     "voxels_occupancy_tie",          K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           voxels<&VoxelGrid::occupancy_tie>,
   "1 where a correct GL may leave the voxel empty (every fragment in it may drop) or occupied (a fragment it may make lands there) otherwise than the reference: the coverage ties of 2^-8 px vertex snapping (reference only)", "Voxelizers", "ref/freedoms/coverage_ties.cpp", "-", ""},
  {st::kVoxelFragmentCountRange, "voxels_fragment_count_range",   K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           voxels<&VoxelGrid::fragment_count_range>,
   "the fewest and the most fragments a correct GL may average in each voxel (lo, hi): the reference's count less those that may drop, plus those it may make under the coverage ties; a test count inside is a coverage tie, not counted against the 2 % cap (reference only)", "Voxelizers", "ref/freedoms/coverage_ties.cpp", "-", ""},
  {st::kVoxelBounceInput,      "voxels_bounce_input",           K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           bounce_input,
   "multibounce: the base level of the frame before the last, whose mips the last frame's bounce light was traced in; voxel.radiance is judged on the test's own (compare/isolated_stages.h)", "Temporal multibounce", "ref/stages/multibounce.cpp", "gl/gl_pass_voxel.cpp (voxel_passes)", ""},
  {st::kVoxelConservative,     "voxels_conservative_occupancy", K::Volume, X::None,     R::Auxiliary, P::Volume,   T::None,           false, C::No,                0, "",                     nullptr,                                           conservative,
   "exact triangle-box voxel occupancy (reference only)", "Voxelizers", "ref/stages/voxelize_conservative.cpp", "-", "voxelize"},
  {st::kVoxelHoles,            "holes",                         K::Volume, X::None,     R::Judged,    P::Volume,   T::VoxelHoles,     false, C::No,                0, "",                     nullptr,                                           holes,
   "voxels the conservative set has and the sample rule misses", "Voxelizers", "ref/stages/voxelize_conservative.cpp", "gl/shaders/voxelize.geom", ""},
  {st::kMipIso,                "voxels_radiance_L{}",           K::Volume, X::MipLevel, R::Judged,    P::Volume,   T::Mip,            false, C::ChosenMips,        4, "",                     nullptr,                                           iso_level,
   "isotropic 2x2x2 box-filtered mip level", "Mips", "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_iso.comp", "mips"},
  {st::kMipPosx,               "aniso_posx_L{}",                K::Volume, X::MipLevel, R::Judged,    P::Volume,   T::Mip,            false, C::ChosenMips,        4, "",                     nullptr,                                           aniso_level<kPosX>,
   "anisotropic mip level seen along +x (front-to-back pairs)", "Mips", "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_aniso.comp", "mips"},
  {st::kMipNegx,               "aniso_negx_L{}",                K::Volume, X::MipLevel, R::Judged,    P::Volume,   T::Mip,            false, C::ChosenMips,        4, "",                     nullptr,                                           aniso_level<kNegX>,
   "anisotropic mip level seen along -x (front-to-back pairs)", "Mips", "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_aniso.comp", ""},
  {st::kMipPosy,               "aniso_posy_L{}",                K::Volume, X::MipLevel, R::Judged,    P::Volume,   T::Mip,            false, C::ChosenMips,        4, "",                     nullptr,                                           aniso_level<kPosY>,
   "anisotropic mip level seen along +y (front-to-back pairs)", "Mips", "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_aniso.comp", ""},
  {st::kMipNegy,               "aniso_negy_L{}",                K::Volume, X::MipLevel, R::Judged,    P::Volume,   T::Mip,            false, C::ChosenMips,        4, "",                     nullptr,                                           aniso_level<kNegY>,
   "anisotropic mip level seen along -y (front-to-back pairs)", "Mips", "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_aniso.comp", ""},
  {st::kMipPosz,               "aniso_posz_L{}",                K::Volume, X::MipLevel, R::Judged,    P::Volume,   T::Mip,            false, C::ChosenMips,        4, "",                     nullptr,                                           aniso_level<kPosZ>,
   "anisotropic mip level seen along +z (front-to-back pairs)", "Mips", "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_aniso.comp", ""},
  {st::kMipNegz,               "aniso_negz_L{}",                K::Volume, X::MipLevel, R::Judged,    P::Volume,   T::Mip,            false, C::ChosenMips,        4, "",                     nullptr,                                           aniso_level<kNegZ>,
   "anisotropic mip level seen along -z (front-to-back pairs)", "Mips", "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_aniso.comp", ""},
  {st::kImageSoftShadow,       "soft_shadow",                   K::Image,  X::None,     R::Judged,    P::Unit,     T::ConeVisibility, true,  C::No,                1, "",                     frame_image_slot<&FrameImages::soft_shadow>,       nullptr,
   "cone-traced visibility toward the light", "Soft shadows", "ref/stages/soft_shadow.cpp", "gl/gl_pass_shading.cpp (direct_pass), gl/shaders/direct.frag", "soft"},
  {st::kImageIndirectDiffuse,  "indirect_diffuse",              K::Image,  X::None,     R::Judged,    P::Color,    T::Filtered,       true,  C::No,                3, "",                     frame_image_slot<&FrameImages::indirect_diffuse>,  nullptr,
   "incident radiance gathered by the diffuse cones", "Diffuse cones and their weights", "ref/stages/cone_trace.cpp, ref/stages/indirect_pass.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/cone.glsl", "indirect_diffuse"},
  {st::kImageIndirectSpecular, "indirect_specular",             K::Image,  X::None,     R::Judged,    P::Color,    T::Filtered,       true,  C::No,                3, "",                     frame_image_slot<&FrameImages::indirect_specular>, nullptr,
   "incident radiance of the specular cone", "Specular cone", "ref/stages/cone_trace.cpp, ref/stages/indirect_pass.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/cone.glsl", "specular"},
  {st::kImageDiffuseTerm,      "diffuse_term",                  K::Image,  X::None,     R::Judged,    P::Color,    T::Filtered,       true,  C::No,                3, "pt_indirect_diffuse",  frame_image_slot<&FrameImages::diffuse_term>,      nullptr,
   "kd x albedo x indirect diffuse, the term the final image adds", "Final composite", "ref/stages/composite.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/indirect.frag", "indirect_diffuse"},
  {st::kImageSpecularTerm,     "specular_term",                 K::Image,  X::None,     R::Judged,    P::Color,    T::Filtered,       true,  C::No,                3, "pt_indirect_specular", frame_image_slot<&FrameImages::specular_term>,     nullptr,
   "F x indirect specular, the term the final image adds", "Final composite", "ref/stages/composite.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/indirect.frag", "specular"},
  {st::kImageEmission,         "emission",                      K::Image,  X::None,     R::Judged,    P::Color,    T::Shading,        false, C::No,                3, "pt_emission",          frame_image_slot<&FrameImages::emission>,          nullptr,
   "emitted radiance", "Final composite", "ref/stages/composite.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/indirect.frag", "final"},
  {st::kImageParticles,        "particles",                     K::Image,  X::None,     R::Judged,    P::Color,    T::Filtered,       false, C::WithParticles,     3, "pt_particles",         frame_image_slot<&FrameImages::particles>,         nullptr,
   "the additive fire particle layer", "Particles", "ref/stages/particles.cpp", "gl/gl_pass_shading.cpp (particle_pass), gl/shaders/particles.frag", "final"},
  {st::kImageFinal,            "final",                         K::Image,  X::None,     R::Judged,    P::Color,    T::Filtered,       true,  C::No,                3, "pt_full",              frame_image_slot<&FrameImages::final_image>,       nullptr,
   "direct + kd albedo indirect diffuse + F indirect specular + emission (+ particles)", "Final composite", "ref/stages/composite.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/indirect.frag", "final"},
};
// clang-format on

// "12" -> 12; nullopt for empty, signed or non-digit text (std::stol would accept " 1" or "1x").
std::optional<int> parse_index(const std::string& s) {
  if (s.empty() || s.size() > 6) return std::nullopt;
  int v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
  }
  return v;
}

// Mip levels and multibounce frames count from 1 (level 0 / the last frame is voxel.radiance).
int first_member(const StageRow& row) {
  return row.index == StageIndex::MipLevel || row.index == StageIndex::Frame ? 1 : 0;
}

}  // namespace

const std::vector<StageRow>& stage_rows() { return kRows; }

std::optional<StageRef> find_stage(const std::string& name) {
  for (const StageRow& row : kRows) {
    if (row.index == StageIndex::None) {
      if (name == row.name) return StageRef{&row, 0};
      continue;
    }
    const std::string prefix = std::string(row.name) + ".";
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const auto i = parse_index(name.substr(prefix.size()));
    if (!i || (first_member(row) == 1 && *i < 1)) return std::nullopt;
    return StageRef{&row, *i};
  }
  return std::nullopt;
}

std::optional<StageKind> namespace_kind(const std::string& name) {
  const std::string ns = name.substr(0, name.find('.') + 1);
  if (ns.empty()) return std::nullopt;
  for (const StageRow& row : kRows) {
    const std::string row_name = row.name;
    if (row_name.compare(0, ns.size(), ns) == 0 || row_name + "." == ns) return row.kind;
  }
  return std::nullopt;
}

const StageRow& stage_row(const std::string& name) {
  for (const StageRow& row : kRows)
    if (name == row.name) return row;
  throw std::logic_error("stage registry has no row '" + name + "'");
}

std::string stage_name(const StageRow& row, int index) {
  return row.index == StageIndex::None ? std::string(row.name) : std::string(row.name) + "." + std::to_string(index);
}

std::string dump_stem(const StageRow& row, int index) {
  std::string s = row.dump_stem;
  const size_t at = s.find("{}");
  const std::string member = row.index == StageIndex::CubeFace
                                 ? std::to_string(index / 6) + "_" + kCubeFaceNames[size_t(index % 6)]
                                 : std::to_string(index);
  if (at != std::string::npos) s.replace(at, 2, member);
  return s;
}

const StageRow& mip_row(int direction) {
  for (const StageRow& row : kRows)
    if (row.index == StageIndex::MipLevel && aniso_direction(row) == direction) return row;
  throw std::logic_error("stage registry has no mip chain for direction " + std::to_string(direction));
}

int aniso_direction(const StageRow& row) {
  const std::string name = row.name;
  for (int d = 0; d < 6; ++d)
    if (name == std::string("mip.") + kAnisoDirNames[size_t(d)]) return d;
  return -1;
}

bool judged_on_own_inputs(const StageRow& row, bool soft_shadows) {
  return row.own_inputs || (soft_shadows && row.cone_input == ConeInput::UnlessSoftShadows);
}

const Image* frame_image(const FrameResult& f, const StageRow& row, int index) {
  if (!row.image) return nullptr;
  // The accessors only take the address of a member (no growth without `grow`), so reading
  // through a const frame is safe.
  const Image* img = row.image(const_cast<FrameResult&>(f), index, false);
  return img && !img->empty() ? img : nullptr;
}

const Volume* frame_volume(const FrameResult& f, const StageRow& row, int index) {
  if (!row.volume) return nullptr;
  const Volume* vol = row.volume(const_cast<FrameResult&>(f), index, false);
  return vol && !vol->data.empty() ? vol : nullptr;
}

std::vector<int> frame_members(const FrameResult& f, const StageRow& row) {
  std::vector<int> out;
  const int first = first_member(row);
  for (int i = first;; ++i) {
    const bool held = row.kind == StageKind::Image ? row.image && row.image(const_cast<FrameResult&>(f), i, false)
                                                   : row.volume && row.volume(const_cast<FrameResult&>(f), i, false);
    if (!held) break;
    if (frame_image(f, row, i) || frame_volume(f, row, i)) out.push_back(i);
    if (row.index == StageIndex::None) break;
  }
  return out;
}

}  // namespace vct
