#include "stages/cone_sets.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/declared_cones.h"
#include "core/error.h"

namespace vct {

static_assert(kMaxDiffuseCones == kMaxDiffuseConeCount, "the shared header and the settings disagree on the cone limit");

namespace {
float radians(float deg) { return deg * (kPi / 180.0f); }
int grid_of(const VoxelMips& mips) { return mips.iso.empty() ? 1 : std::max(mips.iso[0].nx, 1); }
}  // namespace

sh::DiffuseConeBlock diffuse_cone_block(const VctSettings& s) {
  const int count = s.diffuse_cone_count;
  if (count < 1 || count > kMaxDiffuseCones)
    throw InputError("", "diffuse_cone_count must be in 1.." + std::to_string(kMaxDiffuseCones) + " (got " +
                             std::to_string(count) + ")");
  if (!(s.diffuse_cone_tilt_deg > 0.0f && s.diffuse_cone_tilt_deg < 90.0f)) {
    std::ostringstream got;
    got << s.diffuse_cone_tilt_deg;
    throw InputError("", "diffuse_cone_tilt_deg must be in (0, 90) (got " + got.str() + ")");
  }
  // In double, rounded once: for 45 degrees both give 0.70710677f, the seed's literal
  // 0.70710678118654752f (tests/ref/cone_set_test.cpp checks), and for count 5 the step
  // 2 pi / 4 rounds to exactly 0.5f * SH_PI.
  const double tilt = double(s.diffuse_cone_tilt_deg) * (3.14159265358979323846 / 180.0);
  const float sin_t = float(std::sin(tilt)), cos_t = float(std::cos(tilt));
  const float step = count > 1 ? float(2.0 * 3.14159265358979323846 / double(count - 1)) : 0.0f;
  sh::DiffuseConeBlock b;
  b.shape = vec4(sin_t, cos_t, step, float(count));
  if (s.diffuse_weighting == DiffuseWeighting::Cosine) {
    // The seed's order of operations (1 + 4 c, then each cosine over the total), so count 5 keeps
    // its bits.
    const float total = 1.0f + float(count - 1) * cos_t;
    b.weights = vec4(1.0f / total, cos_t / total, 0.0f, 0.0f);
  } else {
    b.weights = vec4(1.0f, 1.0f, 0.0f, 0.0f);
  }
  return b;
}

namespace {
std::vector<DiffuseConeSpec> declared_specs(const VctSettings& s) {
  std::vector<DiffuseConeSpec> out;
  for (const DeclaredCone& c : parse_declared_cones(s.diffuse_cone_set))
    out.push_back({c.direction, radians(c.aperture_deg), c.weight});
  return out;
}
}  // namespace

std::vector<DiffuseConeSpec> diffuse_cone_specs(const VctSettings& s) {
  std::vector<DiffuseConeSpec> out = declared_specs(s);
  if (!out.empty()) return out;
  const sh::DiffuseConeBlock block = diffuse_cone_block(s);
  for (int i = 0; i < sh::diffuse_cone_count(block); ++i)
    out.push_back({sh::diffuse_cone_direction(i, 0.0f, block), radians(s.diffuse_aperture_deg),
                   sh::diffuse_cone_weight(i, block)});
  return out;
}

sh::Frame diffuse_cone_frame(const vec3& n, ConeTangentFrame kind) {
  if (kind == ConeTangentFrame::Branchless) return sh::frame_from_normal(n);
  // righier/gidemo voxelcone.frag ortho(): the hint (0.1, 0, 1) unless n is within ~2.6 degrees
  // of it, then (1, 0, 0); t = normalize(n x hint), b = n x t.
  const vec3 hint(0.1f, 0.0f, 1.0f);
  const vec3 w = std::abs(glm::dot(n, glm::normalize(hint))) < 0.999f ? hint : vec3(1.0f, 0.0f, 0.0f);
  sh::Frame f;
  f.t = glm::normalize(glm::cross(n, w));
  f.b = glm::cross(n, f.t);
  f.n = n;
  return f;
}

ConeFrame::ConeFrame(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, float min_lod,
                     bool prepare)
    : mips_(mips), volume_(volume), block_(diffuse_cone_block(s)) {
  count_ = sh::diffuse_cone_count(block_);
  params_ = MarchParams::from_settings(s, grid_of(mips));
  specular_params_ = MarchParams::specular_from_settings(s, grid_of(mips));
  specular_aperture_ = s.specular_aperture;
  specular_view_ = s.specular_view;
  shadow_params_ = MarchParams::shadow_from_settings(s, grid_of(mips));
  params_.min_lod = min_lod;
  diffuse_aperture_ = radians(s.diffuse_aperture_deg);
  shadow_aperture_ = radians(s.soft_shadow_aperture_deg);
  random_rotation_ = s.random_rotation;
  frame_ = uint32_t(s.frame);
  tangent_frame_ = s.cone_tangent_frame;
  declared_ = declared_specs(s);
  if (!declared_.empty()) count_ = int(declared_.size());
  rotation_block_ = block_;
  if (!declared_.empty()) rotation_block_.shape.z = 2.0f * kPi;
  for (int i = 0; i < count_; ++i)
    unrotated_[size_t(i)] = declared_.empty() ? sh::diffuse_cone_direction(i, 0.0f, block_) : declared_[size_t(i)].local;
  if (prepare) {
    sampler_ = std::make_unique<MipSampler>(mips);
    if (!sampler_->usable()) sampler_.reset();
  }
  if (sampler_) {
    const float voxel = 1.0f / float(sampler_->base_size());  // as trace_cone forms it
    const auto add_schedule = [&](float aperture, const MarchParams& params) {
      for (const MarchSchedule& known : schedules_)
        if (known.fits(aperture, params, voxel)) return;
      schedules_.emplace_back(aperture, params, voxel);
    };
    if (declared_.empty()) add_schedule(diffuse_aperture_, params_);
    for (const DiffuseConeSpec& spec : declared_) add_schedule(spec.aperture, params_);
    add_schedule(shadow_aperture_, shadow_params_);
  }
}

const MarchSchedule* ConeFrame::schedule_for(const Cone& cone, const MarchParams& params) const {
  const float voxel = 1.0f / float(sampler_->base_size());
  for (const MarchSchedule& schedule : schedules_)
    if (schedule.fits(cone.aperture, params, voxel)) return &schedule;
  return nullptr;
}

vec4 ConeFrame::trace(const Cone& cone, const MarchParams& params, std::vector<ConeSample>* record) const {
  if (sampler_ && !record) return trace_cone(*sampler_, cone, params, schedule_for(cone, params));
  return trace_cone(mips_, cone, params, record);
}

vec3 ConeFrame::origin_margin(const vec3& position_margin) const {
  if (!(position_margin.x > 0.0f || position_margin.y > 0.0f || position_margin.z > 0.0f)) return vec3(0.0f);
  // Texture coordinates are at most 1 or so: the engine's world-to-texture map and its normal
  // offset, each with a rounding or two (or a fused multiply-add) that ours need not share, add
  // 8 units in the last place of 1 on every axis (docs/compare.md, "The start-face tie").
  constexpr float kRounding = 8.0f / 16777216.0f;
  return position_margin / volume_.size + vec3(kRounding);
}

DiffuseConeSet ConeFrame::diffuse(const vec3& p, const vec3& n, float rotation,
                                  std::vector<std::vector<ConeSample>>* records,
                                  const vec3& position_margin) const {
  const sh::Frame frame = diffuse_cone_frame(n, tangent_frame_);
  DiffuseConeSet set;
  set.count = count_;
  if (records) records->assign(size_t(set.count), {});
  const vec3 origin = params_.origin_at(volume_.to_texture(p), n);
  // rotation == 0 (also -0: phi = rotation + k step is then the same float) is the unrotated set.
  const bool unrotated = rotation == 0.0f;
  const vec3 margin = origin_margin(position_margin);
  for (int i = 0; i < set.count; ++i) {
    Cone& cone = set.geometry[size_t(i)];
    cone.origin = origin;
    cone.origin_margin = margin;
    cone.direction = glm::normalize(sh::frame_to_world(frame, rotated(i, rotation, unrotated)));
    cone.aperture = declared_.empty() ? diffuse_aperture_ : declared_[size_t(i)].aperture;
  }
  for (int i = 0; i < set.count; ++i)
    set.cones[size_t(i)] = trace(set.geometry[size_t(i)], params_, records ? &(*records)[size_t(i)] : nullptr);
  for (int i = 0; i < set.count; ++i) {
    set.weights[size_t(i)] = declared_.empty() ? sh::diffuse_cone_weight(i, block_) : declared_[size_t(i)].weight;
    set.radiance += set.weights[size_t(i)] * vec3(set.cones[size_t(i)]);
  }
  return set;
}

float ConeFrame::rotation_for_pixel(int x, int y) const {
  if (!random_rotation_) return 0.0f;
  return sh::diffuse_cone_rotation(uint32_t(x), uint32_t(y), frame_, rotation_block_);
}

vec3 ConeFrame::rotated(int i, float rotation, bool unrotated) const {
  if (unrotated) return unrotated_[size_t(i)];
  if (declared_.empty()) return sh::diffuse_cone_direction(i, rotation, block_);
  // A declared cone turns about the normal (z) by the rotation.
  const vec3 d = declared_[size_t(i)].local;
  const float c = std::cos(rotation), s = std::sin(rotation);
  return vec3(c * d.x - s * d.y, s * d.x + c * d.y, d.z);
}

vec4 ConeFrame::specular(const vec3& p, const vec3& n, const vec3& v, float roughness,
                         std::vector<ConeSample>* record, const vec3& position_margin) const {
  Cone cone = specular_cone(volume_, p, n, v, roughness, specular_params_.normal_offset, specular_aperture_);
  cone.origin_margin = origin_margin(position_margin);
  return trace(cone, specular_params_, record);
}

vec3 ConeFrame::specular_view_point(const vec3& p, const vec3& n) const {
  return vct::specular_view_point(volume_, specular_view_, specular_params_.normal_offset, p, n);
}

Cone ConeFrame::shadow_cone(const vec3& p, const Light& light, float* max_distance) const {
  Cone cone;
  cone.origin = volume_.to_texture(p);
  cone.aperture = shadow_aperture_;
  *max_distance = shadow_params_.max_distance;
  if (light.is_directional()) {
    // The sun is infinitely far: the cone runs against its direction (a world direction is the
    // same in texture space, a uniform scale) until the marcher leaves the volume.
    cone.direction = -glm::normalize(light.direction);
    return cone;
  }
  const vec3 to_light = volume_.to_texture(light.position) - cone.origin;
  const float dist = glm::length(to_light);
  cone.direction = dist > 0.0f ? to_light / dist : vec3(0.0f, 0.0f, 1.0f);
  *max_distance = std::min(*max_distance, dist);  // occluders behind the light don't count
  return cone;
}

float ConeFrame::shadow(const vec3& p, const Light& light, std::vector<ConeSample>* record) const {
  MarchParams params = shadow_params_;
  const Cone cone = shadow_cone(p, light, &params.max_distance);
  if (!(params.max_distance > 0.0f)) return 1.0f;
  return 1.0f - trace(cone, params, record).a;
}

DiffuseConeSet trace_diffuse_cones(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s,
                                   const vec3& p, const vec3& n, float rotation, float min_lod,
                                   std::vector<std::vector<ConeSample>>* records) {
  return ConeFrame(mips, volume, s, min_lod, false).diffuse(p, n, rotation, records);
}

float diffuse_rotation_for_pixel(const VctSettings& s, int x, int y) {
  if (!s.random_rotation) return 0.0f;
  sh::DiffuseConeBlock block = diffuse_cone_block(s);
  if (!declared_specs(s).empty()) block.shape.z = 2.0f * kPi;  // a declared set turns a full circle
  return sh::diffuse_cone_rotation(uint32_t(x), uint32_t(y), uint32_t(s.frame), block);
}

float specular_cone_aperture_of(SpecularAperture kind, float roughness) {
  // Same clamp as sh::surface_pbr, so the cone matches the roughness the BRDF uses.
  if (kind == SpecularAperture::Ggx) return sh::specular_cone_aperture(std::max(roughness, sh::MIN_ROUGHNESS));
  // righier/gidemo voxelcone.frag: roughnessToAperture(r^2) returns tan(half-angle), doubled into
  // the apertureTan2 = 2 tan(aperture / 2) its ConeTracing takes.
  const float r = std::clamp(roughness, 0.0f, 1.0f);
  const float a = r * r;
  return 2.0f * (0.0003474660443456835f + a * (1.3331290497744692f - a * 0.5040552688878546f));
}

Cone specular_cone(const VoxelVolume& volume, const vec3& p, const vec3& n, const vec3& v, float roughness,
                  float normal_offset, SpecularAperture kind) {
  Cone cone;
  cone.origin = volume.to_texture(p) + n * normal_offset;
  cone.direction = glm::normalize(glm::reflect(-v, n));
  cone.aperture = specular_cone_aperture_of(kind, roughness);
  return cone;
}

vec3 specular_view_point(const VoxelVolume& volume, SpecularView view, float normal_offset, const vec3& p,
                         const vec3& n) {
  // Texture units to world: the volume's uniform scale.
  return view == SpecularView::Origin ? p + n * (normal_offset * volume.size) : p;
}

vec4 trace_specular_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                         const vec3& n, const vec3& v, float roughness, std::vector<ConeSample>* record) {
  const MarchParams params = MarchParams::specular_from_settings(s, grid_of(mips));
  return trace_cone(mips, specular_cone(volume, p, n, v, roughness, params.normal_offset, s.specular_aperture),
                    params, record);
}

float trace_shadow_cone(const VoxelMips& mips, const VoxelVolume& volume, const VctSettings& s, const vec3& p,
                        const Light& light, std::vector<ConeSample>* record) {
  return ConeFrame(mips, volume, s, 0.0f, false).shadow(p, light, record);
}

}  // namespace vct
