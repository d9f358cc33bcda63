// The cones the final frame traces at one surface point: the diffuse cone set (settings
// diffuse_cone_count / diffuse_cone_tilt_deg; the seed's is 5 cones at 45 degrees), the specular
// cone along the reflected view vector and the soft-shadow cone toward a light
// (docs/pipeline.md, "Diffuse cones", "Specular cone", "Soft shadows"). Inputs in world space;
// the volume mapping (uniform scale) turns them into texture space without changing directions.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "shared/vct_shared.h"
#include "stages/cone_trace.h"
#include "stages/march_schedule.h"
#include "stages/mip_sampler.h"

namespace vct {

constexpr int kMaxDiffuseCones = sh::MAX_DIFFUSE_CONES;

/// The shared block of the diffuse cone set (count, sin/cos of the tilt, azimuth step, weights),
/// computed once on the host from the settings; both backends trace from exactly these floats.
/// With the defaults (5 cones, 45 degrees) it reproduces the seed's constants bit for bit.
/// Throws InputError for a count outside 1..kMaxDiffuseCones or a tilt outside (0, 90).
sh::DiffuseConeBlock diffuse_cone_block(const VctSettings& s);

/// One diffuse cone as the settings define it: its direction in the tangent frame (z = normal),
/// full aperture (radians) and weight.
struct DiffuseConeSpec {
  vec3 local{0.0f, 0.0f, 1.0f};
  float aperture = 0.0f;
  float weight = 0.0f;
};

/// The diffuse cones before any rotation: the declared set (settings diffuse_cone_set,
/// core/declared_cones.h) when given, else the count/tilt set of diffuse_cone_block with
/// diffuse_aperture_deg.
std::vector<DiffuseConeSpec> diffuse_cone_specs(const VctSettings& s);

/// The tangent frame the diffuse cones are given in at unit normal n (settings
/// cone_tangent_frame): sh::frame_from_normal, or the source design's cross-hint frame.
sh::Frame diffuse_cone_frame(const vec3& n, ConeTangentFrame kind);

/// Per-cone results of one diffuse cone set, kept for dumps and --explain (entries >= count unused).
struct DiffuseConeSet {
  int count = 0;
  vec3 radiance{0.0f};                         // weighted combination (what the frame uses)
  std::array<vec4, kMaxDiffuseCones> cones{};  // each cone's accumulated (rgb, opacity)
  std::array<Cone, kMaxDiffuseCones> geometry{};
  std::array<float, kMaxDiffuseCones> weights{};
};

/// Everything the cones of one frame share, built once per frame rather than per pixel (issue 20,
/// item 5): the validated diffuse cone block, the march parameters, the apertures, the cones'
/// local directions when rotation is off, and (with `prepare`) the mips prepared for fast lookups
/// (stages/mip_sampler.h). Every trace gives the same bits as the free functions below, which
/// build one of these without preparing the mips. `mips` and `volume` must outlive it.
class ConeFrame {
 public:
  ConeFrame(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, float min_lod = 0.0f,
            bool prepare = true);

  /// The diffuse set at world p, unit normal n, rotated by `rotation` about n; `records` as for
  /// trace_diffuse_cones (recording uses the readable sampler, voxel_sampler.h).
  /// `position_margin` (world units per axis): how far a correct test engine's p may lie from
  /// this one (GBuffer::position_margin); the cones' Cone::origin_margin.
  DiffuseConeSet diffuse(const vec3& p, const vec3& n, float rotation,
                         std::vector<std::vector<ConeSample>>* records = nullptr,
                         const vec3& position_margin = vec3(0.0f)) const;
  /// The rotation of pixel (x, y) (row 0 = top), 0 when rotation is off.
  float rotation_for_pixel(int x, int y) const;
  vec4 specular(const vec3& p, const vec3& n, const vec3& v, float roughness,
                std::vector<ConeSample>* record = nullptr, const vec3& position_margin = vec3(0.0f)) const;
  /// The world point the specular cone's view vector leaves (settings specular_view).
  vec3 specular_view_point(const vec3& p, const vec3& n) const;
  /// 1 - opacity toward the light, marched no further than a spot or point light's position; a
  /// directional light's cone goes against its direction until it leaves the volume.
  float shadow(const vec3& p, const Light& light, std::vector<ConeSample>* record = nullptr) const;
  /// The soft-shadow cone from p toward the light (texture space) and how far it may march.
  Cone shadow_cone(const vec3& p, const Light& light, float* max_distance) const;

  int diffuse_count() const { return count_; }
  /// Every diffuse and specular cone marched with MarchParams::march_end = `variant` (the
  /// march-end tie's alternatives; 0 = the march itself).
  void set_march_end(int variant) { params_.march_end = specular_params_.march_end = variant; }

 private:
  vec4 trace(const Cone& cone, const MarchParams& params, std::vector<ConeSample>* record) const;
  /// The schedule among schedules_ this cone marches, or null.
  const MarchSchedule* schedule_for(const Cone& cone, const MarchParams& params) const;
  /// A world position margin as a cone's origin_margin (texture units).
  vec3 origin_margin(const vec3& position_margin) const;
  /// Cone i's tangent-frame direction turned by `rotation` about the normal.
  vec3 rotated(int i, float rotation, bool unrotated) const;

  const VoxelMips& mips_;
  const VoxelVolume& volume_;
  std::unique_ptr<MipSampler> sampler_;  // null: not prepared (or not preparable)
  // With sampler_: the march steps of the diffuse apertures and of the soft-shadow cone.
  std::vector<MarchSchedule> schedules_;
  sh::DiffuseConeBlock block_;
  int count_ = 0;
  MarchParams params_;       // diffuse and specular
  MarchParams specular_params_;  // MarchParams::specular_from_settings, without min_lod
  SpecularAperture specular_aperture_ = SpecularAperture::Ggx;
  SpecularView specular_view_ = SpecularView::Surface;
  MarchParams shadow_params_;  // MarchParams::shadow_from_settings
  float diffuse_aperture_ = 0.0f, shadow_aperture_ = 0.0f;
  // A declared cone set (diffuse_cone_set): each cone's own aperture and weight, rotated about n
  // by the pixel's rotation; rotations then span a full turn (rotation_block_).
  std::vector<DiffuseConeSpec> declared_;
  sh::DiffuseConeBlock rotation_block_;
  ConeTangentFrame tangent_frame_ = ConeTangentFrame::Branchless;
  bool random_rotation_ = false;
  uint32_t frame_ = 0;
  std::array<vec3, kMaxDiffuseCones> unrotated_{};  // sh::diffuse_cone_direction(i, 0, block)
};

/// Traces the diffuse cone set at world point p with unit normal n, rotated by `rotation` radians
/// about n. `min_lod` > 0 for multibounce (previous frame's mips at level >= 1).
/// `records`, if given, is resized to the cone count and receives every cone's samples.
DiffuseConeSet trace_diffuse_cones(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s,
                                   const vec3& p, const vec3& n, float rotation, float min_lod = 0.0f,
                                   std::vector<std::vector<ConeSample>>* records = nullptr);

/// The cone rotation of pixel (x, y) (row 0 = top) for this frame, or 0 when rotation is off.
float diffuse_rotation_for_pixel(const VctSettings& s, int x, int y);

/// The specular cone's full aperture (radians) for perceptual roughness (settings
/// specular_aperture): sh::specular_cone_aperture(max(r, MIN_ROUGHNESS)), or the source design's
/// 2 (c0 + a (c1 - c2 a)) with a = clamp(r, 0, 1)^2.
float specular_cone_aperture_of(SpecularAperture kind, float roughness);

/// Specular cone at p: along reflect(-v, n), aperture specular_cone_aperture_of(kind, roughness);
/// its origin moved `normal_offset` (texture units, MarchParams::normal_offset) along n.
Cone specular_cone(const VoxelVolume& volume, const vec3& p, const vec3& n, const vec3& v, float roughness,
                   float normal_offset = 0.0f, SpecularAperture kind = SpecularAperture::Ggx);
/// The world point the specular view vector leaves: p, or (SpecularView::Origin) p moved
/// `normal_offset` texture units along n, where the cone starts.
vec3 specular_view_point(const VoxelVolume& volume, SpecularView view, float normal_offset, const vec3& p,
                         const vec3& n);
/// The specular cone of the settings (MarchParams::specular_from_settings, specular_aperture),
/// with the view vector v the caller took (specular_view_point).
vec4 trace_specular_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                         const vec3& n, const vec3& v, float roughness, std::vector<ConeSample>* record = nullptr);

/// Soft-shadow visibility 1 - opacity of a cone from p toward the light, aperture
/// settings.soft_shadow_aperture_deg, marched no further than the light (ConeFrame::shadow).
float trace_shadow_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                        const Light& light, std::vector<ConeSample>* record = nullptr);

}  // namespace vct
