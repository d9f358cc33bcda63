// Every knob of the VCT pipelines (ref and gl read the same struct) and of the path tracer.
// Defaults follow the seed design unless docs/pipeline.md says why they differ.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace vct {

enum class LightModel { Gltf, Seed };                  // KHR_lights_punctual vs seed falloff
// Camera exposure (docs/scenes.md, "Exposure"): a light meter's whole stops from the scene's
// lights (auto), a photographic EV100, or none (scale 1). Applied to the scene's sources before
// any engine sees them (scene/exposure.h), so every stage of ref, gl and pt is pre-exposed alike.
enum class ExposureMode { Auto, Ev100, None };
enum class PtSampler { Sobol, Independent };           // path tracer: scrambled Sobol or PCG32 (pt/path_sampler.h)
enum class Voxelizer { Conservative, GpuEmulation };   // exact triangle-box vs dominant axis+MSAA
// The GL voxelization pass's conservative mode (issue 15; docs/gl_backend.md, "Conservative
// voxelization"): off (the sample rule), a geometry-shader bounding quad with a per-fragment exact
// clip that runs on any GL 4.5 (gs), or the driver's hardware conservative rasterizer
// (GL_NV_conservative_raster, GL_INTEL_conservative_rasterization). The CPU reference ignores it:
// its exact triangle-box voxelizer (voxelizer = conservative) is what every mode is judged against.
enum class ConservativeRaster { Off, GeometryShader, Nv, Intel };
enum class VoxelStorage { Rgba8, Rgba16f };            // LDR vs HDR voxels
// How fragments in a voxel combine. RunningMeanHalf models an engine's non-atomic running mean
// (stages/running_mean.h): the reference keeps the exact mean and states the interval of values.
enum class Reduction { ExactMean, FixedPoint, CasRgba8, RunningMeanHalf };
enum class DiffuseWeighting { Cosine, SeedSum };       // cosine-weighted mean vs the seed's sum
// Where a diffuse or specular cone starts (issue 21): `cone_offset_voxels` along each cone's own
// axis (ours), or the origin moved that far along the surface normal and marched from t = 0 (the
// source design's, righier/gidemo voxelcone.frag). docs/pipeline.md, "Cone marching".
enum class ConeStart { Axis, Normal };
// How one PCF tap compares: the texel its position falls in (ours), or GL's LINEAR filter on a
// shadow sampler -- the bilinear weighting of the four nearest texels' comparisons (GL 4.5
// section 8.23.1), an engine's convention (issue 21).
enum class ShadowCompare { Nearest, Linear };
// Where a tap's linear filter sits relative to its compare (issue 39): each of the four texels
// compared and the results weighted (ours; GL LINEAR on a shadow sampler), or the four depths
// weighted first and the filtered depth compared once (GL LINEAR on a plain sampler2D, the source
// design's textureProj). With shadow_compare = nearest a tap reads one texel: both are the same.
enum class ShadowFilterOrder { CompareThenFilter, FilterThenCompare };
// The unit of pcf_taps / voxel_pcf_taps (issue 39): texels of the map (ours), or texture
// coordinates in [0, 1] (an offset added to the lookup's UV), multiplied by the map's size.
enum class PcfTapUnit { Texel, Uv };
// Whether the tap offsets are divided by the lookup point's light-clip w (issue 39): no (ours), or
// yes -- offsets added to the clip xy before the projective divide (the source design's
// `textureProj(coords + offset)`), a footprint of constant size in the light's view space.
enum class PcfTapScale { None, InvW };
// What a 2D shadow map reads past its edge (issue 39): the edge texel (ours, GL CLAMP_TO_EDGE), or
// GL CLAMP_TO_BORDER with border depth 1 (lit: every point inside the frustum is in front of it)
// or 0 (shadowed: the source design's border colour). A cube map has no border (GL 4.5 section
// 8.13: seamless filtering reads the neighbouring face).
enum class ShadowBorder { Clamp, Lit, Shadowed };
// The voxelizer's PCF (issue 39): the declared one, with voxel_pcf_taps for its taps (same), or
// the oracle's own whatever the frame declares -- the pcf_kernel square, nearest, in texels,
// clamped to edge (oracle): an engine whose voxelizer uses a plain kernel and whose frame does not.
enum class VoxelPcf { Same, Oracle };
// How a shadow map stores depth: float (ours), or 24/16-bit UNORM -- an engine's depth texture
// format (issue 21); the reference quantises its window depth as GL 4.5 section 2.3.5.2 converts.
enum class ShadowDepthFormat { Depth32f, Depth24, Depth16 };
// The tangent frame a diffuse cone set's directions are given in (issue 21): ours, the branchless
// orthonormal basis sh::frame_from_normal; or the source design's (righier/gidemo voxelcone.frag
// ortho()): t = normalize(n x (0.1, 0, 1)), or n x (1, 0, 0) when |n . normalize(0.1, 0, 1)| >=
// 0.999, and b = n x t. stages/cone_sets.h.
enum class ConeTangentFrame { Branchless, CrossHint };
// The Fresnel factor of the indirect terms in the final composite (issue 21): ours, Schlick with
// the material's f90; or Schlick with f90 = max(1 - roughness^2, f0) per channel, the "roughness"
// variant of split-sum image-based lighting that the source design uses (righier/gidemo
// voxelcone.frag FresnelSchlickRoughness, fed roughness^2). stages/composite.h.
enum class IndirectFresnel { Schlick, SchlickRoughness };
// How the BRDF takes the view cosine n.v where a shading normal faces away from the viewer
// (issue 39; sh::view_cosine in ref/shared/vct_shared.h): both lobes 0 (ours), |n.v| (the source
// design's), or max(n.v, 1e-4) (Filament's clamp).
enum class NdotV { Zero, Abs, Clamp };
// The specular cone's full aperture from perceptual roughness r (issue 21): ours,
// 2 atan(r^2) clamped to [1, 90] degrees (sh::specular_cone_aperture); or the polynomial fit of
// Rosseaux's "How to use voxel cone tracing with two bounces ..." that the source design uses
// (righier/gidemo voxelcone.frag roughnessToAperture, fed a = r^2): half-angle
// 0.0003474660443456835 + a (1.3331290497744692 - 0.5040552688878546 a) radians, a clamped to
// [0, 1], unclamped above (95.04 degrees at r = 1). stages/cone_sets.h specular_cone_aperture_of.
enum class SpecularAperture { Ggx, Rosseaux };
// Where the specular cone's view vector is taken from (issue 21): the shaded point (ours) or the
// cone's origin after its normal offset (the source design: camDir = normalize(pos - camPos)
// with pos already moved 4 voxels along n).
enum class SpecularView { Surface, Origin };

// Largest diffuse_cone_count; equals sh::MAX_DIFFUSE_CONES (static_assert in stages/cone_sets.cpp).
inline constexpr int kMaxDiffuseConeCount = 16;
// Largest surface_thickening_voxels: a wall thicker than this is a scene edit, not a fix.
inline constexpr int kMaxThickening = 4;

struct VctSettings {
  // Images and shadow maps.
  int width = 512;
  int height = 512;
  int shadow_map_size = 2048;
  int pcf_kernel = 3;            // PCF taps per side (seed report: 3x3)
  float shadow_bias = 0.0005f;   // constant depth bias in NDC-depth [0,1] units
  // Normal-offset bias in units of the least offset that keeps a plane from shadowing itself
  // under the PCF footprint (stages/shadow_map.h, normal_offset_per_w; 0 = off).
  float shadow_normal_offset = 1.0f;
  // A spot light's shadow frustum (an engine's convention, issue 21): 0 = the oracle's own choice
  // (fov twice the outer cone angle; far = farthest scene corner x1.01, near = far/20).
  float shadow_fov_deg = 0.0f;
  float shadow_near = 0.0f;
  float shadow_far = 0.0f;
  // An engine's PCF (issue 21): its compare filtering, and its taps as texel offsets
  // "dx,dy dx,dy ..." (fractional allowed; core/pcf_taps.h). Empty = the pcf_kernel square.
  ShadowCompare shadow_compare = ShadowCompare::Nearest;
  std::string pcf_taps;
  // The rest of an engine's PCF (issue 39; stages/shadow_map.h, docs/external_format.md): the
  // filter's order, the taps' unit and 1/w scaling, the voxelizer's own taps (empty = pcf_taps)
  // and what the map reads past its edge. The defaults are the oracle's own PCF.
  ShadowFilterOrder shadow_filter_order = ShadowFilterOrder::CompareThenFilter;
  PcfTapUnit pcf_tap_unit = PcfTapUnit::Texel;
  PcfTapScale pcf_tap_scale = PcfTapScale::None;
  std::string voxel_pcf_taps;
  VoxelPcf voxel_pcf = VoxelPcf::Same;
  ShadowBorder shadow_border = ShadowBorder::Clamp;
  ShadowDepthFormat shadow_depth_format = ShadowDepthFormat::Depth32f;
  // An engine's light matrices (issue 21; core/light_matrices.h): per light, world -> clip as 16
  // numbers in GL's column-major order, "LIGHT:m0,...,m15; ..." (replaces that spot's frustum or
  // directional light's fitted box); and directional lights' ortho boxes in the oracle's light
  // view, "LIGHT:left,right,bottom,top,near,far; ...". Empty = the oracle's own.
  std::string shadow_view_proj;
  std::string shadow_ortho_box;
  LightModel light_model = LightModel::Gltf;
  ExposureMode exposure = ExposureMode::Auto;
  float exposure_ev100 = 0.0f;  // with exposure = ev100: scale 1 / (1.2 * 2^EV100)

  // Voxelization.
  int grid = 128;
  Voxelizer voxelizer = Voxelizer::Conservative;
  int msaa_samples = 8;  // 1, 4 or 8 (GL standard sample positions)
  ConservativeRaster conservative_raster = ConservativeRaster::Off;  // GL only; see the enum
  VoxelStorage storage = VoxelStorage::Rgba16f;
  Reduction reduction = Reduction::ExactMean;
  bool anisotropic = false;
  // Artifact fixes (issue 17; docs/pipeline.md, "Solid voxelization and surface thickening").
  bool solid_voxelization = false;   // opaque (A = 1, RGB 0) interior of closed geometry
  int surface_thickening_voxels = 0;  // opaque voxels added behind each surface, 0..kMaxThickening

  // Cone tracing.
  bool diffuse_cones = true;
  bool specular_cones = true;
  bool soft_shadows = false;      // cone-traced shadow instead of PCF
  float diffuse_aperture_deg = 30.0f;
  int diffuse_cone_count = 5;        // 1 along the normal + count-1 tilted, evenly spaced in azimuth
  float diffuse_cone_tilt_deg = 45.0f;  // angle of the tilted cones from the normal, in (0, 90)
  DiffuseWeighting diffuse_weighting = DiffuseWeighting::Cosine;
  bool random_rotation = false;
  float cone_quality = 0.5f;      // step = diameter * quality  (smaller = more steps)
  float cone_offset_voxels = 1.5f;  // start offset, in voxels of level 0
  ConeStart cone_start = ConeStart::Axis;  // along each cone's axis, or along the surface normal
  // With cone_start = normal: the first sample this far along each cone's axis after the normal
  // offset, in voxels of level 0 (the source design's ConeTracing `offset`). 0 = march from t = 0.
  float cone_axis_offset_voxels = 0.0f;
  // A diffuse cone set given as data (issue 21; stages/cone_sets.h): "x,y,z,aperture_deg,weight
  // ..." with each direction in the tangent frame (z = normal; normalised by the reference).
  // Empty = diffuse_cone_count / diffuse_cone_tilt_deg / diffuse_aperture_deg / diffuse_weighting.
  std::string diffuse_cone_set;
  ConeTangentFrame cone_tangent_frame = ConeTangentFrame::Branchless;
  // A gain on the frame's indirect diffuse light (issue 21): image.indirect_diffuse is the
  // diffuse cones' result times this, and the composite adds that (the source design's
  // u_restitution, 0.15 in its box scene, multiplies its indirect-diffuse render mode and its
  // composite alike). 1 = ours.
  float indirect_diffuse_gain = 1.0f;
  IndirectFresnel indirect_fresnel = IndirectFresnel::Schlick;
  NdotV n_dot_v = NdotV::Zero;  // the direct light's view cosine (reference only; GL runs zero)
  // The specular cone's own conventions (issue 21; docs/pipeline.md, "Specular cone"): its start
  // offset in voxels (< 0: the diffuse cones' cone_offset_voxels and cone_axis_offset_voxels;
  // >= 0: under cone_start = normal the origin moves this far along n and the march starts at
  // t = 0, under axis the first sample is this far along the cone), its step factor (0 = the
  // diffuse cones' cone_quality), its aperture function and the point its view vector leaves.
  float specular_offset_voxels = -1.0f;
  float specular_quality = 0.0f;
  SpecularAperture specular_aperture = SpecularAperture::Ggx;
  SpecularView specular_view = SpecularView::Surface;
  float max_distance = 1.7320508f;  // in voxel-texture units ([0,1]^3 cube diagonal)
  float soft_shadow_aperture_deg = 10.0f;
  // Sample opacity corrected for the step length: 1 - (1 - a)^(step / voxel size at the lod)
  // (sh::step_corrected_opacity; docs/pipeline.md, "Cone marching").
  bool opacity_step_correction = false;

  // Temporal multibounce.
  int bounces = 1;                 // frames of multibounce; 1 = direct light in voxels only
  float restitution = 0.5f;        // the seed's attenuation factor
  float convergence_tolerance = 0.0f;  // >0: stop when relative energy change falls below

  // Particles and time.
  float time = 1.0f;
  int frame = 0;                   // frame index for the random cone rotation hash
  bool particles = true;

  // Occlusion culling (GL only; the image must not change).
  bool depth_prepass = true;

  // (Deliberate GL faults for testing the oracle are not a VCT setting: gl/gl_faults.h,
  // `--gl-fault NAME`.)
};

struct PtSettings {
  int width = 512;
  int height = 512;
  int spp = 64;
  int max_depth = 8;
  int rr_start_depth = 3;
  uint32_t seed = 0;
  int checkpoint_seconds = 30;
  LightModel light_model = LightModel::Gltf;
  PtSampler sampler = PtSampler::Sobol;
};

struct Settings {
  VctSettings vct;
  PtSettings pt;
  int threads = 0;  // 0 = all cores
};

// JSON round-trip (--config FILE.json and run.json). Unknown keys are an InputError.
void to_json(nlohmann::json& j, const VctSettings& s);
void from_json(const nlohmann::json& j, VctSettings& s);
void to_json(nlohmann::json& j, const PtSettings& s);
void from_json(const nlohmann::json& j, PtSettings& s);
void to_json(nlohmann::json& j, const Settings& s);
void from_json(const nlohmann::json& j, Settings& s);

/// Loads a --config file on top of `base`; throws InputError naming the file on any problem.
Settings load_settings_file(const std::string& path, const Settings& base);

/// Checks ranges (grid 16..512, sizes > 0, samples in {1,4,8}, ...); throws InputError.
void validate_settings(const Settings& s);

std::string to_string(LightModel m);
std::string to_string(ExposureMode m);
std::string to_string(PtSampler s);
std::string to_string(Voxelizer v);
std::string to_string(ConservativeRaster c);
std::string to_string(VoxelStorage v);
std::string to_string(Reduction r);
std::string to_string(DiffuseWeighting w);
std::string to_string(ConeStart c);
std::string to_string(ShadowCompare c);
std::string to_string(ShadowFilterOrder o);
std::string to_string(PcfTapUnit u);
std::string to_string(PcfTapScale s);
std::string to_string(ShadowBorder b);
std::string to_string(VoxelPcf v);
std::string to_string(ShadowDepthFormat f);
std::string to_string(ConeTangentFrame f);
std::string to_string(IndirectFresnel f);
std::string to_string(NdotV v);
/// The shared header's mode (sh::NV_ZERO, NV_ABS, NV_CLAMP) of a setting.
int nv_mode(NdotV v);
std::string to_string(SpecularAperture a);
std::string to_string(SpecularView v);

}  // namespace vct
