#include "tolerance.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include "compare/counted_shares.h"
#include "core/precision.h"
#include "freedoms/texture_slack.h"
#include "stages/raster.h"

namespace vct::cmp {

double half_ulp(double v) {
  v = std::abs(v);
  if (v < std::ldexp(1.0, -14)) return std::ldexp(1.0, -24);
  return std::ldexp(1.0, int(std::floor(std::log2(v))) - 10);
}

bool is_cone_traced(const std::string& stage, bool soft_shadows) {
  const auto ref = find_stage(stage);
  return ref && judged_on_own_inputs(*ref->row, soft_shadows);
}

namespace {

// The edge and interior shares are counted allowances: compare/counted_shares.h holds them with
// their denominators (docs/compare.md, "Edges", "Counted shares").

// "2^-14" for powers of two (how the bounds are derived), else three significant digits.
std::string number_text(double v) {
  int e = 0;
  if (v > 0 && std::frexp(v, &e) == 0.5) return "2^" + std::to_string(e - 1);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string percent_text(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g%%", fraction * 100.0);
  return buf;
}

std::string sum_text(const std::vector<std::string>& terms) {
  std::string out;
  for (const std::string& t : terms) out += (out.empty() ? "" : " + ") + t;
  return out;
}

using T = ToleranceModel;

// One row per image model: the numbers and the freedom they stand for (docs/compare.md derives
// each one).
std::vector<ImageModel> make_image_models() {
  const double e = kEdgeTieShare.fraction, i = kInteriorShare.fraction;
  // id, name, abs, rel, abs_of_mean, edge ties, interior, slope, source
  return {
      // D32F: both sides interpolate window z in float; the spec does not fix the barycentric
      // arithmetic (plane equations evaluated far from the vertices lose bits), so allow 2^-14
      // (6.1e-5), 1/8 of the default constant shadow bias (5e-4): a difference inside the bound
      // cannot flip a shadow test except at exact ties.
      {T::Depth, "d32f-depth", precision(Precision::DepthInterpolation), 0.0, 0.0, e, 0.0, kVertexSnapStep,
       "float depth interpolation, subpixel snapping; coverage and fill-rule ties at edges"},
      {T::Coverage, "coverage-exact", 0.0, 0.0, 0.0, e, 0.0, 0.0, "same fill rule; ties at edges"},
      {T::Position, "interpolated-attribute", 1e-4, precision(Precision::AttributeInterpolation), 0.0, e, i, kVertexSnapStep,
       "float interpolation, subpixel snapping"},
      // As the textured attributes below, but a normal map's [0,1] texels become [-1,1] (twice
      // the error) and renormalising a filtered (shortened) tangent-space normal scales it further.
      {T::NormalMap, "normal-map-8bit-weights", std::ldexp(1.0, -6), std::ldexp(1.0, -7), 0.0, e, 0.0, 0.0,
       "8-bit sub-texel + LOD weights on [-1,1] normal-map texels, renormalised"},
      // Textured attributes: bilinear/trilinear weights with 8 sub-texel bits (D3D11 7.18.16.1,
      // dEQP LookupPrecision) and an 8-bit mip blend: |d| <= (2+1)*2^-9*range + 8-bit texel step.
      {T::Texture, "texture-8bit-weights", std::ldexp(1.0, -7), std::ldexp(1.0, -7), 0.0, e, 0.0, 0.0,
       "8-bit sub-texel + LOD weights"},
      // Shared BRDF in float on G-buffer inputs (which carry 2^-7) and PCF shadow tests whose
      // ties flip at shadow edges.
      {T::Shading, "shading-float", 1e-5, precision(Precision::ShadingArithmetic), std::ldexp(1.0, -10), e, i, 0.0,
       "G-buffer bound through the BRDF; shadow and silhouette ties at edges"},
      {T::ConeVisibility, "cone-visibility", std::ldexp(1.0, -5), 0.0, 0.0, e, i, 0.0,
       "8-bit weights over the cone's samples"},
      // Cone-traced images: each fetch has weights with 8 sub-texel bits per axis plus an 8-bit
      // LOD fraction: per fetch error <= 4 * 2^-9 = 2^-7 of the local texel maximum; the front-
      // to-back sum weights fetches by (1-a) <= 1, so with a local max/mean contrast up to 4 the
      // image bound is 2^-5 |ref|, plus 2^-8 of the image mean for near-black pixels.
      {T::Filtered, "filtered-8bit", 1e-6, std::ldexp(1.0, -5), std::ldexp(1.0, -8), e, i, 0.0,
       "8-bit sub-texel and LOD weights, GL 4.5 8.14 / D3D11 7.18.16.1"},
  };
}

}  // namespace

ImageModel image_model(ToleranceModel id) {
  static const std::vector<ImageModel> models = make_image_models();
  for (const ImageModel& m : models)
    if (m.id == id) return m;
  return image_model(T::Filtered);
}

ImageModel image_model(const std::string& stage) {
  const auto ref = find_stage(stage);
  return image_model(ref && ref->row->model != T::None ? ref->row->model : T::Filtered);
}

std::string bound_text(const ImageModel& m) {
  std::vector<std::string> terms;
  if (m.abs > 0) terms.push_back(number_text(m.abs));
  if (m.rel > 0) terms.push_back(number_text(m.rel) + " |ref|");
  if (m.abs_of_mean > 0) terms.push_back(number_text(m.abs_of_mean) + " mean|ref|");
  if (m.slope_factor > 0) terms.push_back(number_text(m.slope_factor) + " (|d/dx|+|d/dy|)");
  std::string out = terms.empty() ? "exact" : "|d| <= " + sum_text(terms);
  out += " (" + m.source + ")";
  if (m.edge_tie_fraction > 0) out += "; ties on up to " + percent_text(m.edge_tie_fraction) + " of edge pixels -> warn";
  if (m.interior_fraction > 0) out += "; up to " + percent_text(m.interior_fraction) + " of interior pixels -> warn";
  return out;
}

int texture_slack_channel(const std::string& stage, const Image& slack) {
  // Each stage a slack channel widens, with the channel's name and its TextureSlackChannel index
  // (for unnamed images). image.emission is the G-buffer's emission as the final pass adds it, so
  // the emission lookup's freedom is the same there.
  struct Row {
    const char* stage;
    const char* channel;
    int index;
  };
  static const Row kRows[] = {{stage_names::kGbufferNormal, "normal", kSlackNormal},
                              {stage_names::kGbufferAlbedo, "albedo", kSlackAlbedo},
                              {stage_names::kGbufferMaterial, "material", kSlackMaterial},
                              {stage_names::kGbufferEmission, "emission", kSlackEmission},
                              {stage_names::kImageEmission, "emission", kSlackEmission},
                              {stage_names::kImageDirect, "direct", kSlackDirect}};
  for (const Row& r : kRows) {
    if (stage != r.stage) continue;
    if (int(slack.channel_names.size()) != slack.channels) return r.index < slack.channels ? r.index : -1;
    for (int c = 0; c < slack.channels; ++c)
      if (slack.channel_names[size_t(c)] == r.channel) return c;
    return -1;
  }
  return -1;
}

int alpha_tie_channel(const Image& slack) {
  for (int c = 0; c < slack.channels && size_t(c) < slack.channel_names.size(); ++c)
    if (slack.channel_names[size_t(c)] == "alpha_tie") return c;
  return -1;
}

double VoxelModel::bound(double ref, double fragments, double slack) const {
  const double r = std::abs(ref);
  const double spread = abs + rel * r + fragments * per_fragment_rel * r + slack;
  // The test's half rounds a mean anywhere within the spread: its spacing at the far end.
  return spread + half_ulps * half_ulp(r + spread);
}

std::string bound_text(const VoxelModel& m) {
  if (m.cas_interval) return "within the reference's [cas_lo, cas_hi] +- " + number_text(m.abs) + " (" + m.source + ")";
  std::vector<std::string> terms;
  if (m.abs > 0) terms.push_back(number_text(m.abs));
  if (m.rel > 0) terms.push_back(number_text(m.rel) + " |ref|");
  if (m.half_ulps > 0) terms.push_back(std::to_string(int(m.half_ulps)) + " half-ulp(|ref| + the rest)");
  if (m.per_fragment_rel > 0) terms.push_back("n_frag * " + number_text(m.per_fragment_rel) + " |ref|");
  return (terms.empty() ? std::string("exact") : "|d| <= " + sum_text(terms)) + " (" + m.source + ")";
}

VoxelModel voxel_model(const std::string& storage, const std::string& reduction, const std::string& ref_reduction) {
  using V = VoxelModelId;
  // Storage rounding of a value both sides computed alike: 1/255 for RGBA8 UNORM (rounding vs
  // truncation), two half-ulps for RGBA16F (binary16, any rounding mode), none for RGBA32F here.
  const double unorm8 = storage == "rgba8" ? precision(Precision::Unorm8) : 0.0;
  const double half_ulps = storage == "rgba16f" ? 2.0 : 0.0;
  if (reduction == "fixed_point" && ref_reduction != "fixed_point")
    // Fixed point (2^-14 quanta, rounded per fragment and at the resolve) against an exact float
    // mean: at most one quantum apart before storage, then the storage rounding.
    // Float storage: 2^-9 |ref| covers two binary16 half-ulps (each <= 2^-10 |ref|).
    return {V::FixedPointVsExact, "fixed-point-vs-exact", std::ldexp(1.0, -14) + unorm8,
            storage == "rgba8" ? 0.0 : std::ldexp(1.0, -9), 0.0, 0.0, false,
            "fixed-point quanta against the exact mean, then the storage rounding"};
  if (reduction == "fixed_point")
    // The reduction itself is exact (integer sums, same rounding on both sides: bit-identical
    // when fragment values agree, see tests/gl). The fragment values are each backend's own
    // float shading at its own interpolated position, so they carry a shading error: 2^-7
    // relative, the G-buffer's texture bound (8-bit sub-texel weights, "texture-8bit-weights")
    // that textured albedo and emission carry. A shading difference also moves a fragment's
    // rounding to the fixed-point grid by one quantum (2^-14), which is all that shows on
    // near-black voxels.
    return {V::FixedPointExactShading, "fixed-point-exact+shading", std::ldexp(1.0, -14) + unorm8, std::ldexp(1.0, -7),
            0.0, half_ulps, false,
            "exact reduction; each fragment's float shading and 8-bit texture filtering weights, then the storage rounding"};
  if (reduction == "cas_rgba8")
    return {V::CasInterval, "cas-rgba8-interval", precision(Precision::Unorm8), 0.0, 0.0, 0.0, true, "any fragment order"};
  if (reduction == "running_mean")
    // The interval (stages/running_mean.h) already holds binary16 rounding of every step in any
    // rounding mode; RGBA8 storage would round once more.
    return {V::RunningMeanInterval, "running-mean-half-interval", unorm8, 0.0, 0.0, 0.0, true,
            "non-atomic running mean: any order, any non-empty subset (lost updates), binary16 each step"};
  if (storage == "rgba8")
    return {V::Rgba8Quantised, "rgba8-quantised", precision(Precision::Unorm8), 0.0, 0.0, 0.0, false, "8-bit UNORM: rounding vs truncation"};
  if (storage == "rgba16f")
    return {V::Rgba16fUlp, "rgba16f-ulp", 0.0, 0.0, std::ldexp(1.0, -23), 2.0, false,
            "float atomics sum in any order, stored as binary16"};
  return {V::Rgba32fSum, "rgba32f-sum", 1e-7, 0.0, std::ldexp(1.0, -23), 0.0, false, "float sum order"};
}

MipBound mip_bound(const VoxelModel& base, const std::string& storage, int level, bool anisotropic, double cas_width) {
  // A base level's half-ulps are at most 2^-10 |ref| each.
  MipBound b{base.abs + cas_width, base.rel + base.half_ulps * std::ldexp(1.0, -10) + 2.0 * base.per_fragment_rel * 8.0};
  double q_abs = 0.0, q_rel = 0.0;  // one storage rounding per level (any rounding mode)
  if (storage == "rgba8") q_abs = precision(Precision::Unorm8);
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
