// Linearity (docs/metamorphic.md): doubling every source of light doubles every radiance stage and
// leaves every other stage unchanged. Scaling by 2 commutes with IEEE rounding (fl(2a op 2b) =
// 2 fl(a op b) for + - * /, below overflow), so the float pipeline doubles exactly; what does not
// commute is rounding to a grid that is not a power of two apart (RGBA8's 1/255) and rounding of
// values that already differ (the fixed-point reduction, then half storage). The bounds below
// carry those through the mip levels and the cone steps.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/metamorphic.h"
#include "compare/metamorphic_bounds.h"
#include "compare/tolerance.h"
#include "scene/scene_transform.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace st = stage_names;

namespace {

constexpr double kScale = 2.0;

// Leading channels that carry radiance (scaled); the rest (opacity, counts, depth) must not move.
int radiance_channels(const std::string& stage) {
  if (stage == st::kGbufferEmission) return 3;
  const auto ref = find_stage(stage);
  if (!ref) return 0;
  switch (ref->row->model) {
    case ToleranceModel::Shading:
    case ToleranceModel::Filtered:
    case ToleranceModel::VoxelRadiance:
    case ToleranceModel::Mip:
      return 3;
    default:
      return 0;
  }
}

struct Bounds {
  std::vector<LinearBound> level;  // per mip level (0 = the base voxels at 8 fragments)
  LinearBound cone;                // one cone's result
  bool saturated = false;          // RGBA8 clipped a doubled voxel: downstream is not linear
};

double max_radiance(const Volume& v) {
  double m = 0.0;
  for (size_t i = 0; i < v.voxel_count(); ++i)
    for (int c = 0; c < std::min(3, v.channels); ++c)
      m = std::max(m, double(v.data[i * size_t(v.channels) + c]));
  return m;
}

LinearBound cone_of(const std::vector<LinearBound>& levels, const VctSettings& s) {
  LinearBound c;
  for (const LinearBound& l : levels)
    c.abs = std::max(c.abs, l.abs), c.rel = std::max(c.rel, l.rel);
  c.abs *= max_cone_steps(s);
  return c;
}

std::vector<LinearBound> chain(const LinearBound& l0, const VctSettings& s) {
  std::vector<LinearBound> levels = {l0};
  for (int n = s.grid / 2; n >= 1; n /= 2) levels.push_back(next_level_bound(s, levels.back()));
  return levels;
}

// Particles the frame adds into its voxels.
int particle_count(const Scene& scene, const VctSettings& s) {
  int n = 0;
  if (s.particles)
    for (const ParticleEmitter& e : scene.emitters) n += e.count;
  return n;
}

Bounds linearity_bounds(const StageSet& base, const VctSettings& s, int particles) {
  Bounds b;
  const Volume* vox =
      base.volumes.count(st::kVoxelRadiance) ? &base.volumes.at(st::kVoxelRadiance) : nullptr;
  b.saturated = s.storage == VoxelStorage::Rgba8 && vox && kScale * max_radiance(*vox) > 1.0;
  const LinearBound own = doubled_voxel_bound(s, 8.0, particles);
  LinearBound l0 = own;
  // Multibounce re-injects cone-traced light (restitution x albedo <= 1 per frame, W cones).
  for (int k = 1; k < s.bounces; ++k) {
    const LinearBound cone = cone_of(chain(l0, s), s);
    l0 = {own.abs + diffuse_weight_sum(s) * cone.abs, own.rel + cone.rel};
  }
  b.level = chain(l0, s);
  b.cone = cone_of(b.level, s);
  return b;
}

LinearBound image_bound(const std::string& stage, const Bounds& b, const VctSettings& s) {
  const double w = diffuse_weight_sum(s);
  if (stage == st::kImageIndirectDiffuse || stage == st::kImageDiffuseTerm)
    return {b.cone.abs * w, b.cone.rel};
  if (stage == st::kImageIndirectSpecular || stage == st::kImageSpecularTerm) return b.cone;
  // final = direct + diffuse term + specular term + emission (+ particles), all non-negative.
  if (stage == st::kImageFinal) return {b.cone.abs * (w + 1.0), b.cone.rel};
  return {};  // direct, emission, particles: float products and sums of the doubled inputs
}

struct Elements {
  const std::vector<float>& base;
  const std::vector<float>& test;
  int channels;
  int nx, ny;
  bool volume;
};

// |test - 2 base| on the radiance channels, |test - base| on the rest, against `bound(i, c, e)`.
template <class BoundFn>
StageVerdict compare_scaled(const std::string& stage, const Elements& e, int scaled,
                            bool clip_at_one, BoundFn bound) {
  StageVerdict v;
  v.stage = stage;
  v.model = "linearity";
  std::vector<Offender> offenders;
  size_t identical = 0;
  double se = 0.0, worst_bound = 0.0;
  const size_t n = e.base.size() / size_t(std::max(e.channels, 1));
  for (size_t i = 0; i < n; ++i) {
    float worst = 0.0f, at_bound = 0.0f;
    bool out = false;
    for (int c = 0; c < e.channels; ++c) {
      const size_t k = i * size_t(e.channels) + size_t(c);
      double expected = c < scaled ? double(e.base[k]) * kScale : double(e.base[k]);
      if (clip_at_one && c < scaled) expected = std::min(expected, 1.0);
      const double d = std::abs(double(e.test[k]) - expected), bnd = bound(i, c, expected);
      identical += d == 0.0;
      se += d * d;
      v.max_abs = std::max(v.max_abs, d);
      worst_bound = std::max(worst_bound, bnd);
      if (d > bnd && float(d) >= worst) out = true, worst = float(d), at_bound = float(bnd);
    }
    if (!out) continue;
    ++v.out_of_bound;
    Offender o;
    const int x = int(i % size_t(e.nx)), y = int((i / size_t(e.nx)) % size_t(e.ny));
    o.at = {x, y, e.volume ? int(i / (size_t(e.nx) * size_t(e.ny))) : -1};
    for (int c = 0; c < e.channels; ++c) {
      const size_t k = i * size_t(e.channels) + size_t(c);
      o.reference.push_back(c < scaled ? float(double(e.base[k]) * kScale) : e.base[k]);
      o.test.push_back(e.test[k]);
    }
    o.error = worst;
    o.bound = at_bound;
    offenders.push_back(o);
  }
  v.checked = n;
  v.rms = n ? std::sqrt(se / double(n * size_t(std::max(e.channels, 1)))) : 0.0;
  keep_worst(offenders, 10);
  v.worst = std::move(offenders);
  v.verdict = v.out_of_bound ? Verdict::Fail : Verdict::Pass;
  char b[200];
  std::snprintf(b, sizeof b, "|test - %s| <= %.3g (radiance channels x2, others x1)",
                scaled ? "2 base" : "base", worst_bound);
  v.bound = b;
  std::snprintf(b, sizeof b,
                "%zu of %zu values bit-identical to the expected ones; max |diff| %.3g", identical,
                n * size_t(std::max(e.channels, 1)), v.max_abs);
  v.note = b;
  v.extra = {{"identical_values", identical}, {"bound", worst_bound}};
  return v;
}

}  // namespace

RelationResult check_linearity(const MetamorphicContext& c) {
  const VctSettings& s = c.settings.vct;
  const StageSet test =
      stage_set_from_frame(c.render(light_scaled(c.scene, float(kScale)), c.settings), s);
  const int particles = particle_count(c.scene, s);
  const Bounds bounds = linearity_bounds(c.base, s, particles);
  const Volume* frags =
      c.base.volumes.count(st::kVoxelFragments) ? &c.base.volumes.at(st::kVoxelFragments) : nullptr;
  RelationResult r;
  r.name = "linearity";
  for (const std::string& stage : pipeline_order(c.base, test)) {
    const auto ref = find_stage(stage);
    if (!c.base.has(stage) || !test.has(stage) ||
        (ref && ref->row->role == StageRole::Auxiliary && stage != st::kVoxelFragments))
      continue;  // the CAS interval and texture slack are the reference's judging aids
    const int scaled = radiance_channels(stage);
    const bool clip = scaled && s.storage == VoxelStorage::Rgba8 && c.base.volumes.count(stage);
    if (c.base.images.count(stage)) {
      const Image &b = c.base.images.at(stage), &t = test.images.at(stage);
      if (b.data.size() != t.data.size()) continue;
      const bool cone = is_cone_traced(stage, s.soft_shadows);
      if (cone && bounds.saturated) {
        r.stages.push_back(
            missing_stage(stage, "RGBA8 voxels saturated when doubled: not linear downstream"));
        continue;
      }
      const LinearBound bnd = image_bound(stage, bounds, s);
      r.stages.push_back(compare_scaled(
          stage, {b.data, t.data, b.channels, b.width, b.height, false}, scaled, false,
          [bnd](size_t, int ch, double e) { return ch < 3 ? bnd.at(e) : 0.0; }));
    } else {
      const Volume &b = c.base.volumes.at(stage), &t = test.volumes.at(stage);
      if (b.data.size() != t.data.size()) continue;
      const int level = ref && ref->row->index == StageIndex::MipLevel ? ref->index : 0;
      const LinearBound lb = bounds.level[std::min<size_t>(size_t(level), bounds.level.size() - 1)];
      auto bound = [&, level, lb, scaled](size_t i, int ch, double expected) {
        if (ch >= scaled) return 0.0;
        if (level > 0 || stage != st::kVoxelRadiance || s.bounces > 1) return lb.at(expected);
        const double n =
            frags && frags->voxel_count() == b.voxel_count() ? double(frags->data[i]) : 8.0;
        return doubled_voxel_bound(s, std::max(n, 1.0), particles).at(expected);
      };
      r.stages.push_back(compare_scaled(stage, {b.data, t.data, b.channels, b.nx, b.ny, true},
                                        scaled, clip, bound));
    }
  }
  r.verdict = overall_of(r.stages);
  size_t exact = 0, compared = 0;
  double worst = 0.0;
  for (const StageVerdict& v : r.stages) {
    if (v.verdict == Verdict::Missing) continue;
    ++compared;
    exact += v.max_abs == 0.0;
    worst = std::max(worst, v.max_abs);
  }
  char b[200];
  std::snprintf(b, sizeof b,
                "%zu stages compared, %zu exactly doubled; largest |test - 2 base| %.3g", compared,
                exact, worst);
  r.note = b;
  r.extra = {{"cone_bound_abs", bounds.cone.abs},
             {"cone_bound_rel", bounds.cone.rel},
             {"max_cone_steps", max_cone_steps(s)}};
  r.sets["base"] = c.base;
  r.sets["doubled"] = test;
  return r;
}

}  // namespace vct::cmp
