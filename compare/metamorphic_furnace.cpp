// The white furnace (docs/metamorphic.md): a closed sphere, Lambertian albedo rho, emission Le, no
// light. With one frame of light in the voxels every voxel holds albedo x 0 + Le, i.e. RGB = Le x
// opacity; the box filter and front-to-back compositing keep that identity (both are the same
// linear combination of RGB and of opacity), so every cone sample is premultiplied and a cone's
// result is Le x (its accumulated opacity) <= Le. Hence 0 <= indirect diffuse <= Le x W (W the sum
// of the cone weights) and Le <= final <= Le (1 + rho W). The analytic one-bounce value is
// Le (1 + rho) (every direction sees the shell); how far VCT falls short is its bias, reported.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/metamorphic.h"
#include "compare/metamorphic_bounds.h"
#include "compare/tolerance.h"
#include "core/error.h"
#include "scene/embedded_scenes.h"
#include "scene/gltf_loader.h"
#include "shared/voxel_fixed_point.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace st = stage_names;

namespace {

constexpr char kFurnaceFile[] = "furnace_sphere.gltf";

StageVerdict verdict_of(const std::string& stage, const std::string& bound, size_t checked,
                        std::vector<Offender> offenders, double max_abs) {
  StageVerdict v;
  v.stage = stage;
  v.model = "furnace";
  v.bound = bound;
  v.checked = checked;
  v.out_of_bound = offenders.size();
  v.max_abs = max_abs;
  keep_worst(offenders, 10);
  v.worst = std::move(offenders);
  v.verdict = v.out_of_bound ? Verdict::Fail : Verdict::Pass;
  return v;
}

// Every voxel of `vol` (level L of a premultiplied chain): |RGB - Le a| <= bound, 0 <= a <= 1.
StageVerdict premultiplied(const std::string& stage, const Volume& vol, double le, double bound) {
  std::vector<Offender> off;
  double worst = 0.0;
  for (int z = 0; z < vol.nz; ++z)
    for (int y = 0; y < vol.ny; ++y)
      for (int x = 0; x < vol.nx; ++x) {
        const vec4 v = vol.rgba(x, y, z);
        double d = 0.0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(double(v[c]) - le * double(v.w)));
        const double alpha_out = std::max(double(v.w) - 1.0, -double(v.w));
        worst = std::max(worst, d);
        if (d <= bound && alpha_out <= 0.0) continue;
        Offender o;
        o.at = {x, y, z};
        const float expected = float(le * double(v.w));
        o.reference = {expected, expected, expected, std::clamp(v.w, 0.0f, 1.0f)};
        o.test = {v.x, v.y, v.z, v.w};
        o.error = float(std::max(d, alpha_out));
        o.bound = float(bound);
        off.push_back(o);
      }
  char b[160];
  std::snprintf(b, sizeof b, "RGB = Le x opacity within %.3g, opacity in [0, 1]", bound);
  return verdict_of(stage, b, vol.voxel_count(), std::move(off), worst);
}

// Every covered pixel within [lo, hi] (+ bound) and grey (all inputs are grey).
StageVerdict within(const std::string& stage, const Image& img, const Image& coverage, double lo,
                    double hi, double bound, double& mean) {
  std::vector<Offender> off;
  double worst = 0.0, sum = 0.0;
  size_t n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (coverage.at(x, y, 0) <= 0.0f) continue;
      const vec3 v = img.rgb(x, y);
      const double r = double(v.x);
      ++n;
      sum += r;
      const double grey = double(std::max(std::abs(v.x - v.y), std::abs(v.x - v.z)));
      const double range = std::max({lo - r, r - hi, 0.0});
      const double d = std::max(grey, range);
      worst = std::max(worst, d);
      if (d <= bound) continue;
      Offender o;
      o.at = {x, y, -1};
      o.reference = {float(std::clamp(r, lo, hi))};
      o.test = {v.x, v.y, v.z};
      o.error = float(d);
      o.bound = float(bound);
      off.push_back(o);
    }
  mean = n ? sum / double(n) : 0.0;
  char b[160];
  std::snprintf(b, sizeof b, "grey and in [%.4g, %.4g] within %.3g on covered pixels", lo, hi,
                bound);
  StageVerdict v = verdict_of(stage, b, n, std::move(off), worst);
  std::snprintf(b, sizeof b, "mean %.4f over %zu covered pixels", mean, n);
  v.note = b;
  return v;
}

}  // namespace

RelationResult check_furnace(const MetamorphicContext& c) {
  const std::string& text = embedded_scene(kFurnaceFile);
  if (text.empty())
    throw InputError("builtin:furnace_sphere", "the furnace scene is missing from this build");
  const Scene scene = load_gltf_text(text, "builtin:furnace_sphere", "");
  Settings s = c.settings;
  s.vct.bounces = 1;  // the relation below is about one frame of light in the voxels
  const Material& m = scene.materials.at(0);
  const double le = m.emission().x, rho = m.base_color_factor.x;
  const StageSet set = stage_set_from_frame(c.render(scene, s), s.vct);
  const double w = diffuse_weight_sum(s.vct);
  RelationResult r;
  r.name = "furnace";
  // Level 0 stores the mean of equal values Le: one fixed-point quantum (round(Le 2^-14)) and one
  // storage rounding; every level rounds RGB and opacity once more (Le x one opacity rounding),
  // and compositing may double what came before.
  const double quantum =
      s.vct.reduction == Reduction::FixedPoint ? double(sh::FIXED_POINT_INV_SCALE) : 0.0;
  std::vector<double> level_bounds = {quantum + storage_rounding(s.vct, le)};
  for (int n = s.vct.grid / 2; n >= 1; n /= 2)
    level_bounds.push_back(level_bounds.back() * (s.vct.anisotropic ? 2.0 : 1.0) +
                           storage_rounding(s.vct, le) + le * storage_rounding(s.vct, 1.0));
  for (const std::string& stage : pipeline_order(set, set)) {
    if (!set.volumes.count(stage)) continue;
    const Volume& vol = set.volumes.at(stage);
    const auto ref = find_stage(stage);
    const bool chain =
        stage == st::kVoxelRadiance || (ref && ref->row->model == ToleranceModel::Mip);
    if (!chain || vol.channels < 4) continue;
    const int level = ref && ref->row->index == StageIndex::MipLevel ? ref->index : 0;
    r.stages.push_back(premultiplied(
        stage, vol, le, level_bounds[std::min<size_t>(size_t(level), level_bounds.size() - 1)]));
  }
  // A cone is Le x its opacity plus what each sample's rounding added: <= steps x the largest
  // level bound (transmittance <= 1).
  const double cone_bound =
      max_cone_steps(s.vct) * *std::max_element(level_bounds.begin(), level_bounds.end());
  const Image& cov = set.images.at(st::kGbufferCoverage);
  double mean_indirect = 0.0, mean_final = 0.0;
  if (set.images.count(st::kImageIndirectDiffuse))
    r.stages.push_back(within(st::kImageIndirectDiffuse, set.images.at(st::kImageIndirectDiffuse),
                              cov, 0.0, le * w, cone_bound, mean_indirect));
  if (set.images.count(st::kImageFinal))
    r.stages.push_back(within(st::kImageFinal, set.images.at(st::kImageFinal), cov, le,
                              le * (1.0 + rho * w), cone_bound * (1.0 + rho), mean_final));
  r.verdict = overall_of(r.stages);
  const double analytic = le * (1.0 + rho);
  char b[320];
  std::snprintf(b, sizeof b,
                "final %.4f vs analytic one-bounce Le(1+rho) = %.4f (%+.1f%%); indirect diffuse "
                "%.4f vs Le = %.4f "
                "(%+.1f%%): VCT's bias (docs/metamorphic.md, Furnace)",
                mean_final, analytic, 100.0 * (mean_final / analytic - 1.0), mean_indirect, le,
                100.0 * (mean_indirect / le - 1.0));
  r.note = b;
  r.extra = {{"le", le},
             {"albedo", rho},
             {"analytic_final", analytic},
             {"mean_final", mean_final},
             {"mean_indirect_diffuse", mean_indirect},
             {"final_bias", mean_final / analytic - 1.0},
             {"indirect_bias", mean_indirect / le - 1.0}};
  r.sets["furnace"] = set;
  return r;
}

}  // namespace vct::cmp
