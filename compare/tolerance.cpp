#include "tolerance.h"

#include <cmath>

namespace vct::cmp {

double half_ulp(double v) {
  v = std::abs(v);
  if (v < std::ldexp(1.0, -14)) return std::ldexp(1.0, -24);
  return std::ldexp(1.0, int(std::floor(std::log2(v))) - 10);
}

bool is_cone_traced(const std::string& stage) {
  return stage == "image.indirect_diffuse" || stage == "image.indirect_specular" || stage == "image.diffuse_term" ||
         stage == "image.specular_term" || stage == "image.soft_shadow" || stage == "image.final";
}

// Edge ties, as a share of the pixels the edge map flags (image_edges.h). Measured with GL
// (llvmpipe) against the reference on the built-in scene at 32^2..512^2 and demo_room from 64^2:
// legitimate ties reach 1.2% of the flagged pixels (image.direct, shadow-test ties); a one-pixel
// shift that shows only at edges puts >= 15% of them beyond the bound, half the edge pixels wrong
// 50%. 2.5% is what the former shares of all pixels (0.5% raster, 1% shading) amounted to at 64^2
// on the built-in scene (docs/compare.md, "Edges").
constexpr double kEdgeTieFraction = 0.025;

ImageModel image_model(const std::string& stage) {
  ImageModel m;
  if (stage.rfind("shadow_map", 0) == 0 || stage == "gbuffer.depth") {
    // D32F: both sides interpolate window z in float; the spec does not fix the barycentric
    // arithmetic (plane equations evaluated far from the vertices lose bits), so allow 2^-14
    // (6.1e-5), 1/8 of the default constant shadow bias (5e-4): a
    // difference inside the bound cannot flip a shadow test except at exact ties.
    m = {"d32f-depth", std::ldexp(1.0, -14), 0.0, 0.0, kEdgeTieFraction, 0.0,
         "|dz| <= 2^-14 + 2^-8 (|dz/dx|+|dz/dy|) (subpixel snapping); ties (coverage, fill rule) on up to 2.5% of edge texels -> warn"};
    m.slope_factor = std::ldexp(1.0, -8);
  } else if (stage == "gbuffer.coverage") {
    m = {"coverage-exact", 0.0, 0.0, 0.0, kEdgeTieFraction, 0.0, "exact; fill-rule ties on up to 2.5% of edge pixels -> warn"};
  } else if (stage == "gbuffer.position") {
    m = {"interpolated-attribute", 1e-4, std::ldexp(1.0, -12), 0.0, kEdgeTieFraction, 0.001,
         "|d| <= 1e-4 + 2^-12 |ref| + 2^-8 (|d/dx|+|d/dy|) (float interpolation, subpixel snapping); ties on up to 2.5% of edge pixels"};
    m.slope_factor = std::ldexp(1.0, -8);
  } else if (stage == "gbuffer.normal") {
    // As the textured attributes below, but a normal map's [0,1] texels become [-1,1] (twice the
    // error) and renormalising a filtered (shortened) tangent-space normal scales it further.
    m = {"normal-map-8bit-weights", std::ldexp(1.0, -6), std::ldexp(1.0, -7), 0.0, kEdgeTieFraction, 0.0,
         "|d| <= 2^-6 + 2^-7 |ref| (8-bit sub-texel + LOD weights on [-1,1] normal-map texels, renormalised); ties on up to 2.5% of edge pixels"};
  } else if (stage.rfind("gbuffer.", 0) == 0) {
    // Textured attributes: bilinear/trilinear weights with 8 sub-texel bits (D3D11 7.18.16.1,
    // dEQP LookupPrecision) and an 8-bit mip blend: |d| <= (2+1)*2^-9*range + 8-bit texel step.
    m = {"texture-8bit-weights", std::ldexp(1.0, -7), std::ldexp(1.0, -7), 0.0, kEdgeTieFraction, 0.0,
         "|d| <= 2^-7 + 2^-7 |ref| (8-bit sub-texel + LOD weights); ties on up to 2.5% of edge pixels"};
  } else if (stage == "image.direct" || stage == "image.emission") {
    // Shared BRDF in float on G-buffer inputs (which carry 2^-7) and PCF shadow tests whose
    // ties flip at shadow edges.
    m = {"shading-float", 1e-5, std::ldexp(1.0, -6), std::ldexp(1.0, -10), kEdgeTieFraction, 0.001,
         "|d| <= 2^-6 |ref| + 2^-10 mean|ref| (G-buffer bound through the BRDF); shadow/silhouette ties on up to 2.5% of edge pixels"};
  } else if (stage == "image.soft_shadow") {
    m = {"cone-visibility", std::ldexp(1.0, -5), 0.0, 0.0, kEdgeTieFraction, 0.001,
         "|d| <= 2^-5 (8-bit weights over the cone's samples); ties on up to 2.5% of edge pixels"};
  } else {
    // Cone-traced images: each fetch has weights with 8 sub-texel bits per axis plus an 8-bit
    // LOD fraction: per fetch error <= 4 * 2^-9 = 2^-7 of the local texel maximum; the front-to-
    // back sum weights fetches by (1-a) <= 1, so with a local max/mean contrast up to 4 the
    // image bound is 2^-5 |ref|, plus 2^-8 of the image mean for near-black pixels.
    m = {"filtered-8bit", 1e-6, std::ldexp(1.0, -5), std::ldexp(1.0, -8), kEdgeTieFraction, 0.001,
         "|d| <= 2^-5 |ref| + 2^-8 mean|ref| (8-bit sub-texel and LOD weights, GL 4.5 8.14 / D3D11 7.18.16.1); ties on up to 2.5% of edge pixels"};
  }
  return m;
}

int texture_slack_channel(const std::string& stage, const Image& slack) {
  static const char* kNames[] = {"normal", "albedo", "material", "emission"};  // TextureSlackChannel order
  for (int k = 0; k < 4; ++k) {
    if (stage != std::string("gbuffer.") + kNames[k]) continue;
    if (int(slack.channel_names.size()) != slack.channels) return k < slack.channels ? k : -1;
    for (int c = 0; c < slack.channels; ++c)
      if (slack.channel_names[size_t(c)] == kNames[k]) return c;
    return -1;
  }
  return -1;
}

VoxelModel voxel_model(const std::string& storage, const std::string& reduction, const std::string& ref_reduction) {
  VoxelModel m;
  if (reduction == "fixed_point" && ref_reduction != "fixed_point") {
    // Fixed point (2^-14 quanta, rounded per fragment and at the resolve) against an exact float
    // mean: at most one quantum apart before storage, then the storage rounding.
    m = {"fixed-point-vs-exact", std::ldexp(1.0, -14), storage == "rgba8" ? 0.0 : std::ldexp(1.0, -9), 0.0, false,
         "|d| <= 2^-14 + storage rounding (2 half-ulp or 1/255): fixed-point quanta against the exact mean"};
    if (storage == "rgba8") m.abs += 1.0 / 255.0;
  } else if (reduction == "fixed_point") {
    // The reduction itself is exact (integer sums, same rounding on both sides: bit-identical
    // when fragment values agree, see tests/gl). The fragment values are each backend's own
    // float shading at its own interpolated position, so they carry a shading error; stored as
    // binary16 that shows as one half-ulp flip, plus 2^-10 relative for the shading itself.
    // Textured albedo and emission carry the G-buffer's texture bound (8-bit sub-texel weights,
    // 2^-7 relative: the "texture-8bit-weights" model). A shading difference also moves a
    // fragment's rounding to the fixed-point grid by one quantum (2^-14), which is all that shows
    // on near-black voxels.
    m = {"fixed-point-exact+shading", std::ldexp(1.0, -14), std::ldexp(1.0, -7), 0.0, false,
         "exact reduction; |d| <= 2^-14 + 2^-7 |ref| (+ 2 half-ulp for RGBA16F, 1/255 for RGBA8): each fragment's float shading and 8-bit texture filtering weights"};
    if (storage == "rgba8") m.abs += 1.0 / 255.0;
  } else if (reduction == "cas_rgba8") {
    m = {"cas-rgba8-interval", 1.0 / 255.0, 0.0, 0.0, true,
         "within the reference's [cas_lo, cas_hi] (any fragment order) +- 1/255"};
  } else if (storage == "rgba8") {
    m = {"rgba8-quantised", 1.0 / 255.0, 0.0, 0.0, false, "|d| <= 1/255 (8-bit UNORM: rounding vs truncation)"};
  } else if (storage == "rgba16f") {
    m = {"rgba16f-ulp", 0.0, std::ldexp(1.0, -9), std::ldexp(1.0, -23), false,
         "|d| <= 2 half-ulp(ref) + n_frag * 2^-23 |ref| (float atomics sum in any order, stored as binary16)"};
  } else {
    m = {"rgba32f-sum", 1e-7, 0.0, std::ldexp(1.0, -23), false, "|d| <= n_frag * 2^-23 |ref| (float sum order)"};
  }
  return m;
}

MipBound mip_bound(const VoxelModel& base, const std::string& storage, int level, bool anisotropic, double cas_width) {
  MipBound b{base.abs + cas_width, base.rel + 2.0 * base.per_fragment_rel * 8.0};
  double q_abs = 0.0, q_rel = 0.0;  // one storage rounding per level (any rounding mode)
  if (storage == "rgba8") q_abs = 1.0 / 255.0;
  else if (storage == "rgba16f") q_rel = std::ldexp(1.0, -10), q_abs = std::ldexp(1.0, -24);
  else q_rel = std::ldexp(1.0, -22);
  for (int l = 1; l <= level; ++l) {
    const double grow = anisotropic ? 2.0 : 1.0;
    b.abs = grow * b.abs + q_abs;
    b.rel = grow * b.rel + q_rel;
  }
  return b;
}

}  // namespace vct::cmp
