#include "stage_compare.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "compare/fill_ties.h"
#include "compare/image_edges.h"
#include "compare/mip_rounding.h"
#include "compare/tie_range.h"
#include "compare/tolerance.h"
#include "io/image_io.h"
#include "io/nrrd.h"
#include "stages/shadow_map.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {

namespace st = stage_names;

std::string mask_stem(const std::string& stage) {
  std::string s = stage;
  std::replace(s.begin(), s.end(), '.', '_');
  return s + "_mask";
}

Offender pixel_offender(const Image& ref, const Image& test, int x, int y, float err, float bound) {
  Offender o;
  o.at = {x, y, -1};
  for (int c = 0; c < ref.channels; ++c) o.reference.push_back(ref.at(x, y, c));
  for (int c = 0; c < test.channels; ++c) o.test.push_back(test.at(x, y, c));
  o.error = err;
  o.bound = bound;
  return o;
}

Offender voxel_offender(const Volume& ref, const Volume& test, int x, int y, int z, float err, float bound) {
  Offender o;
  o.at = {x, y, z};
  for (int c = 0; c < ref.channels; ++c) o.reference.push_back(ref.voxel(x, y, z)[c]);
  for (int c = 0; c < test.channels; ++c) o.test.push_back(test.voxel(x, y, z)[c]);
  o.error = err;
  o.bound = bound;
  return o;
}

void write_image_mask(const CompareOptions& opt, StageVerdict& v, const Image& ref, const std::vector<uint8_t>& state) {
  if (opt.mask_dir.empty()) return;
  // Grey context (reference luminance, dimmed), yellow = tolerated edge tie, red = beyond bound.
  Image m(ref.width, ref.height, 3);
  float peak = 1e-6f;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) peak = std::max(peak, std::abs(ref.at(x, y, 0)));
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const uint8_t s = state[size_t(y) * size_t(ref.width) + size_t(x)];
      const float g = 0.35f * std::min(1.0f, std::abs(ref.at(x, y, 0)) / peak);
      m.set_rgb(x, y, s == 2 ? vec3(1, 0, 0) : s == 1 ? vec3(1, 0.85f, 0) : vec3(g));
    }
  std::filesystem::create_directories(opt.mask_dir);
  write_png_linear((std::filesystem::path(opt.mask_dir) / (mask_stem(v.stage) + ".png")).string(), m, 0.0f, 1.0f);
  v.mask = opt.mask_prefix + mask_stem(v.stage) + ".png";
}

void write_volume_mask(const CompareOptions& opt, StageVerdict& v, const Volume& mask) {
  if (opt.mask_dir.empty() || v.out_of_bound == 0) return;
  std::filesystem::create_directories(opt.mask_dir);
  write_volume_montage((std::filesystem::path(opt.mask_dir) / (mask_stem(v.stage) + ".png")).string(), mask, 64, 1.0f);
  v.mask = opt.mask_prefix + mask_stem(v.stage) + ".png";
}

StageVerdict missing(const std::string& stage, const std::string& why) {
  StageVerdict v;
  v.stage = stage;
  v.verdict = Verdict::Missing;
  v.note = why;
  return v;
}

bool same_size(const Volume& a, const Volume& b) { return a.nx == b.nx && a.ny == b.ny && a.nz == b.nz; }

float alpha_of(const Volume& v, size_t i) {
  return v.channels >= 4 ? v.data[i * size_t(v.channels) + 3] : v.data[i * size_t(v.channels)];
}

// Any of the RGB channels non-zero (a voxel with light, whatever its opacity).
bool carries_light(const Volume& v, size_t i) {
  if (v.channels < 4) return false;
  for (int c = 0; c < 3; ++c)
    if (v.data[i * size_t(v.channels) + size_t(c)] != 0.0f) return true;
  return false;
}

// Occupancy = alpha > 0 (or the single channel > 0).
std::vector<uint8_t> occupancy(const Volume& v) {
  std::vector<uint8_t> occ(v.voxel_count());
  for (size_t i = 0; i < occ.size(); ++i) occ[i] = alpha_of(v, i) > 0.0f ? 1 : 0;
  return occ;
}

void xyz_of(const Volume& v, size_t i, int& x, int& y, int& z) {
  x = int(i % size_t(v.nx));
  y = int((i / size_t(v.nx)) % size_t(v.ny));
  z = int(i / (size_t(v.nx) * size_t(v.ny)));
}

// Every channel of the test pixel within [min, max] of the reference's 3x3 neighbourhood,
// widened by the pixel's bound.
template <typename Bound>
bool admissible_tie(const Image& ref, const Image& test, int x, int y, int channels, Bound bound) {
  for (int c = 0; c < channels; ++c) {
    double lo = 1e300, hi = -1e300;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int u = x + dx, w = y + dy;
        if (u < 0 || w < 0 || u >= ref.width || w >= ref.height) continue;
        lo = std::min(lo, double(ref.at(u, w, c)));
        hi = std::max(hi, double(ref.at(u, w, c)));
      }
    const double t = test.at(x, y, c), b = bound(c);
    if (!(t >= lo - b && t <= hi + b)) return false;
  }
  return true;
}

}  // namespace

StageVerdict compare_image_stage(const std::string& stage, const Image& ref, const Image& test, const Image* edge_hint,
                                 const CompareOptions& opt, const Image* texture_slack,
                                 const DisplayTransform* display, const Image* tie_range) {
  StageVerdict v;
  v.stage = stage;
  if (ref.width != test.width || ref.height != test.height) {
    v.verdict = Verdict::Fail;
    v.note = "size differs: reference " + std::to_string(ref.width) + "x" + std::to_string(ref.height) + ", test " +
             std::to_string(test.width) + "x" + std::to_string(test.height);
    return v;
  }
  const ImageModel m = image_model(stage);
  v.model = m.name;
  v.bound = bound_text(m);
  const int slack_ch = texture_slack ? texture_slack_channel(stage, *texture_slack) : -1;
  const bool use_slack = slack_ch >= 0 && texture_slack->width == ref.width && texture_slack->height == ref.height;
  if (use_slack)
    v.bound +=
        " + the reference's texture slack (its value's range under a 2^-8 px sample shift and any "
        "admissible texture LOD)";
  const int ch = std::min(ref.channels, test.channels);
  const bool strict_ties = m.id != ToleranceModel::Shading;
  const TieRangeChannels alt_ch = tie_range && tie_range->width == ref.width && tie_range->height == ref.height
                                      ? tie_range_channels(stage, *tie_range, ch)
                                      : TieRangeChannels();
  const bool alternatives_only = !alt_ch.empty();
  // The shading stages' range comes from the reference re-shaded on the test's own G-buffer and
  // shadow maps (stages/direct_ties.h): only PCF taps its lookup's float arithmetic may flip.
  const bool pcf_range = alternatives_only && m.id == ToleranceModel::Shading;
  if (pcf_range)
    v.bound += "; ties: only PCF taps that the lookup's float arithmetic may flip on the test's own shadow maps, "
               "no edge or interior share";
  else if (alternatives_only)
    v.bound += "; ties: only the reference's raster alternatives (" + tie_range_stage(stage) +
               "), no edge or interior share";
  double mean_abs = 0;
  for (float x : ref.data) mean_abs += double(std::abs(x));
  mean_abs /= std::max<size_t>(1, ref.data.size());
  // Alpha-mask ties (docs/compare.md, "Alpha-mask ties") are edges inside a triangle that the
  // depth may not show: the reference marks them, camera-space stages (those with a depth hint)
  // add them to the edge map, where a flipped pixel must still be an admissible neighbour value.
  const int alpha_ch = texture_slack && edge_hint ? alpha_tie_channel(*texture_slack) : -1;
  const bool alpha_ties =
      alpha_ch >= 0 && texture_slack->width == ref.width && texture_slack->height == ref.height;
  // Depth images are their own discontinuity hint.
  if (!edge_hint && m.id == ToleranceModel::Depth) edge_hint = &ref;
  std::vector<uint8_t> edge = edge_map(ref, edge_hint);
  if (alpha_ties)
    for (int y = 0; y < ref.height; ++y)
      for (int x = 0; x < ref.width; ++x)
        if (texture_slack->at(x, y, alpha_ch) > 0.0f) edge[size_t(y) * size_t(ref.width) + size_t(x)] = 1;
  std::vector<uint8_t> state(edge.size(), 0);  // 0 ok, 1 tolerated edge, 2 beyond bound
  std::vector<Offender> offenders;
  double se = 0;
  size_t edge_pixels = 0, interior_bad = 0, edge_bad = 0, inadmissible = 0, alternatives = 0;
  // A UNORM depth map: each side within a step q of its float depth (either neighbour, GL 4.5
  // section 2.3.5.2), so two maps within the float bound stay within it + 2q.
  const double depth_format = m.id == ToleranceModel::Depth ? 2.0 * opt.depth_quantum : 0.0;
  if (depth_format > 0) v.bound += " + 2q of the UNORM depth format (" + std::to_string(depth_format) + ")";
  auto linear_bound = [&](int x, int y, int c) {
    double bound = m.abs + m.rel * std::abs(double(ref.at(x, y, c))) + m.abs_of_mean * mean_abs + depth_format;
    if (m.slope_factor > 0) bound += m.slope_factor * attribute_slope(ref, x, y, c);
    if (use_slack) bound += double(texture_slack->at(x, y, slack_ch));
    return bound;
  };
  // A declared display transform: the reference is judged as the engine would have written it
  // (colour channels only), with its bound carried through the transform (docs/compare.md,
  // "Display transform").
  const bool displayed = display && display->declared();
  Image shown;
  if (displayed) {
    shown = ref;
    for (int y = 0; y < ref.height; ++y)
      for (int x = 0; x < ref.width; ++x)
        for (int c = 0; c < std::min(ref.channels, 3); ++c) shown.at(x, y, c) = float(display->apply(ref.at(x, y, c)));
    v.bound += "; carried through the declared display transform (" + to_string(display->op) + ", exposure " +
               std::to_string(display->exposure) + ", gamma " + std::to_string(display->gamma) + ", " +
               std::to_string(display->bits) + " bits): its change over [r - b, r + b] + one step";
  }
  // The re-traced composite built on a decoded display-encoded direct light is within one more
  // step of the exact one (DisplayTransform::decodable).
  const double decoded_input = displayed && opt.direct_decoded_from_display && stage == stage_names::kImageFinal
                                   ? display->quantisation_allowance()
                                   : 0.0;
  if (decoded_input > 0) v.bound += " + one step for image.direct decoded from display";
  const Image& judged = displayed ? shown : ref;
  auto pixel_bound = [&](int x, int y, int c) {
    const double b = linear_bound(x, y, c);
    return displayed && c < 3 ? display->carry_bound(ref.at(x, y, c), b) + decoded_input : b;
  };
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const size_t i = size_t(y) * size_t(ref.width) + size_t(x);
      edge_pixels += edge[i];
      double worst_ratio = 0;
      float worst_err = 0, worst_bound = 0;
      for (int c = 0; c < ch; ++c) {
        const double r = judged.at(x, y, c), t = test.at(x, y, c), d = std::abs(t - r);
        const double bound = pixel_bound(x, y, c);
        se += d * d;
        v.max_abs = std::max(v.max_abs, std::isfinite(d) ? d : 1e30);
        const double ratio = std::isfinite(d) ? d / std::max(bound, 1e-30) : 1e30;
        if (ratio > worst_ratio) worst_ratio = ratio, worst_err = float(d), worst_bound = float(bound);
      }
      ++v.checked;
      if (worst_ratio <= 1.0) continue;
      ++v.out_of_bound;
      // A tie is a value the reference could have produced here: within its 3x3 neighbourhood's
      // range plus this pixel's bound (dEQP's verifiers accept any admissible neighbour), never
      // anything (docs/compare.md, "Ties are admissible values").
      // Not for shading stages: their inputs (the G-buffer) carry texture freedom that their
      // bound does not propagate, so a value outside the range is no proof of a bug there yet.
      const auto bound_of = [&](int c) { return pixel_bound(x, y, c); };
      // A raster alternative: a value a correct GL shows here when an edge, a depth order, a
      // facing or an alpha test ties the other way (compare/tie_range.h). The bound is the
      // pixel's, plus its relative term on the alternative's larger magnitude. Where the
      // reference supplies them (its G-buffer stages), they are the only ties: the neighbourhood
      // rule and the edge and interior shares are not used (docs/compare.md, "Raster
      // alternatives": every G-buffer pixel beyond its bound on every scene at 64^2-256^2 was one).
      // A stage the engine wrote display-encoded is admitted where its value lies between the
      // range's ends, each widened by the linear bound, carried through the transform (monotone:
      // DisplayTransform::apply), plus the store's quantisation.
      const auto is_alternative = [&] {
        if (alt_ch.empty()) return false;
        for (int c = 0; c < ch; ++c) {
          const double lo = tie_range->at(x, y, alt_ch.lo[size_t(c)]), hi = tie_range->at(x, y, alt_ch.hi[size_t(c)]);
          const double b = linear_bound(x, y, c) + m.rel * std::max(0.0, std::max(std::abs(lo), std::abs(hi)) -
                                                                             std::abs(double(ref.at(x, y, c))));
          const double t = test.at(x, y, c);
          if (displayed && c < 3) {
            const double q = display->quantisation_allowance();
            if (!(t >= display->apply(lo - b) - q && t <= display->apply(hi + b) + q)) return false;
          } else if (!within_tie_range(*tie_range, alt_ch, x, y, c, t, b)) {
            return false;
          }
        }
        return true;
      };
      if (is_alternative()) {
        ++alternatives, state[i] = 1;
      } else if (alternatives_only || (strict_ties && !admissible_tie(judged, test, x, y, ch, bound_of))) {
        ++inadmissible, state[i] = 2;
      } else if (edge[i]) {
        ++edge_bad, state[i] = 1;
      } else {
        ++interior_bad, state[i] = 2;
      }
      offenders.push_back(pixel_offender(judged, test, x, y, worst_err, worst_bound));
    }
  v.rms = std::sqrt(se / double(std::max<size_t>(1, v.checked * size_t(std::max(ch, 1)))));
  const double n = double(std::max<size_t>(1, v.checked));
  // Edge ties are counted against the pixels the edge map flags, not against all pixels: their
  // number grows with the length of the edges (~W) while the pixel count grows as W^2, so a share
  // of all pixels meant a different share of the edges at every size (3.2% of the built-in scene's
  // position edge pixels at 32^2, 41% at 512^2; docs/compare.md, "Edges").
  double allow_i = alternatives_only ? 0.0 : m.interior_fraction,
         allowed_edge_pixels = alternatives_only ? 0.0 : m.edge_tie_fraction * double(edge_pixels);
  if (is_cone_traced(stage, opt.soft_shadows) && opt.upstream_tie_fraction > 0) {
    // Voxels that legitimately differ (ties) are seen by many cones anywhere in the image, not at
    // edges: allow a proportional share of all pixels, at any value (a tied voxel moves a cone's
    // result by the voxel's difference, which no neighbourhood of the reference bounds). The
    // isolated judgement on the test's own voxels (compare/isolated_stages.h) has no such ties.
    const double widened = std::min(0.05, 4.0 * opt.upstream_tie_fraction);
    allow_i = std::max(allow_i, widened);
    allowed_edge_pixels = std::max(allowed_edge_pixels, widened * n);
    interior_bad += inadmissible;
    inadmissible = 0;
  }
  v.allowed = edge_bad + interior_bad + alternatives;
  const double fi = double(interior_bad) / n;
  if (inadmissible > 0 || fi > allow_i || double(edge_bad) > allowed_edge_pixels)
    v.verdict = Verdict::Fail;
  else if (v.out_of_bound > 0) v.verdict = Verdict::Warn;
  else v.verdict = Verdict::Pass;
  const double fe = edge_pixels ? double(edge_bad) / double(edge_pixels) : 0.0;
  char buf[200];
  std::snprintf(buf, sizeof buf, "%zu of %zu pixels beyond the bound (%zu of %zu edge pixels = %.2f%%, %.3f%% interior)",
                v.out_of_bound, v.checked, edge_bad, edge_pixels, 100 * fe, 100 * fi);
  v.note = buf;
  const bool light_space_range = alternatives_only && tie_range_stage(stage) != stage_names::kGbufferTieRange;
  if (alternatives)
    v.note += "; " + std::to_string(alternatives) +
              (pcf_range            ? " within the range of PCF taps that may flip (float lookup arithmetic)"
               : light_space_range ? " at a depth the reference's raster alternatives allow (2^-8 texel snapping, "
                                     "alpha-test ties)"
                                   : " showing a surface or facing the reference's raster alternatives allow (2^-8 px snapping)");
  if (inadmissible)
    v.note += "; " + std::to_string(inadmissible) +
              (pcf_range ? " outside the range of PCF taps that may flip (not a value a tie can give)"
               : alternatives_only ? " not among the reference's raster alternatives (not a value a tie can give)"
                                   : " outside the reference's 3x3 range plus the bound (not a value a tie can give)");
  v.extra = {{"edge_pixels", edge_pixels},
             {"edge_fraction", fe},
             {"interior_fraction", fi},
             {"inadmissible", inadmissible},
             {"raster_alternatives", alternatives},
             {"mean_abs_reference", mean_abs},
             {"allowed_edge_fraction", edge_pixels ? allowed_edge_pixels / double(edge_pixels) : 0.0},
             {"allowed_interior_fraction", allow_i}};
  if (displayed) v.extra["display_transform"] = to_json(*display);
  if (allow_i > m.interior_fraction && v.out_of_bound) v.note += "; allowance widened by upstream voxel ties";
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  write_image_mask(opt, v, ref, state);
  return v;
}

namespace {
StageVerdict compare_volume_masked(const std::string& stage, const Volume& ref, const Volume& test,
                                   double abs, double rel, const CompareOptions& opt,
                                   const std::vector<uint8_t>* tolerated,
                                   const std::vector<float>* extra_abs = nullptr);
}  // namespace

StageVerdict compare_volume_plain(const std::string& stage, const Volume& ref, const Volume& test, double abs, double rel,
                                  const CompareOptions& opt) {
  return compare_volume_masked(stage, ref, test, abs, rel, opt, nullptr);
}

namespace {
StageVerdict compare_volume_masked(const std::string& stage, const Volume& ref, const Volume& test,
                                   double abs, double rel, const CompareOptions& opt,
                                   const std::vector<uint8_t>* tolerated,
                                   const std::vector<float>* extra_abs) {
  StageVerdict v;
  v.stage = stage;
  v.model = "volume-abs-rel";
  char b[120];
  std::snprintf(b, sizeof b, "|d| <= %.3g + %.3g |ref|", abs, rel);
  v.bound = b;
  if (!same_size(ref, test)) {
    v.verdict = Verdict::Fail;
    v.note = "volume sizes differ";
    return v;
  }
  Volume mask(ref.nx, ref.ny, ref.nz, 1);
  std::vector<Offender> offenders;
  const int ch = std::min(ref.channels, test.channels);
  double se = 0;
  for (size_t i = 0; i < ref.voxel_count(); ++i) {
    double worst_ratio = 0;
    float we = 0, wb = 0;
    for (int c = 0; c < ch; ++c) {
      const double r = ref.data[i * size_t(ref.channels) + size_t(c)], t = test.data[i * size_t(test.channels) + size_t(c)];
      const double slack = extra_abs && i < extra_abs->size() ? double((*extra_abs)[i]) : 0.0;
      const double d = std::abs(t - r), bound = abs + rel * std::abs(r) + slack;
      se += d * d;
      v.max_abs = std::max(v.max_abs, std::isfinite(d) ? d : 1e30);
      const double ratio = std::isfinite(d) ? d / std::max(bound, 1e-30) : 1e30;
      if (ratio > worst_ratio) worst_ratio = ratio, we = float(d), wb = float(bound);
    }
    ++v.checked;
    if (worst_ratio <= 1.0) continue;
    ++v.out_of_bound;
    const bool tol = tolerated && i < tolerated->size() && (*tolerated)[i];
    mask.data[i] = tol ? 0.5f : 1.0f;
    if (tol) {
      ++v.allowed;
      continue;
    }
    int x, y, z;
    xyz_of(ref, i, x, y, z);
    offenders.push_back(voxel_offender(ref, test, x, y, z, we, wb));
  }
  v.rms = std::sqrt(se / double(std::max<size_t>(1, v.checked * size_t(std::max(ch, 1)))));
  v.verdict = v.out_of_bound > v.allowed ? Verdict::Fail : v.allowed ? Verdict::Warn : Verdict::Pass;
  v.note = std::to_string(v.out_of_bound) + " of " + std::to_string(v.checked) + " voxels beyond the bound";
  if (v.allowed) v.note += " (" + std::to_string(v.allowed) + " above voxels that tie upstream)";
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  write_volume_mask(opt, v, mask);
  return v;
}
}  // namespace

namespace {

// Voxels where the two sides may legitimately differ (ties); mips above them inherit the
// tolerance.
using Taint = std::vector<uint8_t>;

bool face_neighbour_in(const Volume& v, const std::vector<uint8_t>& set, size_t i) {
  int x, y, z;
  xyz_of(v, i, x, y, z);
  // 26-neighbourhood: a sample on a voxel edge or corner moves diagonally.
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int xx = x + dx, yy = y + dy, zz = z + dz;
        if (v.contains(xx, yy, zz) && set[(size_t(zz) * size_t(v.ny) + size_t(yy)) * size_t(v.nx) + size_t(xx)]) return true;
      }
  return false;
}

constexpr double kTieFraction = 0.01;  // ties beyond 1% of occupied voxels are not ties

StageVerdict compare_occupancy(const StageSet& rs, const StageSet& ts, const CompareOptions& opt, Taint& taint) {
  const Volume& ref = rs.volumes.at(st::kVoxelRadiance);
  const Volume& test = ts.volumes.at(st::kVoxelRadiance);
  StageVerdict v;
  v.stage = st::kVoxelOccupancy;
  if (!same_size(ref, test)) {
    v.verdict = Verdict::Fail;
    v.note = "grid sizes differ: " + std::to_string(ref.nx) + " vs " + std::to_string(test.nx);
    return v;
  }
  // If the reference voxelized conservatively, the GPU's sample rule must give a SUBSET of it
  // (every covered sample lies on the triangle inside its voxel); missing voxels are holes.
  const auto vz = rs.settings.is_object() ? rs.settings.find("voxelizer") : rs.settings.end();
  const bool conservative_ref = vz != rs.settings.end() && *vz == "conservative";
  v.model = conservative_ref ? "subset-of-conservative" : "gpu-rule-exact";
  v.bound = conservative_ref
                ? "no voxel outside the conservative set (except boundary ties); missing voxels are holes (warn)"
                : "exact, except ties (up to 1% of occupied voxels -> warn): a missing voxel with an extra one among "
                  "its 26 neighbours (sample on a voxel face), or a voxel of <= 2 fragments (sample on a triangle "
                  "edge); any other missing or extra voxel fails";
  v.bound += "; a filled voxel (opaque, no fragments: solid/thickening) may differ only where an axis ray through it "
             "crosses a surface difference";
  const auto ro = occupancy(ref), to = occupancy(test);
  auto frag_of = [&](const StageSet& s) -> const Volume* {
    auto it = s.volumes.find(st::kVoxelFragments);
    return it != s.volumes.end() && same_size(it->second, ref) ? &it->second : nullptr;
  };
  const Volume *rfrag = frag_of(rs), *tfrag = frag_of(ts);
  std::vector<uint8_t> missing_set(ro.size(), 0), extra_set(ro.size(), 0);
  size_t occupied = 0;
  for (size_t i = 0; i < ro.size(); ++i) {
    occupied += ro[i];
    missing_set[i] = ro[i] && !to[i];
    extra_set[i] = to[i] && !ro[i];
  }
  Volume mask(ref.nx, ref.ny, ref.nz, 1);
  std::vector<Offender> offenders;
  size_t missing_n = 0, extra_n = 0, ties = 0, hard = 0;
  taint.assign(ro.size(), 0);
  // Filled voxels (opaque without fragments: solid interior, thickening) are judged by their own
  // rule (fill_ties.h). A sample-rule fragment lies on a triangle inside its voxel, so where the
  // counts agree the two sides hold the same triangles (hence the same facing), also against a
  // conservative reference.
  std::vector<uint8_t> surface_differs;
  if (rfrag && tfrag) surface_differs = surface_differences(*rfrag, *tfrag);
  size_t fill_differences = 0;
  for (size_t i = 0; i < ro.size(); ++i) {
    if (!missing_set[i] && !extra_set[i]) continue;
    (missing_set[i] ? missing_n : extra_n)++;
    // Coverage tie: the voxel held at most 2 fragments on the side that has it (samples on a
    // triangle edge, decided by the fill rule).
    const Volume* fr = missing_set[i] ? rfrag : tfrag;
    const bool filled = !surface_differs.empty() && fr->data[i * size_t(fr->channels)] == 0.0f;
    const bool few = fr && fr->data[i * size_t(fr->channels)] <= 2.0f;
    bool allowed;
    if (filled) {
      ++fill_differences;
      allowed = ray_meets(ref, surface_differs, i);
    } else {
      const bool tie = few || face_neighbour_in(ref, missing_set[i] ? extra_set : missing_set, i);
      allowed = tie || (conservative_ref && missing_set[i]);
    }
    taint[i] = 1;
    mask.data[i] = allowed ? 0.5f : 1.0f;  // white = unexplained difference, grey = tie / hole
    if (allowed) {
      ++ties;
      continue;
    }
    ++hard;
    int x, y, z;
    xyz_of(ref, i, x, y, z);
    offenders.push_back(voxel_offender(ref, test, x, y, z, 1.0f, 0.0f));
  }
  v.checked = ro.size();
  v.out_of_bound = missing_n + extra_n;
  v.allowed = ties;
  v.max_abs = v.out_of_bound ? 1.0 : 0.0;
  const bool too_many_ties = double(ties) > kTieFraction * double(std::max<size_t>(occupied, 1)) && !conservative_ref;
  v.verdict = hard || too_many_ties ? Verdict::Fail : ties ? Verdict::Warn : Verdict::Pass;
  v.note = std::to_string(occupied) + " occupied in the reference; " + std::to_string(missing_n) + " missing, " +
           std::to_string(extra_n) + " extra in " + ts.backend + " (" + std::to_string(ties) +
           (conservative_ref ? " holes/ties" : " boundary ties") + ")";
  if (too_many_ties) v.note += "; too many to be ties (a shifted grid?)";
  if (too_many_ties)  // list the paired voxels too: they are the evidence of a shift
    for (size_t i = 0; i < ro.size() && offenders.size() < 4 * opt.worst_n; ++i)
      if (missing_set[i] || extra_set[i]) {
        int x, y, z;
        xyz_of(ref, i, x, y, z);
        offenders.push_back(voxel_offender(ref, test, x, y, z, 1.0f, 0.0f));
      }
  if (fill_differences) v.note += "; " + std::to_string(fill_differences) + " of them filled voxels (solid/thickening)";
  v.extra = {{"occupied_reference", occupied}, {"missing", missing_n}, {"extra", extra_n}, {"ties", ties},
             {"fill_differences", fill_differences}};
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  write_volume_mask(opt, v, mask);
  return v;
}

StageVerdict compare_holes(const StageSet& rs, const StageSet& ts, const CompareOptions& opt) {
  StageVerdict v;
  v.stage = st::kVoxelHoles;
  v.model = "conservative-holes-reported";
  v.bound = "reported, never failed: holes are a property of sample-based voxelization";
  const Volume* cons = rs.volumes.count(st::kVoxelConservative) ? &rs.volumes.at(st::kVoxelConservative) : nullptr;
  if (!cons) cons = ts.volumes.count(st::kVoxelConservative) ? &ts.volumes.at(st::kVoxelConservative) : nullptr;
  if (!cons || !ts.volumes.count(st::kVoxelRadiance)) return missing(v.stage, "no conservative occupancy or no test voxels");
  const Volume& test = ts.volumes.at(st::kVoxelRadiance);
  if (!same_size(*cons, test)) return missing(v.stage, "conservative and test grids differ in size");
  const auto to = occupancy(test);
  Volume mask(test.nx, test.ny, test.nz, 1);
  size_t holes = 0, cons_n = 0;
  for (size_t i = 0; i < to.size(); ++i) {
    const bool c = cons->data[i * size_t(cons->channels)] > 0.0f;
    cons_n += c;
    if (c && !to[i]) ++holes, mask.data[i] = 1.0f;
  }
  v.checked = cons_n;
  v.out_of_bound = holes;
  v.allowed = holes;
  v.verdict = Verdict::Pass;
  char b[160];
  std::snprintf(b, sizeof b, "%zu holes: %.2f%% of the %zu conservatively covered voxels are not occupied in %s", holes,
                cons_n ? 100.0 * double(holes) / double(cons_n) : 0.0, cons_n, ts.backend.c_str());
  v.note = b;
  v.extra = {{"holes", holes}, {"conservative_voxels", cons_n}};
  write_volume_mask(opt, v, mask);
  return v;
}

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g%%", 100.0 * fraction);
  return buf;
}

StageVerdict compare_radiance(const StageSet& rs, const StageSet& ts, const CompareOptions& opt, Taint& taint) {
  const Volume& ref = rs.volumes.at(st::kVoxelRadiance);
  const Volume& test = ts.volumes.at(st::kVoxelRadiance);
  StageVerdict v;
  v.stage = st::kVoxelRadiance;
  if (!same_size(ref, test)) {
    v.verdict = Verdict::Fail;
    v.note = "grid sizes differ";
    return v;
  }
  const VoxelModel m = voxel_model(ts.storage, ts.reduction, rs.reduction);
  v.model = m.name;
  v.bound = bound_text(m);
  const Volume* lo = rs.volumes.count(st::kVoxelCasLo) ? &rs.volumes.at(st::kVoxelCasLo) : nullptr;
  const Volume* hi = rs.volumes.count(st::kVoxelCasHi) ? &rs.volumes.at(st::kVoxelCasHi) : nullptr;
  const bool interval = m.cas_interval && lo && hi && same_size(*lo, ref) && same_size(*hi, ref);
  if (m.cas_interval && !interval)
    v.note = "no cas_lo/cas_hi interval in the reference (render it with reduction " + ts.reduction + "): judged with +-" +
             std::to_string(m.abs) + " only; ";
  // Each voxel's mean may move by its fragments' mean shading slack (the reference's
  // voxel.shading_slack, docs/compare.md "Voxel shading slack").
  const Volume* lod_slack =
      rs.volumes.count(st::kVoxelShadingSlack) ? &rs.volumes.at(st::kVoxelShadingSlack) : nullptr;
  if (lod_slack && !same_size(*lod_slack, ref)) lod_slack = nullptr;
  const Volume* frags = rs.volumes.count(st::kVoxelFragments) ? &rs.volumes.at(st::kVoxelFragments) : nullptr;
  const Volume* tfrags = ts.volumes.count(st::kVoxelFragments) ? &ts.volumes.at(st::kVoxelFragments) : nullptr;
  if (tfrags && (!frags || !same_size(*tfrags, ref))) tfrags = nullptr;
  // Voxels whose every fragment's light GL computes bit for bit (the reference's voxel.exact:
  // emission from constants, no light in front, no bounce, no particles) reduce to the same
  // integers and the same half: with the fixed-point reduction and the same fragment count they
  // must be identical (docs/compare.md, "Exact voxels"). Needs the test's fragment counts.
  const Volume* exact = rs.volumes.count(st::kVoxelExact) ? &rs.volumes.at(st::kVoxelExact) : nullptr;
  if (exact && (!same_size(*exact, ref) || !tfrags || m.cas_interval)) exact = nullptr;
  size_t count_ties = 0, shading_ties = 0, transparent_lit = 0, exact_checked = 0, exact_differ = 0;
  const auto ro = occupancy(ref), to = occupancy(test);
  taint.assign(ro.size(), 0);
  Volume mask(ref.nx, ref.ny, ref.nz, 1);
  std::vector<Offender> offenders;
  const int ch = std::min(ref.channels, test.channels);
  double se = 0;
  for (size_t i = 0; i < ro.size(); ++i) {
    if (ro[i] != to[i]) continue;  // occupied on one side only: the occupancy stage judges it
    // Transparent voxels holding light (the particles' additive light has opacity 0) are judged
    // like occupied ones: a backend that loses that light must fail here, not one stage later.
    if (!ro[i] && !carries_light(ref, i) && !carries_light(test, i)) continue;
    if (!ro[i]) ++transparent_lit;
    const double n = frags ? std::max(1.0, double(frags->data[i * size_t(frags->channels)])) : 8.0;
    // Different fragment counts: MSAA sample-coverage ties at triangle edges changed the set of
    // fragments averaged. The mean of any set those ties admit is inside the reference's slack
    // (stages/coverage_ties.h), so a voxel beyond it is no tie; the count is still capped below.
    const bool count_tie = tfrags && frags->data[i * size_t(frags->channels)] != tfrags->data[i * size_t(tfrags->channels)];
    const bool exact_voxel = exact && !count_tie && exact->data[i * size_t(exact->channels)] > 0.0f;
    exact_checked += exact_voxel;
    double worst_ratio = 0;
    float we = 0, wb = 0;
    for (int c = 0; c < ch; ++c) {
      const size_t k = i * size_t(ref.channels) + size_t(c);
      const double r = ref.data[k], t = test.data[i * size_t(test.channels) + size_t(c)];
      const double slack =
          lod_slack && c < 3 ? double(lod_slack->data[i * size_t(lod_slack->channels)]) : 0.0;
      double d = std::abs(t - r), bound = exact_voxel ? 0.0 : m.bound(r, n) + slack;
      if (interval) {
        const double l = double(lo->data[k]) - m.abs - slack,
                     h = double(hi->data[k]) + m.abs + slack;
        d = t < l ? l - t : t > h ? t - h : 0.0;
        bound = m.abs + slack;
      }
      se += (t - r) * (t - r);
      v.max_abs = std::max(v.max_abs, std::abs(t - r));
      const double ratio = !std::isfinite(d) ? 1e30 : bound > 0 ? d / bound : (d > 0 ? 1e30 : 0.0);
      if (ratio > worst_ratio) worst_ratio = ratio, we = float(std::abs(t - r)), wb = float(bound);
    }
    ++v.checked;
    if (count_tie) ++count_ties, taint[i] = 1;
    if (worst_ratio <= 1.0) continue;
    ++v.out_of_bound;
    mask.data[i] = 1.0f;
    if (exact_voxel)
      ++exact_differ;  // no freedom there: never a tie
    else
      ++shading_ties;
    taint[i] = 1;
    int x, y, z;
    xyz_of(ref, i, x, y, z);
    offenders.push_back(voxel_offender(ref, test, x, y, z, we, wb));
  }
  // Shadow-test ties: a fragment whose light-space depth ties the shadow map flips a PCF tap on
  // one side only, moving that fragment by 1/taps of its light. They are rare and sit on shadow
  // edges; up to kShadingTieFraction of the voxels they warn, beyond that they fail.
  const bool shading_ties_tolerated =
      double(shading_ties) <= opt.shading_tie_fraction * double(std::max<size_t>(v.checked, 1));
  if (shading_ties_tolerated) v.allowed += shading_ties;
  v.rms = std::sqrt(se / double(std::max<size_t>(1, v.checked * size_t(std::max(ch, 1)))));
  const bool too_many = double(count_ties) > 2.0 * kTieFraction * double(std::max<size_t>(v.checked, 1));
  v.verdict = v.out_of_bound > v.allowed || too_many ? Verdict::Fail : v.allowed ? Verdict::Warn : Verdict::Pass;
  v.note += std::to_string(v.out_of_bound) + " of " + std::to_string(v.checked) + " voxels beyond the bound (" +
            std::to_string(v.checked - transparent_lit) + " occupied in both, " + std::to_string(transparent_lit) +
            " transparent with light)";
  v.extra["transparent_lit"] = transparent_lit;
  if (tfrags) v.note += "; " + std::to_string(count_ties) + " with a different fragment count (coverage ties" +
                        std::string(too_many ? ": more than 2%, not ties)" : ", judged within the slack)");
  v.extra["fragment_count_ties"] = count_ties;
  v.extra["exact_voxels"] = exact_checked;
  v.extra["exact_voxels_differing"] = exact_differ;
  if (exact) v.note += "; " + std::to_string(exact_differ) + " of " + std::to_string(exact_checked) + " exact voxels differ";
  v.extra["shading_ties"] = shading_ties;
  if (shading_ties)
    v.note += "; " + std::to_string(shading_ties) + " beyond the shading bound" +
              (opt.shading_tie_fraction <= 0.0
                   ? std::string(" on the test's own shadow maps (no share: not ties)")
                   : " (shadow-test ties" + std::string(shading_ties_tolerated ? ", tolerated up to " : ": more than ") +
                         percent(opt.shading_tie_fraction) + (shading_ties_tolerated ? ")" : ", not ties)"));
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  write_volume_mask(opt, v, mask);
  return v;
}

// A stage the reference has and the test lacks is "missing" (an engine dumps what it can), except
// within a family the test does have: a mip chain that stops short, or one light's shadow map of
// several, is a bug of the test (the settings fix the levels and the scene the lights).
bool chain_broken(const StageSet& ts, const std::optional<StageRef>& ref) {
  if (!ref || ref->row->index == StageIndex::None) return false;
  auto same_family = [&](const std::string& name) {
    const auto other = find_stage(name);
    return other && other->row == ref->row;
  };
  for (const auto& kv : ts.images)
    if (same_family(kv.first)) return true;
  for (const auto& kv : ts.volumes)
    if (same_family(kv.first)) return true;
  return false;
}

StageVerdict broken_chain(const std::string& stage, const StageSet& ts, const std::optional<StageRef>& ref) {
  StageVerdict v;
  v.stage = stage;
  v.verdict = Verdict::Fail;
  v.model = "required-stage";
  v.bound = "every member of a family the test produces (mip levels down to 1^3, one shadow map per light)";
  v.note = ts.backend + " has other " + std::string(ref->row->name) + " members but not this one (a chain that stops short)";
  return v;
}

// A level-L voxel covers a 2^L cube of the base: tainted if any voxel of that cube is.
Taint taint_at_level(const Taint& base, int n, const Volume& level_vol, int level) {
  Taint t(level_vol.voxel_count(), 0);
  if (base.empty()) return t;
  const int f = 1 << level;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        if (!base[(size_t(z) * size_t(n) + size_t(y)) * size_t(n) + size_t(x)]) continue;
        const int X = x / f, Y = y / f, Z = z / f;
        if (level_vol.contains(X, Y, Z)) t[(size_t(Z) * size_t(level_vol.ny) + size_t(Y)) * size_t(level_vol.nx) + size_t(X)] = 1;
      }
  return t;
}

// The base level's texture LOD slack carried up the chain: a level-L voxel is a convex combination
// of the 2^L cube of base voxels under it (iso box filter), so it moves by at most their largest
// slack; anisotropic compositing c_f + (1 - a_f) c_b at most doubles a bound per level (as the
// aniso-mip-propagated model). Empty when the reference has no slack volume.
// Per level-L voxel, the largest of `per_base` (one value per base voxel) over its 2^L cube, times
// 2^L for anisotropic levels.
std::vector<float> cube_max_slack(const Volume& s, const std::vector<float>& per_base, const Volume& level_vol,
                                  int level, bool aniso);

std::vector<float> mip_lod_slack(const StageSet& rs, const Volume& base, const Volume& level_vol,
                                 int level, bool aniso) {
  if (!rs.volumes.count(st::kVoxelShadingSlack)) return {};
  const Volume& s = rs.volumes.at(st::kVoxelShadingSlack);
  if (!same_size(s, base) || s.nx != s.ny || s.ny != s.nz) return {};
  std::vector<float> per_base(s.voxel_count());
  for (size_t i = 0; i < per_base.size(); ++i) per_base[i] = s.data[i * size_t(s.channels)];
  return cube_max_slack(s, per_base, level_vol, level, aniso);
}

// The running mean's interval carried up the chain (docs/compare.md, running-mean-half-interval):
// a base voxel may sit anywhere in [cas_lo, cas_hi], so it moves by at most hi - lo (largest over
// RGB); a level-L voxel, a convex combination of its cube, by at most the largest of those (the
// anisotropic compositing at most doubles it per level, as mip_lod_slack). Per voxel, not the
// grid's widest interval: a running mean's interval spans a shadow edge's fragments.
std::vector<float> mip_interval_slack(const StageSet& rs, const Volume& base, const Volume& level_vol, int level,
                                      bool aniso) {
  if (!rs.volumes.count(st::kVoxelCasLo) || !rs.volumes.count(st::kVoxelCasHi)) return {};
  const Volume& lo = rs.volumes.at(st::kVoxelCasLo);
  const Volume& hi = rs.volumes.at(st::kVoxelCasHi);
  if (!same_size(lo, base) || !same_size(hi, base) || lo.channels < 3 || hi.channels < 3 || lo.nx != lo.ny ||
      lo.ny != lo.nz)
    return {};
  std::vector<float> per_base(lo.voxel_count(), 0.0f);
  for (size_t i = 0; i < per_base.size(); ++i)
    for (int c = 0; c < 3; ++c)
      per_base[i] = std::max(per_base[i], hi.data[i * size_t(hi.channels) + size_t(c)] -
                                              lo.data[i * size_t(lo.channels) + size_t(c)]);
  return cube_max_slack(lo, per_base, level_vol, level, aniso);
}

std::vector<float> cube_max_slack(const Volume& s, const std::vector<float>& per_base, const Volume& level_vol,
                                  int level, bool aniso) {
  const int f = 1 << level;
  const float grow = aniso ? float(f) : 1.0f;
  std::vector<float> out(level_vol.voxel_count(), 0.0f);
  for (int z = 0; z < s.nz; ++z)
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x) {
        const int lx = x / f, ly = y / f, lz = z / f;
        if (lx >= level_vol.nx || ly >= level_vol.ny || lz >= level_vol.nz) continue;
        const size_t li =
            (size_t(lz) * size_t(level_vol.ny) + size_t(ly)) * size_t(level_vol.nx) + size_t(lx);
        const float v = per_base[(size_t(z) * size_t(s.ny) + size_t(y)) * size_t(s.nx) + size_t(x)];
        out[li] = std::max(out[li], grow * v);
      }
  return out;
}

// A declared mip_scale (compare/conventions.h) is a deviation the engine admits, not a convention
// the reference adopts: the verdict stands, and says whether the reference times scale^level
// (bound scaled alike) explains the test. A level that differs beyond that is a fault on top.
void explain_by_declared_mip_scale(StageVerdict& v, const Volume& ref, const Volume& test, int level, const MipBound& b,
                                   double scale, const CompareOptions& opt, const Taint& tolerated,
                                   const std::vector<float>& slack) {
  const double f = std::pow(scale, double(level));
  Volume scaled = ref;
  for (float& x : scaled.data) x = float(double(x) * f);
  std::vector<float> scaled_slack = slack;
  for (float& x : scaled_slack) x = float(double(x) * f);
  CompareOptions quiet = opt;
  quiet.mask_dir.clear();  // the declared-scale check writes no mask of its own
  const StageVerdict s = compare_volume_masked(v.stage, scaled, test, b.abs * f, b.rel, quiet, &tolerated,
                                               scaled_slack.empty() ? nullptr : &scaled_slack);
  const bool explained = s.verdict != Verdict::Fail;
  char text[200];
  std::snprintf(text, sizeof text, "; declared deviation mip_scale %.4g: %s reference x %.4g (scale^%d)", scale,
                explained ? "matches" : "does NOT match even", f, level);
  v.note += text;
  v.extra["declared_mip_scale"] = scale;
  v.extra["explained_by_declared_mip_scale"] = explained;
}

// Our GL backend's mip step (isotropic or anisotropic), judged on the test's own level below:
// exact up to the float arithmetic's rounding (compare/mip_rounding.h), so a wrong rounding fails
// here even where it hides in the end-to-end bound. Only a set our GL backend rendered on a driver (its facts name the
// renderer): a frame that merely calls itself "gl" (the compare tests' simulated GL frames, built
// from the reference's unrounded mips) has no such rounding to check.
void judge_mip_step_rounding(StageVerdict& v, const StageRow& row, int level, const StageSet& ts) {
  if (ts.backend != "gl" || ts.facts.renderer.empty() || level < 1) return;
  const std::string below = level == 1 ? std::string(st::kVoxelRadiance) : stage_name(row, level - 1);
  if (!ts.volumes.count(below)) return;
  const Volume& child = ts.volumes.at(below);
  const Volume& parent = ts.volumes.at(stage_name(row, level));
  const int direction = aniso_direction(row);
  const MipRoundingCheck r = direction < 0 ? check_iso_mip_rounding(child, parent, ts.storage)
                                           : check_aniso_mip_rounding(child, parent, ts.storage, direction);
  if (!r.checked) return;
  v.extra["step_rounding_checked"] = r.checked;
  v.extra["step_rounding_violations"] = r.violations;
  if (!r.violations) return;
  v.verdict = Verdict::Fail;
  v.note += "; " + std::to_string(r.violations) + " of " + std::to_string(r.checked) +
            " values are not the " + (direction < 0 ? "box filter" : "front-to-back composite") + " of the test's own " +
            below + " rounded as the storage rounds (first at (" +
            std::to_string(r.worst_x) + ", " + std::to_string(r.worst_y) + ", " + std::to_string(r.worst_z) +
            "); docs/compare.md \"Mip rounding\")";
}

StageVerdict compare_mip(const std::string& stage, const StageSet& rs, const StageSet& ts, const CompareOptions& opt,
                         const Taint& taint) {
  const StageRef ref = *find_stage(stage);  // a mip.<dir>.<level> row: the caller dispatched on it
  const int level = ref.index;
  const bool aniso = aniso_direction(*ref.row) >= 0;
  const VoxelModel base = voxel_model(ts.storage, ts.reduction, rs.reduction);
  double cas_width = 0.0;
  const bool running_mean = base.id == VoxelModelId::RunningMeanInterval;
  if (base.cas_interval && !running_mean && rs.volumes.count(st::kVoxelCasLo) && rs.volumes.count(st::kVoxelCasHi)) {
    const auto& lo = rs.volumes.at(st::kVoxelCasLo).data;
    const auto& hi = rs.volumes.at(st::kVoxelCasHi).data;
    for (size_t i = 0; i < lo.size() && i < hi.size(); ++i) cas_width = std::max(cas_width, double(hi[i] - lo[i]));
  }
  const MipBound b = mip_bound(base, ts.storage, level, aniso, cas_width);
  const Volume& base_vol = rs.volumes.at(st::kVoxelRadiance);
  const Taint lt = base_vol.nx == base_vol.ny && base_vol.ny == base_vol.nz
                       ? taint_at_level(taint, base_vol.nx, rs.volumes.at(stage), level)
                       : Taint();
  std::vector<float> slack = mip_lod_slack(rs, base_vol, rs.volumes.at(stage), level, aniso);
  if (running_mean) {
    const std::vector<float> width = mip_interval_slack(rs, base_vol, rs.volumes.at(stage), level, aniso);
    if (slack.empty()) slack = width;
    else
      for (size_t i = 0; i < slack.size() && i < width.size(); ++i) slack[i] += width[i];
  }
  StageVerdict v = compare_volume_masked(stage, rs.volumes.at(stage), ts.volumes.at(stage), b.abs,
                                         b.rel, opt, &lt, slack.empty() ? nullptr : &slack);
  v.model = std::string(aniso ? "aniso" : "iso") + "-mip-propagated(" + base.name + ")";
  // Opacity is a coverage fraction: outside [0, 1] is wrong whatever the reference says.
  const Volume& t = ts.volumes.at(stage);
  size_t bad_alpha = 0;
  if (t.channels >= 4)
    for (size_t i = 0; i < t.voxel_count(); ++i) {
      const float a = t.data[i * size_t(t.channels) + 3];
      if (a > 1.0f + 1e-3f || a < -1e-3f) ++bad_alpha;
    }
  if (bad_alpha) {
    v.verdict = Verdict::Fail;
    v.note += "; " + std::to_string(bad_alpha) + " voxels with opacity outside [0,1] (alpha not clamped?)";
  }
  v.extra["alpha_out_of_range"] = bad_alpha;
  v.extra["level"] = level;
  if (ts.conventions.mip_scale != 1.0) explain_by_declared_mip_scale(v, rs.volumes.at(stage), t, level, b, ts.conventions.mip_scale, opt, lt, slack);
  judge_mip_step_rounding(v, *ref.row, level, ts);
  return v;
}

// One step of the reference's shadow depth format (its manifest settings; absent = float).
double depth_quantum_of(const StageSet& rs) {
  if (!rs.settings.is_object() || !rs.settings.contains("shadow_depth_format")) return 0.0;
  const nlohmann::json& format = rs.settings.at("shadow_depth_format");
  for (ShadowDepthFormat f : {ShadowDepthFormat::Depth24, ShadowDepthFormat::Depth16})
    if (format == to_string(f)) return depth_quantum(f);
  return 0.0;
}

}  // namespace

Report compare_stage_sets(const StageSet& rs, const StageSet& ts, const CompareOptions& opt_in) {
  Report rep;
  CompareOptions opt = opt_in;
  opt.soft_shadows = soft_shadows_of(rs) || soft_shadows_of(ts);
  Taint taint, radiance_taint;
  const Image* depth_hint = rs.images.count(st::kGbufferDepth) ? &rs.images.at(st::kGbufferDepth) : nullptr;
  const Image* slack = rs.images.count(st::kGbufferTextureSlack) ? &rs.images.at(st::kGbufferTextureSlack) : nullptr;
  const Image* tie_range = rs.images.count(st::kGbufferTieRange) ? &rs.images.at(st::kGbufferTieRange) : nullptr;
  for (const std::string& stage : pipeline_order(rs, ts)) {
    const auto ref = find_stage(stage);
    const ToleranceModel model = ref ? ref->row->model : ToleranceModel::None;
    const bool r_has = rs.has(stage), t_has = ts.has(stage);
    if (model == ToleranceModel::VoxelOccupancy || model == ToleranceModel::VoxelRadiance) {
      if (!rs.volumes.count(st::kVoxelRadiance) || !ts.volumes.count(st::kVoxelRadiance))
        rep.stages.push_back(missing(stage, "voxel radiance missing on one side"));
      else
        rep.stages.push_back(model == ToleranceModel::VoxelOccupancy ? compare_occupancy(rs, ts, opt, taint)
                                                                     : compare_radiance(rs, ts, opt, radiance_taint));
      // The upstream share needs the reference's voxels; a set without them was judged missing.
      if (model == ToleranceModel::VoxelRadiance && rs.volumes.count(st::kVoxelRadiance)) {
        taint.resize(std::max(taint.size(), radiance_taint.size()), 0);
        for (size_t i = 0; i < radiance_taint.size(); ++i) taint[i] |= radiance_taint[i];
        size_t tainted = 0;
        for (uint8_t t : taint) tainted += t;
        const auto occ = occupancy(rs.volumes.at(st::kVoxelRadiance));
        size_t occupied = 0;
        for (uint8_t o : occ) occupied += o;
        opt.upstream_tie_fraction = occupied ? double(tainted) / double(occupied) : 0.0;
      }
      continue;
    }
    if (model == ToleranceModel::VoxelHoles) {
      rep.stages.push_back(compare_holes(rs, ts, opt));
      continue;
    }
    if (!r_has || !t_has) {
      rep.stages.push_back(r_has && chain_broken(ts, ref) ? broken_chain(stage, ts, ref)
                                                          : missing(stage, std::string("not produced by ") +
                                                                               (r_has ? ts.backend : rs.backend)));
      continue;
    }
    if (rs.images.count(stage)) {
      // A shadow map is its own depth: the camera's depth says nothing about its edges.
      const bool light_space =
          ref && (ref->row->index == StageIndex::Light || ref->row->index == StageIndex::CubeFace);
      const DisplayTransform& shown = ts.conventions.display;
      CompareOptions stage_opt = opt;
      if (light_space) stage_opt.depth_quantum = depth_quantum_of(rs);
      // A shadow map's raster alternatives are its own range image (stages/shadow_map_ties.h);
      // without one (an external reference) it keeps the neighbourhood rule and the shares.
      const auto own_range = light_space ? rs.images.find(tie_range_stage(stage)) : rs.images.end();
      const Image* range = !light_space ? tie_range : own_range != rs.images.end() ? &own_range->second : nullptr;
      rep.stages.push_back(compare_image_stage(stage, rs.images.at(stage), ts.images.at(stage),
                                               light_space ? nullptr : depth_hint, stage_opt, slack,
                                               shown.applies_to(stage) ? &shown : nullptr, range));
    } else if (model == ToleranceModel::Mip) {
      // The mip bounds and taint are taken on the reference's level 0.
      rep.stages.push_back(rs.volumes.count(st::kVoxelRadiance)
                               ? compare_mip(stage, rs, ts, opt, taint)
                               : missing(stage, "the reference's voxel.radiance is missing"));
    } else {
      rep.stages.push_back(compare_volume_plain(stage, rs.volumes.at(stage), ts.volumes.at(stage), 1e-6, 1e-5, opt));
    }
  }
  return rep;
}

}  // namespace vct::cmp
