// Mip levels (compare/volume_judges.h): the base model's bound propagated level by level, the
// reference's slack carried up the chain, upstream ties inherited (docs/compare.md).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "compare/mip_rounding.h"
#include "compare/tolerance.h"
#include "compare/volume_judges.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {
namespace st = stage_names;

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

}  // namespace

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
  // Opacity is a coverage fraction: outside [0, 1] is wrong, unless the reference is outside it
  // at that voxel too -- then the reference is an engine's own dump (two runs of one engine,
  // issue 39) and the value bound above judges the pair like any other value.
  const Volume& t = ts.volumes.at(stage);
  const Volume& r = rs.volumes.at(stage);
  const auto out_of_range = [](float a) { return a > 1.0f + 1e-3f || a < -1e-3f; };
  size_t bad_alpha = 0;
  if (t.channels >= 4)
    for (size_t i = 0; i < t.voxel_count(); ++i) {
      const bool shared = r.channels >= 4 && i < r.voxel_count() && out_of_range(r.data[i * size_t(r.channels) + 3]);
      if (out_of_range(t.data[i * size_t(t.channels) + 3]) && !shared) ++bad_alpha;
    }
  if (bad_alpha) {
    v.verdict = Verdict::Fail;
    v.note += "; " + std::to_string(bad_alpha) + " voxels with opacity outside [0,1] (alpha not clamped?)";
  }
  v.extra["alpha_out_of_range"] = bad_alpha;
  v.extra["level"] = level;
  // A deviation both sides declare alike is the same engine's: nothing for the scale to explain.
  if (ts.conventions.mip_scale != 1.0 && rs.conventions.mip_scale != ts.conventions.mip_scale) explain_by_declared_mip_scale(v, rs.volumes.at(stage), t, level, b, ts.conventions.mip_scale, opt, lt, slack);
  judge_mip_step_rounding(v, *ref.row, level, ts);
  return v;
}

}  // namespace vct::cmp
