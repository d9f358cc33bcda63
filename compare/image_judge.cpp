// Image stages (G-buffer, shadow maps, shading and cone images): each pixel is admitted by the first
// rule of the admission table (compare/admission.h) that holds, then the counted shares decide the
// verdict (compare/counted_shares.h). The bound terms and every rule: docs/compare.md.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/element_loop.h"
#include "compare/explain_element.h"
#include "compare/image_edges.h"
#include "compare/rule_masks.h"
#include "compare/stage_compare.h"
#include "compare/tie_range.h"
#include "compare/tolerance.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {

// Everything a pixel's rules read, prepared once per stage.
struct ImageJudge {
  ImageJudge(const std::string& s, const Image& r, const Image& t, const ImageStageInputs& i, const JudgeContext& c)
      : stage(s), ref(r), test(t), in(i), ctx(c) {}
  const std::string& stage;
  const Image& ref;
  const Image& test;
  const ImageStageInputs& in;
  const JudgeContext& ctx;
  ImageModel model;
  int channels = 0;
  int slack_channel = -1;        // texture slack channel widening this stage's bound (-1: none)
  TieRangeChannels alternatives; // the stage's range channels (empty: no range rule)
  Rule range_rule = Rule::RasterAlternative;
  bool strict_ties = true;       // beyond-bound pixels at edges must be admissible neighbour values
  double mean_abs = 0.0;
  double depth_format = 0.0;     // 2q of a UNORM shadow depth format
  bool displayed = false;        // judged through the declared display transform
  double decoded_input = 0.0;    // image.final over a decoded display-encoded image.direct
  Image shown;                   // the reference through the display transform (when displayed)
  std::vector<uint8_t> edge;

  const Image& judged() const { return displayed ? shown : ref; }
  double linear_bound(int x, int y, int c) const;
  double pixel_bound(int x, int y, int c) const;
  bool within_range(int x, int y) const;
  bool admissible_neighbour(int x, int y) const;
};

bool same_size(const Image& a, const Image* b) { return b && a.width == b->width && a.height == b->height; }

// The rule a range image stands for: the G-buffer's raster alternatives, a shadow map's own range,
// or the shading stages' PCF taps on the test's own inputs (docs/compare.md, "Raster alternatives").
Rule range_rule_of(const std::string& stage, ToleranceModel model) {
  if (model == ToleranceModel::Shading) return Rule::PcfTapRange;
  return tie_range_stage(stage) != stage_names::kGbufferTieRange ? Rule::LightSpaceAlternative
                                                                 : Rule::RasterAlternative;
}

double ImageJudge::linear_bound(int x, int y, int c) const {
  double b = model.abs + model.rel * std::abs(double(ref.at(x, y, c))) + model.abs_of_mean * mean_abs + depth_format;
  if (model.slope_factor > 0) b += model.slope_factor * attribute_slope(ref, x, y, c);
  if (slack_channel >= 0) b += double(in.texture_slack->at(x, y, slack_channel));
  return b;
}

double ImageJudge::pixel_bound(int x, int y, int c) const {
  const double b = linear_bound(x, y, c);
  return displayed && c < 3 ? in.display->carry_bound(ref.at(x, y, c), b) + decoded_input + in.reference_quantisation : b;
}

// A value a correct GL shows here when an edge, a depth order, a facing, an alpha test or a PCF
// tap ties the other way: inside the range, widened by the pixel's bound plus its relative term on
// the range's larger magnitude. A display-encoded stage: between the ends carried through the
// (monotone) transform, plus the store's quantisation.
bool ImageJudge::within_range(int x, int y) const {
  if (alternatives.empty()) return false;
  const Image& range = *in.tie_range;
  for (int c = 0; c < channels; ++c) {
    const double lo = range.at(x, y, alternatives.lo[size_t(c)]), hi = range.at(x, y, alternatives.hi[size_t(c)]);
    const double b = linear_bound(x, y, c) +
                     model.rel * std::max(0.0, std::max(std::abs(lo), std::abs(hi)) - std::abs(double(ref.at(x, y, c))));
    const double t = test.at(x, y, c);
    if (displayed && c < 3) {
      const double q = in.display->quantisation_allowance() + in.reference_quantisation;
      if (!(t >= in.display->apply(lo - b) - q && t <= in.display->apply(hi + b) + q)) return false;
    } else if (!within_tie_range(range, alternatives, x, y, c, t, b)) {
      return false;
    }
  }
  return true;
}

// Every channel within [min, max] of the reference's 3x3 neighbourhood widened by the pixel's
// bound: a value the reference could have produced here (dEQP's verifiers accept any admissible
// neighbour; docs/compare.md, "Ties are admissible values").
bool ImageJudge::admissible_neighbour(int x, int y) const {
  const Image& r = judged();
  for (int c = 0; c < channels; ++c) {
    double lo = 1e300, hi = -1e300;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int u = x + dx, w = y + dy;
        if (u < 0 || w < 0 || u >= r.width || w >= r.height) continue;
        lo = std::min(lo, double(r.at(u, w, c)));
        hi = std::max(hi, double(r.at(u, w, c)));
      }
    const double t = test.at(x, y, c), b = pixel_bound(x, y, c);
    if (!(t >= lo - b && t <= hi + b)) return false;
  }
  return true;
}

// The bound in words: the model's, then each term this stage adds.
std::string bound_words(const ImageJudge& j) {
  std::string b = bound_text(j.model);
  if (j.slack_channel >= 0)
    b += " + the reference's texture slack (its value's range under a 2^-8 px sample shift and any admissible "
         "texture LOD)";
  if (j.range_rule == Rule::PcfTapRange && !j.alternatives.empty())
    b += "; ties: only PCF taps that the lookup's float arithmetic may flip on the test's own shadow maps, no edge or "
         "interior share";
  else if (!j.alternatives.empty())
    b += "; ties: only the reference's raster alternatives (" + tie_range_stage(j.stage) + "), no edge or interior share";
  if (j.depth_format > 0) b += " + 2q of the UNORM depth format (" + std::to_string(j.depth_format) + ")";
  if (j.displayed)
    b += "; carried through the declared display transform (" + to_string(j.in.display->op) + ", exposure " +
         std::to_string(j.in.display->exposure) + ", gamma " + std::to_string(j.in.display->gamma) + ", " +
         std::to_string(j.in.display->bits) + " bits): its change over [r - b, r + b] + one step";
  if (j.decoded_input > 0) b += " + one step for image.direct decoded from display";
  return b;
}

// The edge map (image_edges.h): depth images are their own hint; the reference's alpha-test ties
// (docs/compare.md, "Alpha-mask ties") are edges inside a triangle that the depth may not show, so
// camera-space stages (those with a depth hint) add them.
std::vector<uint8_t> edges_of(const ImageJudge& j) {
  const Image* hint = j.in.edge_hint;
  const int alpha_ch = j.in.texture_slack && hint ? alpha_tie_channel(*j.in.texture_slack) : -1;
  const bool alpha_ties = alpha_ch >= 0 && same_size(j.ref, j.in.texture_slack);
  if (!hint && j.model.id == ToleranceModel::Depth) hint = &j.ref;
  std::vector<uint8_t> edge = edge_map(j.ref, hint);
  if (alpha_ties)
    for (int y = 0; y < j.ref.height; ++y)
      for (int x = 0; x < j.ref.width; ++x)
        if (j.in.texture_slack->at(x, y, alpha_ch) > 0.0f) edge[size_t(y) * size_t(j.ref.width) + size_t(x)] = 1;
  return edge;
}

void prepare(ImageJudge& j) {
  j.model = image_model(j.stage);
  j.channels = std::min(j.ref.channels, j.test.channels);
  if (j.in.texture_slack && same_size(j.ref, j.in.texture_slack))
    j.slack_channel = texture_slack_channel(j.stage, *j.in.texture_slack);
  j.strict_ties = j.model.id != ToleranceModel::Shading;
  if (same_size(j.ref, j.in.tie_range)) j.alternatives = tie_range_channels(j.stage, *j.in.tie_range, j.channels);
  j.range_rule = range_rule_of(j.stage, j.model.id);
  for (float x : j.ref.data) j.mean_abs += double(std::abs(x));
  j.mean_abs /= double(std::max<size_t>(1, j.ref.data.size()));
  // A UNORM depth map: each side within a step q of its float depth (either neighbour, GL 4.5
  // section 2.3.5.2), so two maps within the float bound stay within it + 2q.
  j.depth_format = j.model.id == ToleranceModel::Depth ? 2.0 * j.ctx.depth_quantum : 0.0;
  j.displayed = j.in.display && j.in.display->declared();
  if (j.displayed) {
    j.shown = j.ref;
    for (int y = 0; y < j.ref.height; ++y)
      for (int x = 0; x < j.ref.width; ++x)
        for (int c = 0; c < std::min(j.ref.channels, 3); ++c)
          j.shown.at(x, y, c) = float(j.in.display->apply(j.ref.at(x, y, c)));
  }
  if (j.displayed && j.ctx.direct_decoded_from_display && j.stage == stage_names::kImageFinal)
    j.decoded_input = j.in.display->quantisation_allowance();
  j.edge = edges_of(j);
}

// The first rule that admits pixel (x, y) beyond its bound. Where the reference supplies a range
// it is the only rule (every G-buffer pixel beyond its bound on every scene at 64^2-256^2 was one).
// Shading stages skip the neighbour predicate: their inputs carry freedom their bound does not
// propagate, so a value outside the neighbourhood is no proof of a bug there yet.
Rule admit_beyond_bound(const ImageJudge& j, int x, int y) {
  if (j.within_range(x, y)) return j.range_rule;
  if (!j.alternatives.empty()) return Rule::Beyond;
  if (j.strict_ties && !j.admissible_neighbour(x, y)) return Rule::Beyond;
  if (j.edge[size_t(y) * size_t(j.ref.width) + size_t(x)]) return j.strict_ties ? Rule::EdgeNeighbour : Rule::EdgeShare;
  return Rule::InteriorShare;
}

Offender pixel_offender(const Image& ref, const Image& test, int x, int y, const WorstChannel& w) {
  Offender o;
  o.at = {x, y, -1};
  for (int c = 0; c < ref.channels; ++c) o.reference.push_back(ref.at(x, y, c));
  for (int c = 0; c < test.channels; ++c) o.test.push_back(test.at(x, y, c));
  o.error = w.error;
  o.bound = w.bound;
  return o;
}

// Every pixel: its rule, the statistics, the offenders.
// `opt.explain` names a pixel whose worst channel goes to `explained_worst`.
std::vector<Rule> admit_pixels(const ImageJudge& j, StageVerdict& v, std::vector<Offender>& offenders,
                               const CompareOptions& opt, WorstChannel& explained_worst) {
  std::vector<Rule> rules(size_t(j.ref.width) * size_t(j.ref.height), Rule::WithinBound);
  const Image& r = j.judged();
  double se = 0;
  for (int y = 0; y < j.ref.height; ++y)
    for (int x = 0; x < j.ref.width; ++x) {
      const WorstChannel w = worst_channel(j.channels, [&](int c) {
        const double d = std::abs(double(j.test.at(x, y, c)) - double(r.at(x, y, c)));
        se += d * d;
        v.max_abs = std::max(v.max_abs, std::isfinite(d) ? d : 1e30);
        return ChannelDistance{d, j.pixel_bound(x, y, c), d};
      });
      ++v.checked;
      if (explains(opt, x, y)) explained_worst = w;
      if (w.within()) continue;
      ++v.out_of_bound;
      rules[size_t(y) * size_t(j.ref.width) + size_t(x)] = admit_beyond_bound(j, x, y);
      offenders.push_back(pixel_offender(r, j.test, x, y, w));
    }
  v.rms = std::sqrt(se / double(std::max<size_t>(1, v.checked * size_t(std::max(j.channels, 1)))));
  return rules;
}

// The counting policy (compare/counted_shares.h): the edge and interior shares of the model, or,
// for a cone-traced stage judged end to end over voxel ties, the upstream share, which then also
// takes the pixels no value rule admitted. A share exceeded fails the stage; its pixels are then
// beyond (red), not admitted.
struct ShareOutcome {
  size_t edge_pixels = 0;
  double allowed_interior = 0.0, allowed_edge_pixels = 0.0;
  bool upstream = false;
  size_t edge = 0, interior = 0, ranged = 0;  // admitted per share (before an exceeded share fails them)
};

ShareOutcome apply_shares(const ImageJudge& j, std::vector<Rule>& rules) {
  ShareOutcome s;
  for (uint8_t e : j.edge) s.edge_pixels += e;
  const double n = double(std::max<size_t>(1, rules.size()));
  const bool ranged = !j.alternatives.empty();
  s.allowed_interior = ranged ? 0.0 : j.model.interior_fraction;
  s.allowed_edge_pixels = ranged ? 0.0 : j.model.edge_tie_fraction * double(s.edge_pixels);
  if (is_cone_traced(j.stage, j.ctx.soft_shadows) && j.ctx.upstream_tie_fraction > 0) {
    const double widened = std::min(kUpstreamShare.fraction, kUpstreamFactor * j.ctx.upstream_tie_fraction);
    s.allowed_interior = std::max(s.allowed_interior, widened);
    s.allowed_edge_pixels = std::max(s.allowed_edge_pixels, widened * n);
    s.upstream = true;
    for (Rule& r : rules)
      if (r == Rule::Beyond) r = Rule::UpstreamShare;
  }
  return s;
}

void decide(StageVerdict& v, std::vector<Rule>& rules, ShareOutcome& s) {
  RuleTally& t = v.admitted;
  for (Rule r : rules) t.add(r);
  s.interior = t[Rule::InteriorShare] + t[Rule::UpstreamShare];
  s.edge = t[Rule::EdgeNeighbour] + t[Rule::EdgeShare];
  s.ranged = t[Rule::RasterAlternative] + t[Rule::LightSpaceAlternative] + t[Rule::PcfTapRange];
  v.allowed = s.edge + s.interior + s.ranged;
  const double n = double(std::max<size_t>(1, v.checked));
  const bool interior_over = double(s.interior) / n > s.allowed_interior;
  const bool edge_over = double(s.edge) > s.allowed_edge_pixels;
  v.verdict = t[Rule::Beyond] > 0 || interior_over || edge_over ? Verdict::Fail
              : v.out_of_bound > 0                              ? Verdict::Warn
                                                                : Verdict::Pass;
  if (!interior_over && !edge_over) return;
  // A share exceeded: its pixels are failures, not admitted.
  for (Rule& r : rules) {
    const bool in_interior = r == Rule::InteriorShare || r == Rule::UpstreamShare;
    const bool in_edge = r == Rule::EdgeNeighbour || r == Rule::EdgeShare;
    if ((interior_over && in_interior) || (edge_over && in_edge)) r = Rule::Beyond;
  }
  t = RuleTally();
  for (Rule r : rules) t.add(r);
}

void write_note(const ImageJudge& j, StageVerdict& v, const ShareOutcome& s, size_t inadmissible) {
  const size_t edge_bad = s.edge, interior_bad = s.interior, ranged = s.ranged;
  const double n = double(std::max<size_t>(1, v.checked));
  const double fe = s.edge_pixels ? double(edge_bad) / double(s.edge_pixels) : 0.0, fi = double(interior_bad) / n;
  char buf[200];
  std::snprintf(buf, sizeof buf, "%zu of %zu pixels beyond the bound (%zu of %zu edge pixels = %.2f%%, %.3f%% interior)",
                v.out_of_bound, v.checked, edge_bad, s.edge_pixels, 100 * fe, 100 * fi);
  v.note = buf;
  if (ranged)
    v.note += "; " + std::to_string(ranged) +
              (j.range_rule == Rule::PcfTapRange ? " within the range of PCF taps that may flip (float lookup arithmetic)"
               : j.range_rule == Rule::LightSpaceAlternative
                   ? " at a depth the reference's raster alternatives allow (2^-8 texel snapping, alpha-test ties)"
                   : " showing a surface or facing the reference's raster alternatives allow (2^-8 px snapping)");
  if (inadmissible)
    v.note += "; " + std::to_string(inadmissible) +
              (j.range_rule == Rule::PcfTapRange && !j.alternatives.empty()
                   ? " outside the range of PCF taps that may flip (not a value a tie can give)"
               : !j.alternatives.empty() ? " not among the reference's raster alternatives (not a value a tie can give)"
                                         : " outside the reference's 3x3 range plus the bound (not a value a tie can give)");
  v.extra = {{"edge_pixels", s.edge_pixels},
             {"edge_fraction", fe},
             {"interior_fraction", fi},
             {"inadmissible", inadmissible},
             {"raster_alternatives", ranged},
             {"mean_abs_reference", j.mean_abs},
             {"allowed_edge_fraction", s.edge_pixels ? s.allowed_edge_pixels / double(s.edge_pixels) : 0.0},
             {"allowed_interior_fraction", s.allowed_interior}};
  if (j.displayed) v.extra["display_transform"] = to_json(*j.in.display);
  if (s.upstream && s.allowed_interior > j.model.interior_fraction && v.out_of_bound)
    v.note += "; allowance widened by upstream voxel ties";
}

}  // namespace

StageVerdict judge_image_stage(const std::string& stage, const Image& ref, const Image& test,
                               const ImageStageInputs& in, const CompareOptions& opt, const JudgeContext& ctx) {
  StageVerdict v;
  v.stage = stage;
  if (ref.width != test.width || ref.height != test.height) {
    v.verdict = Verdict::Fail;
    v.note = "size differs: reference " + std::to_string(ref.width) + "x" + std::to_string(ref.height) + ", test " +
             std::to_string(test.width) + "x" + std::to_string(test.height);
    return v;
  }
  ImageJudge j{stage, ref, test, in, ctx};
  prepare(j);
  v.model = j.model.name;
  v.bound = bound_words(j);
  std::vector<Offender> offenders;
  WorstChannel explained;
  std::vector<Rule> rules = admit_pixels(j, v, offenders, opt, explained);
  size_t inadmissible = 0;
  for (Rule r : rules) inadmissible += r == Rule::Beyond;
  ShareOutcome shares = apply_shares(j, rules);
  if (shares.upstream) inadmissible = 0;
  decide(v, rules, shares);
  write_note(j, v, shares, inadmissible);
  if (opt.explain.size() == 2 && opt.explain[0] >= 0 && opt.explain[1] >= 0 && opt.explain[0] < ref.width &&
      opt.explain[1] < ref.height) {
    const Offender o = pixel_offender(j.judged(), test, opt.explain[0], opt.explain[1], explained);
    record_explained(v, rules[size_t(opt.explain[1]) * size_t(ref.width) + size_t(opt.explain[0])], o.at, o.reference,
                     o.test, explained);
  }
  keep_worst(offenders, opt.worst_n);
  v.worst = std::move(offenders);
  write_image_rule_mask(opt, v, ref, rules);
  return v;
}

StageVerdict compare_image_stage(const std::string& stage, const Image& ref, const Image& test, const Image* edge_hint,
                                 const CompareOptions& opt, const Image* texture_slack,
                                 const DisplayTransform* display, const Image* tie_range) {
  return judge_image_stage(stage, ref, test, {edge_hint, texture_slack, display, tie_range}, opt, JudgeContext());
}

}  // namespace vct::cmp
