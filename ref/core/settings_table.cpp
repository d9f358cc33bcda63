#include "core/settings_table.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>
#include <type_traits>

#include "core/error.h"
#include "core/reduction_names.h"
#include "io/bounded_json.h"
#include "shared/vct_shared.h"

namespace vct {

namespace {

// JSON names of the enumerations (the settings files' and run.json's spelling).
template <typename Enum>
const std::vector<std::pair<Enum, const char*>>& enum_names();
template <>
const std::vector<std::pair<LightModel, const char*>>& enum_names() {
  static const std::vector<std::pair<LightModel, const char*>> m{{LightModel::Gltf, "gltf"}, {LightModel::Seed, "seed"}};
  return m;
}
template <>
const std::vector<std::pair<ExposureMode, const char*>>& enum_names() {
  static const std::vector<std::pair<ExposureMode, const char*>> m{
      {ExposureMode::Auto, "auto"}, {ExposureMode::Ev100, "ev100"}, {ExposureMode::None, "none"}};
  return m;
}
template <>
const std::vector<std::pair<PtSampler, const char*>>& enum_names() {
  static const std::vector<std::pair<PtSampler, const char*>> m{{PtSampler::Sobol, "sobol"},
                                                                {PtSampler::Independent, "independent"}};
  return m;
}
template <>
const std::vector<std::pair<Voxelizer, const char*>>& enum_names() {
  static const std::vector<std::pair<Voxelizer, const char*>> m{{Voxelizer::Conservative, "conservative"},
                                                                {Voxelizer::GpuEmulation, "gpu"}};
  return m;
}
template <>
const std::vector<std::pair<ConservativeRaster, const char*>>& enum_names() {
  static const std::vector<std::pair<ConservativeRaster, const char*>> m{
      {ConservativeRaster::Off, "off"}, {ConservativeRaster::GeometryShader, "gs"},
      {ConservativeRaster::Nv, "nv"}, {ConservativeRaster::Intel, "intel"}};
  return m;
}
template <>
const std::vector<std::pair<VoxelStorage, const char*>>& enum_names() {
  static const std::vector<std::pair<VoxelStorage, const char*>> m{{VoxelStorage::Rgba8, "rgba8"},
                                                                   {VoxelStorage::Rgba16f, "rgba16f"}};
  return m;
}
template <>
const std::vector<std::pair<Reduction, const char*>>& enum_names() {
  static const std::vector<std::pair<Reduction, const char*>> m = [] {
    std::vector<std::pair<Reduction, const char*>> names;
    for (const ReductionName& r : kReductionNames) names.emplace_back(r.value, r.setting);
    return names;
  }();
  return m;
}

// Other spellings a choice also accepts (read, never written): the manifest's reduction names
// (core/reduction_names.h), so a stage set's "reduction" can be given to --set / --config as is.
template <typename Enum>
const std::vector<std::pair<Enum, const char*>>& enum_aliases() {
  static const std::vector<std::pair<Enum, const char*>> none;
  return none;
}
template <>
const std::vector<std::pair<Reduction, const char*>>& enum_aliases() {
  static const std::vector<std::pair<Reduction, const char*>> m = [] {
    std::vector<std::pair<Reduction, const char*>> names;
    for (const ReductionName& r : kReductionNames)
      if (std::string(r.manifest) != r.setting) names.emplace_back(r.value, r.manifest);
    return names;
  }();
  return m;
}
template <>
const std::vector<std::pair<DiffuseWeighting, const char*>>& enum_names() {
  static const std::vector<std::pair<DiffuseWeighting, const char*>> m{{DiffuseWeighting::Cosine, "cosine"},
                                                                       {DiffuseWeighting::SeedSum, "seed"}};
  return m;
}
template <>
const std::vector<std::pair<ConeStart, const char*>>& enum_names() {
  static const std::vector<std::pair<ConeStart, const char*>> m{{ConeStart::Axis, "axis"},
                                                                {ConeStart::Normal, "normal"}};
  return m;
}

template <>
const std::vector<std::pair<ShadowCompare, const char*>>& enum_names() {
  static const std::vector<std::pair<ShadowCompare, const char*>> m{{ShadowCompare::Nearest, "nearest"},
                                                                    {ShadowCompare::Linear, "linear"}};
  return m;
}

template <>
const std::vector<std::pair<ShadowFilterOrder, const char*>>& enum_names() {
  static const std::vector<std::pair<ShadowFilterOrder, const char*>> m{
      {ShadowFilterOrder::CompareThenFilter, "compare_then_filter"},
      {ShadowFilterOrder::FilterThenCompare, "filter_then_compare"}};
  return m;
}

template <>
const std::vector<std::pair<PcfTapUnit, const char*>>& enum_names() {
  static const std::vector<std::pair<PcfTapUnit, const char*>> m{{PcfTapUnit::Texel, "texel"}, {PcfTapUnit::Uv, "uv"}};
  return m;
}

template <>
const std::vector<std::pair<PcfTapScale, const char*>>& enum_names() {
  static const std::vector<std::pair<PcfTapScale, const char*>> m{{PcfTapScale::None, "none"},
                                                                  {PcfTapScale::InvW, "inv_w"}};
  return m;
}

template <>
const std::vector<std::pair<ShadowBorder, const char*>>& enum_names() {
  static const std::vector<std::pair<ShadowBorder, const char*>> m{
      {ShadowBorder::Clamp, "clamp"}, {ShadowBorder::Lit, "lit"}, {ShadowBorder::Shadowed, "shadowed"}};
  return m;
}

template <>
const std::vector<std::pair<VoxelPcf, const char*>>& enum_names() {
  static const std::vector<std::pair<VoxelPcf, const char*>> m{{VoxelPcf::Same, "same"}, {VoxelPcf::Oracle, "oracle"}};
  return m;
}

template <>
const std::vector<std::pair<ShadowDepthFormat, const char*>>& enum_names() {
  static const std::vector<std::pair<ShadowDepthFormat, const char*>> m{
      {ShadowDepthFormat::Depth32f, "depth32f"}, {ShadowDepthFormat::Depth24, "depth24"},
      {ShadowDepthFormat::Depth16, "depth16"}};
  return m;
}

template <>
const std::vector<std::pair<ConeTangentFrame, const char*>>& enum_names() {
  static const std::vector<std::pair<ConeTangentFrame, const char*>> m{
      {ConeTangentFrame::Branchless, "branchless"}, {ConeTangentFrame::CrossHint, "cross_hint"}};
  return m;
}

template <>
const std::vector<std::pair<IndirectFresnel, const char*>>& enum_names() {
  static const std::vector<std::pair<IndirectFresnel, const char*>> m{
      {IndirectFresnel::Schlick, "schlick"}, {IndirectFresnel::SchlickRoughness, "schlick_roughness"}};
  return m;
}

template <>
const std::vector<std::pair<NdotV, const char*>>& enum_names() {
  static const std::vector<std::pair<NdotV, const char*>> m{
      {NdotV::Zero, "zero"}, {NdotV::Abs, "abs"}, {NdotV::Clamp, "clamp"}};
  return m;
}

template <>
const std::vector<std::pair<SpecularAperture, const char*>>& enum_names() {
  static const std::vector<std::pair<SpecularAperture, const char*>> m{{SpecularAperture::Ggx, "ggx"},
                                                                       {SpecularAperture::Rosseaux, "rosseaux"}};
  return m;
}

template <>
const std::vector<std::pair<SpecularView, const char*>>& enum_names() {
  static const std::vector<std::pair<SpecularView, const char*>> m{{SpecularView::Surface, "surface"},
                                                                   {SpecularView::Origin, "origin"}};
  return m;
}

template <typename Enum>
std::string enum_name(Enum e) {
  for (const auto& [value, name] : enum_names<Enum>())
    if (value == e) return name;
  return "?";
}

template <typename Enum>
std::vector<std::string> choice_names() {
  std::vector<std::string> out;
  for (const auto& [value, name] : enum_names<Enum>()) out.push_back(name);
  return out;
}

std::string join(const std::vector<std::string>& items, const char* sep) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : sep) + s;
  return out;
}

// An integer setting given a number it cannot hold (1e300, 2^32 + 16, 16.5) is bad input: the
// plain conversion would be undefined (float) or wrap silently to a value that may validate
// (reachable from an external stage set's manifest "settings": fuzz/regressions/scene_compare/).
template <typename T>
bool fits_integer(const nlohmann::json& v) {
  using L = std::numeric_limits<T>;
  if (v.is_number_unsigned()) return v.get<uint64_t>() <= uint64_t(L::max());
  if (v.is_number_integer()) return v.get<int64_t>() >= int64_t(L::min()) && v.get<int64_t>() <= int64_t(L::max());
  const double d = v.get<double>();
  return std::isfinite(d) && d == std::trunc(d) && d >= double(L::min()) && d <= double(L::max());
}

template <typename T>
constexpr SettingType type_of() {
  if constexpr (std::is_same_v<T, bool>) return SettingType::Bool;
  else if constexpr (std::is_integral_v<T>) return SettingType::Int;
  else if constexpr (std::is_floating_point_v<T>) return SettingType::Float;
  else if constexpr (std::is_same_v<T, std::string>) return SettingType::Text;
  else return SettingType::Choice;
}

// A row for a plain member (number, bool or text).
template <typename S, typename T>
SettingField<S> field(const char* key, T S::*member, SettingRange range, const char* help,
                      const char* gl_uniform = nullptr) {
  SettingField<S> f{key, type_of<T>(), std::move(range), help, gl_uniform, {}, nullptr, nullptr};
  f.get = [member](const S& s) { return nlohmann::json(s.*member); };
  f.set = [member, key](S& s, const nlohmann::json& j, const std::string& scope) {
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>)
      if (j.is_number() && !fits_integer<T>(j))
        throw InputError("", "setting '" + scope + key + "' = " + j.dump() + " is not an integer in range");
    try {
      s.*member = j.get<T>();
    } catch (const nlohmann::json::exception&) {
      throw InputError("", "setting '" + scope + key + "' has the wrong type");
    }
    // NaN or Inf (--time nan, --offset inf) or a number beyond the float range (1e39) would reach
    // the renderer and run.json (as null); every key refuses them, "any" ranges included.
    if constexpr (std::is_floating_point_v<T>)
      if (!std::isfinite(s.*member))
        throw InputError("", "setting '" + scope + key + "' is not a finite number (NaN, Inf or beyond the float range)");
  };
  return f;
}

// A row for an enumeration, stored by its JSON name.
template <typename S, typename E>
SettingField<S> choice(const char* key, E S::*member, const char* help) {
  SettingField<S> f{key, SettingType::Choice, {}, help, nullptr, choice_names<E>(), nullptr, nullptr};
  f.get = [member](const S& s) { return nlohmann::json(enum_name(s.*member)); };
  f.set = [member, key](S& s, const nlohmann::json& j, const std::string& scope) {
    if (!j.is_string()) throw InputError("", "setting '" + scope + key + "' must be a string");
    const std::string name = j.get<std::string>();
    for (const auto* names : {&enum_names<E>(), &enum_aliases<E>()})
      for (const auto& [value, n] : *names)
        if (name == n) {
          s.*member = value;
          return;
        }
    std::vector<std::string> aliases;
    for (const auto& [value, n] : enum_aliases<E>()) aliases.push_back(n);
    throw InputError("", "setting '" + scope + key + "' is '" + name + "', expected one of " +
                             join(choice_names<E>(), "|") + (aliases.empty() ? "" : " (or " + join(aliases, "|") + ")"));
  };
  return f;
}

// Each range starts from the defaults of SettingRange and sets what it means.
SettingRange closed(double lo, double hi) {
  SettingRange r;
  r.lo = lo, r.hi = hi;
  return r;
}
SettingRange open(double lo, double hi) {
  SettingRange r = closed(lo, hi);
  r.lo_open = r.hi_open = true;
  return r;
}
SettingRange open_lo(double lo, double hi) {
  SettingRange r = closed(lo, hi);
  r.lo_open = true;
  return r;
}
SettingRange at_least(double lo) { return closed(lo, std::numeric_limits<double>::infinity()); }
SettingRange powers_of_two(double lo, double hi) {
  SettingRange r = closed(lo, hi);
  r.power_of_two = true;
  return r;
}
SettingRange one_of(std::vector<int> values) {
  SettingRange r;
  r.only = std::move(values);
  return r;
}
SettingRange any() {
  SettingRange r;
  r.unbounded = true;
  return r;
}

using V = VctSettings;
using P = PtSettings;

}  // namespace

std::string to_string(LightModel m) { return enum_name(m); }
std::string to_string(ExposureMode m) { return enum_name(m); }
std::string to_string(PtSampler s) { return enum_name(s); }
std::string to_string(Voxelizer v) { return enum_name(v); }
std::string to_string(ConservativeRaster c) { return enum_name(c); }
std::string to_string(VoxelStorage v) { return enum_name(v); }
std::string to_string(Reduction r) { return enum_name(r); }
std::string to_string(DiffuseWeighting w) { return enum_name(w); }
std::string to_string(ConeStart c) { return enum_name(c); }
std::string to_string(ShadowCompare c) { return enum_name(c); }
std::string to_string(ShadowFilterOrder o) { return enum_name(o); }
std::string to_string(PcfTapUnit u) { return enum_name(u); }
std::string to_string(PcfTapScale s) { return enum_name(s); }
std::string to_string(ShadowBorder b) { return enum_name(b); }
std::string to_string(VoxelPcf v) { return enum_name(v); }
std::string to_string(NdotV v) { return enum_name(v); }
int nv_mode(NdotV v) { return v == NdotV::Abs ? sh::NV_ABS : v == NdotV::Clamp ? sh::NV_CLAMP : sh::NV_ZERO; }
std::string to_string(ShadowDepthFormat f) { return enum_name(f); }
std::string to_string(ConeTangentFrame f) { return enum_name(f); }
std::string to_string(IndirectFresnel f) { return enum_name(f); }
std::string to_string(SpecularAperture a) { return enum_name(a); }
std::string to_string(SpecularView v) { return enum_name(v); }

const std::vector<SettingField<VctSettings>>& vct_setting_fields() {
  // clang-format off
  static const std::vector<SettingField<V>> fields = {
    field("width", &V::width, closed(1, 16384), "image width in pixels"),
    field("height", &V::height, closed(1, 16384), "image height in pixels", "u_image_height"),
    field("shadow_map_size", &V::shadow_map_size, closed(16, 16384), "shadow map side in texels", "u_shadow_size"),
    field("pcf_kernel", &V::pcf_kernel, closed(1, 9), "PCF taps per side (seed report: 3)", "u_pcf_kernel"),
    field("shadow_bias", &V::shadow_bias, any(), "constant depth bias in window-depth [0,1] units", "u_shadow_bias"),
    field("shadow_normal_offset", &V::shadow_normal_offset, at_least(0), "normal-offset bias: the lookup point moves along the surface normal by this many times the least offset that keeps a plane from shadowing itself under the PCF footprint (0 = off; docs/pipeline.md, \"Normal offset\")", "u_shadow_normal_offset"),
    field("shadow_fov_deg", &V::shadow_fov_deg, closed(0, 179), "spot shadow map field of view, degrees (0 = twice the outer cone)"),
    field("shadow_near", &V::shadow_near, at_least(0), "spot shadow map near plane (0 = far / 20)"),
    field("shadow_far", &V::shadow_far, at_least(0), "spot shadow map far plane (0 = farthest scene corner x1.01)"),
    choice("shadow_compare", &V::shadow_compare, "a PCF tap's compare: its texel (nearest) or GL LINEAR's bilinear weighting of 4 compares"),
    field("pcf_taps", &V::pcf_taps, any(), "PCF taps as offsets \"dx,dy dx,dy ...\" in pcf_tap_unit (empty = the pcf_kernel square); the frame's, and the voxelizer's unless voxel_pcf_taps is given"),
    field("voxel_pcf_taps", &V::voxel_pcf_taps, any(), "the voxelizer's (light injection's) PCF taps, as pcf_taps (empty = pcf_taps); reference only"),
    choice("voxel_pcf", &V::voxel_pcf, "the voxelizer's PCF: the declared one with voxel_pcf_taps (same), or the oracle's pcf_kernel square, nearest, texel, clamped (oracle) whatever the frame declares"),
    choice("shadow_filter_order", &V::shadow_filter_order, "with shadow_compare = linear: compare the four texels then weight (compare_then_filter, a shadow sampler) or weight the four depths then compare once (filter_then_compare, a plain sampler2D); reference only"),
    choice("pcf_tap_unit", &V::pcf_tap_unit, "unit of the PCF tap offsets: texels, or texture coordinates (uv, x the map size); reference only"),
    choice("pcf_tap_scale", &V::pcf_tap_scale, "tap offsets as given (none) or divided by the light-clip w (inv_w: added before the projective divide); needs shadow_normal_offset = 0; reference only"),
    choice("shadow_border", &V::shadow_border, "what a 2D shadow map reads past its edge: the edge texel (clamp), depth 1 (lit) or depth 0 (shadowed); reference only"),
    choice("shadow_depth_format", &V::shadow_depth_format, "stored shadow depth: float, or 24/16-bit UNORM rounded to nearest"),
    field("shadow_view_proj", &V::shadow_view_proj, any(), "per light world->clip matrix \"LIGHT:m0,...,m15; ...\" (GL column-major; empty = the oracle's)"),
    field("shadow_ortho_box", &V::shadow_ortho_box, any(), "directional lights' ortho boxes \"LIGHT:l,r,b,t,near,far; ...\" in the oracle's light view"),
    choice("light_model", &V::light_model, "KHR_lights_punctual (gltf) or the seed's falloff (docs/scenes.md)"),
    choice("exposure", &V::exposure, "pre-exposure of every light and emission for ref, gl and pt alike: whole stops from a light meter of the scene's lights when outside +-4 stops of 1 (auto), exposure_ev100, or none (docs/scenes.md, \"Light units and exposure\")"),
    field("exposure_ev100", &V::exposure_ev100, closed(-20, 30), "with exposure = ev100: camera EV at ISO 100, scale 1/(1.2 x 2^EV100)"),
    field("grid", &V::grid, powers_of_two(16, 512), "voxel grid resolution N (N^3 voxels)", "u_grid"),
    choice("voxelizer", &V::voxelizer, "exact triangle-box overlap, or the GPU's dominant axis + MSAA rule"),
    field("msaa_samples", &V::msaa_samples, one_of({1, 4, 8}), "MSAA samples of the voxelization pass"),
    choice("conservative_raster", &V::conservative_raster, "GL voxelization: sample rule (off), GS bounding quad + exact clip (gs), or the hardware nv or intel extension (exit 3 without it)"),
    choice("storage", &V::storage, "voxel texture format"),
    choice("reduction", &V::reduction, "how the fragments of a voxel combine"),
    field("anisotropic", &V::anisotropic, any(), "six directional mip volumes", "u_anisotropic"),
    field("solid_voxelization", &V::solid_voxelization, any(), "opaque interior: empty voxels enclosed along x, y and z get A = 1", "u_solid_voxelization"),
    field("surface_thickening_voxels", &V::surface_thickening_voxels, closed(0, kMaxThickening), "opaque voxels added behind each surface (0 = off)", "u_surface_thickening_voxels"),
    field("diffuse_cones", &V::diffuse_cones, any(), "trace the diffuse cones", "u_diffuse_cones"),
    field("specular_cones", &V::specular_cones, any(), "trace the specular cone", "u_specular_cones"),
    field("soft_shadows", &V::soft_shadows, any(), "cone-traced shadows instead of PCF", "u_soft_shadows"),
    field("diffuse_aperture_deg", &V::diffuse_aperture_deg, open(0, 180), "diffuse cone aperture, degrees"),
    field("diffuse_cone_count", &V::diffuse_cone_count, closed(1, kMaxDiffuseConeCount), "diffuse cones: 1 along the normal + count-1 tilted"),
    field("diffuse_cone_tilt_deg", &V::diffuse_cone_tilt_deg, open(0, 90), "angle of the tilted cones from the normal, degrees"),
    choice("diffuse_weighting", &V::diffuse_weighting, "cosine-weighted mean, or the seed's plain sum"),
    field("random_rotation", &V::random_rotation, any(), "rotate the diffuse cones per pixel (hash of pixel, frame)", "u_random_rotation"),
    field("cone_quality", &V::cone_quality, open_lo(0.01, 4.0), "step = diameter x quality (smaller = more steps)", "u_cone_quality"),
    field("cone_offset_voxels", &V::cone_offset_voxels, any(), "cone start offset, in voxels of level 0"),
    choice("cone_start", &V::cone_start, "offset along each cone's axis, or the origin moved along the surface normal (march from t = 0)"),
    field("cone_axis_offset_voxels", &V::cone_axis_offset_voxels, at_least(0), "with cone_start = normal: first sample this far along the axis, voxels"),
    field("diffuse_cone_set", &V::diffuse_cone_set, any(), "diffuse cones as data \"x,y,z,aperture_deg,weight ...\", tangent frame (empty = count/tilt)"),
    choice("cone_tangent_frame", &V::cone_tangent_frame, "tangent frame of the diffuse cones: ours (branchless) or the source design's (cross_hint)"),
    field("specular_offset_voxels", &V::specular_offset_voxels, any(), "specular cone start, voxels, as cone_start says (< 0 = the diffuse cones' offsets; normal: origin along n, march from t = 0)"),
    field("specular_quality", &V::specular_quality, closed(0, 4), "specular cone step = diameter x this (0 = cone_quality)"),
    choice("specular_aperture", &V::specular_aperture, "specular cone aperture from roughness r: 2 atan(r^2) (ggx), or 2 (c0 + a (c1 - c2 a)), a = r^2 (rosseaux, the source design's)"),
    choice("specular_view", &V::specular_view, "specular view vector from the shaded point (surface) or from the cone's origin after its normal offset (origin)"),
    field("indirect_diffuse_gain", &V::indirect_diffuse_gain, at_least(0), "gain on image.indirect_diffuse and so on its composite term (an engine's, e.g. the source design's u_restitution)", "u_indirect_diffuse_gain"),
    choice("indirect_fresnel", &V::indirect_fresnel, "Fresnel of the composite's indirect terms: Schlick with the material's f90, or f90 = max(1 - roughness^2, f0) (schlick_roughness)"),
    choice("n_dot_v", &V::n_dot_v, "the BRDF's view cosine where a normal faces away from the viewer: both lobes 0 (zero), |n.v| (abs) or max(n.v, 1e-4) (clamp); image.direct in both backends"),
    field("max_distance", &V::max_distance, any(), "cone length, voxel-texture units ([0,1]^3 diagonal = 1.732)", "u_cone_max_distance"),
    field("soft_shadow_aperture_deg", &V::soft_shadow_aperture_deg, any(), "soft-shadow cone aperture, degrees"),
    field("opacity_step_correction", &V::opacity_step_correction, any(), "sample opacity 1-(1-a)^(step/voxel size at the lod)", "u_opacity_step_correction"),
    field("bounces", &V::bounces, closed(1, 64), "temporal multibounce frames (1 = direct light in voxels only)"),
    field("restitution", &V::restitution, closed(0, 1), "multibounce attenuation factor", "u_restitution"),
    field("convergence_tolerance", &V::convergence_tolerance, any(), "> 0: stop multibounce when the relative energy change is at most this"),
    field("time", &V::time, any(), "particle time, seconds", "u_time"),
    field("frame", &V::frame, any(), "frame index of the random cone rotation hash"),
    field("particles", &V::particles, any(), "render and voxelize the fire particles"),
    field("depth_prepass", &V::depth_prepass, any(), "GL depth pre-pass (occlusion culling; the image must not change)"),
  };
  // clang-format on
  return fields;
}

const std::vector<SettingField<PtSettings>>& pt_setting_fields() {
  // clang-format off
  static const std::vector<SettingField<P>> fields = {
    field("width", &P::width, closed(1, 16384), "path tracer image width"),
    field("height", &P::height, closed(1, 16384), "path tracer image height"),
    field("spp", &P::spp, at_least(1), "samples per pixel"),
    field("max_depth", &P::max_depth, closed(1, 1024), "longest path, in bounces"),
    field("rr_start_depth", &P::rr_start_depth, any(), "depth at which Russian roulette starts"),
    field("seed", &P::seed, any(), "random seed"),
    field("checkpoint_seconds", &P::checkpoint_seconds, any(), "seconds between resumable checkpoints"),
    choice("light_model", &P::light_model, "as vct.light_model"),
    choice("sampler", &P::sampler, "scrambled Sobol for the first vertices, or independent PCG32 (docs/pathtracer.md)"),
  };
  // clang-format on
  return fields;
}

namespace {
std::string number(double v) {  // 90 rather than std::to_string's 90.000000
  std::ostringstream o;
  o << v;
  return o.str();
}
}  // namespace

template <typename S>
std::string allowed_text(const SettingField<S>& f) {
  const SettingRange& r = f.range;
  switch (f.type) {
    case SettingType::Bool: return "true|false";
    case SettingType::Choice: return join(f.choices, "|");
    case SettingType::Text: return "text";
    case SettingType::Int:
    case SettingType::Float: break;
  }
  if (r.unbounded) return "any";
  if (!r.only.empty()) {
    std::vector<std::string> items;
    for (int v : r.only) items.push_back(std::to_string(v));
    const std::string last = items.back();
    items.pop_back();
    return join(items, ", ") + " or " + last;
  }
  if (std::isinf(r.hi)) return ">= " + number(r.lo);
  if (f.type == SettingType::Int && !r.lo_open && !r.hi_open)
    return (r.power_of_two ? "a power of two in " : "") + number(r.lo) + ".." + number(r.hi);
  return std::string(r.lo_open ? "(" : "[") + number(r.lo) + ", " + number(r.hi) + (r.hi_open ? ")" : "]");
}

template <typename S>
void check_setting_range(const SettingField<S>& f, const S& s, const std::string& scope) {
  if (f.type != SettingType::Int && f.type != SettingType::Float) return;
  const nlohmann::json stored = f.get(s);  // a non-finite float is stored as null
  const double v = stored.is_number() ? stored.template get<double>() : std::nan("");
  if (!std::isfinite(v)) throw InputError("", scope + f.key + " must be a finite number");
  if (f.range.unbounded) return;
  const SettingRange& r = f.range;
  bool ok = std::isfinite(v) && (r.lo_open ? v > r.lo : v >= r.lo) && (r.hi_open ? v < r.hi : v <= r.hi);
  if (!r.only.empty()) {
    ok = false;
    for (int a : r.only) ok = ok || v == double(a);
  }
  if (r.power_of_two) ok = ok && v > 0 && std::exp2(std::round(std::log2(v))) == v;
  if (ok) return;
  const std::string allowed = allowed_text(f);
  const bool interval = allowed[0] == '(' || allowed[0] == '[' || std::isdigit(static_cast<unsigned char>(allowed[0]));
  const bool list = !r.only.empty();
  throw InputError("", scope + f.key + " must be " + (interval && !list ? "in " : "") + allowed + " (got " + number(v) + ")");
}

template std::string allowed_text(const SettingField<VctSettings>&);
template std::string allowed_text(const SettingField<PtSettings>&);
template void check_setting_range(const SettingField<VctSettings>&, const VctSettings&, const std::string&);
template void check_setting_range(const SettingField<PtSettings>&, const PtSettings&, const std::string&);

nlohmann::json setting_value_from_text(SettingType type, const std::string& text, const std::string& what) {
  if (type == SettingType::Choice || type == SettingType::Text) return text;
  const std::string expected = type == SettingType::Bool ? "boolean" : "number";
  nlohmann::json v;
  try {
    v = parse_bounded_json(text, what);
  } catch (const InputError&) {
    throw InputError(what, "'" + input_excerpt(text) + "' is not a " + expected);
  }
  if (type == SettingType::Bool ? !v.is_boolean() : !v.is_number())
    throw InputError(what, "'" + input_excerpt(text) + "' is not a " + expected);
  return v;
}

// The shortest decimal that reads back as the same float.
std::string shortest_float(float f) {
  for (int digits = 1; digits < 9; ++digits) {
    std::ostringstream o;
    o.precision(digits);
    o << f;
    if (std::stof(o.str()) == f) return o.str();
  }
  std::ostringstream o;
  o.precision(9);
  o << f;
  return o.str();
}

std::string value_text(const nlohmann::json& v) {
  if (v.is_number_float()) return shortest_float(float(v.get<double>()));
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

namespace {
template <typename S>
bool set_field(const std::vector<SettingField<S>>& fields, S& s, const std::string& key, const std::string& text,
               const std::string& what, const std::string& scope) {
  for (const auto& f : fields) {
    if (key != f.key) continue;
    const nlohmann::json value = setting_value_from_text(f.type, text, what);
    try {
      f.set(s, value, scope);
    } catch (const InputError& e) {
      throw InputError(what, e.what());
    }
    return true;
  }
  return false;
}
}  // namespace

Settings with_setting(const Settings& s, const std::string& key, const std::string& text, const std::string& what) {
  Settings out = s;
  const bool pt = key.rfind("pt.", 0) == 0;
  const std::string bare = pt ? key.substr(3) : key.rfind("vct.", 0) == 0 ? key.substr(4) : key;
  const bool found = pt ? set_field(pt_setting_fields(), out.pt, bare, text, what, "pt.")
                        : set_field(vct_setting_fields(), out.vct, bare, text, what, "vct.");
  if (!found) throw InputError(what, "unknown setting '" + key + "' (vct settings lists them)");
  return out;
}

namespace {
// A Markdown table cell: a literal "|" (choice lists "a|b") would end the cell.
std::string table_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

template <typename S>
void markdown_rows(std::ostringstream& o, const std::vector<SettingField<S>>& fields, const S& defaults,
                   const char* scope) {
  for (const auto& f : fields)
    o << "| `" << scope << f.key << "` | `" << value_text(f.get(defaults)) << "` | " << table_cell(allowed_text(f))
      << " | " << table_cell(f.help)
      << (f.gl_uniform ? std::string(" (GLSL `") + f.gl_uniform + "`)" : std::string()) << " |\n";
}
}  // namespace

std::string settings_markdown() {
  std::ostringstream o;
  o << "| key | default | allowed | meaning |\n| --- | --- | --- | --- |\n";
  markdown_rows(o, vct_setting_fields(), VctSettings(), "vct.");
  markdown_rows(o, pt_setting_fields(), PtSettings(), "pt.");
  o << "| `threads` | `0` | 0..1024 | worker threads (0 = all cores) |\n";
  return o.str();
}

}  // namespace vct
