#include "freedoms/coverage_ties.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "freedoms/fragment_slack.h"
#include "freedoms/voxel_alpha_ties.h"
#include "stages/raster.h"
#include "stages/reduction.h"

namespace vct {

namespace {

// Fragments are sorted by (voxel linear index, triangle) (stages/voxelize.h): the key orders them
// totally.
int64_t key_voxel(const Voxelization& v, const VoxelFragment& f) { return voxel_linear_index(v.n, f.voxel); }
bool key_less(const Voxelization& v, const VoxelFragment& a, const VoxelFragment& b) {
  return fragment_before(v.n, a, b);
}
bool same_key(const VoxelFragment& a, const VoxelFragment& b) {
  return a.voxel == b.voxel && a.triangle == b.triangle;
}

// Walks two sorted fragment lists together: marks fragments of `vox` missing from `shifted`, and
// collects those of `shifted` missing from `vox`.
void merge_shifted(const Voxelization& vox, const Voxelization& shifted, std::vector<uint8_t>& may_drop,
                   std::vector<VoxelFragment>& may_add) {
  size_t i = 0, j = 0;
  const auto& a = vox.fragments;
  const auto& b = shifted.fragments;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && key_less(vox, a[i], b[j]))) {
      may_drop[i++] = 1;
    } else if (i == a.size() || key_less(vox, b[j], a[i])) {
      may_add.push_back(b[j++]);
    } else {
      ++i, ++j;
    }
  }
}

// Per voxel, where the fragments of `vox` and of `extra` (both sorted) start.
struct VoxelRuns {
  size_t begin = 0, end = 0, extra_begin = 0, extra_end = 0;
};

// Calls visit(runs) for every voxel that has an uncertain fragment of `vox` or an extra one,
// including voxels only extra fragments reach (begin == end there).
void for_each_uncertain_voxel(const Voxelization& vox, const std::function<void(const VoxelRuns&)>& visit) {
  const auto& f = vox.fragments;
  const auto& x = vox.may_add;
  size_t b = 0, xb = 0;
  while (b < f.size() || xb < x.size()) {
    const int64_t key = b == f.size()    ? key_voxel(vox, x[xb])
                        : xb == x.size() ? key_voxel(vox, f[b])
                                         : std::min(key_voxel(vox, f[b]), key_voxel(vox, x[xb]));
    size_t e = b;
    bool uncertain = false;
    while (e < f.size() && key_voxel(vox, f[e]) == key) uncertain |= vox.may_drop[e++] != 0;
    size_t xe = xb;
    while (xe < x.size() && key_voxel(vox, x[xe]) == key) ++xe;
    if (uncertain || xe > xb) visit({b, e, xb, xe});
    b = e;
    xb = xe;
  }
}

// The largest mean of `certain` plus a subset of `uncertain` (the whole set never empty): the
// subset with the largest mean of any given size is the largest values, and the best size is
// found by trying every prefix of the sorted values.
double largest_mean(const std::vector<double>& certain, std::vector<double> uncertain) {
  std::sort(uncertain.begin(), uncertain.end(), std::greater<>());
  double sum = 0.0;
  for (double c : certain) sum += c;
  double n = double(certain.size());
  double best = certain.empty() ? -std::numeric_limits<double>::infinity() : sum / n;
  for (double u : uncertain) {
    sum += u, n += 1.0;
    best = std::max(best, sum / n);
  }
  return best;
}

std::vector<double> negated(std::vector<double> v) {
  for (double& x : v) x = -x;
  return v;
}

// The voxels across a depth boundary that fragment f may be written to instead (within its
// margin of the boundary), appended to `out`; true when there is one.
bool depth_tie_neighbours(const Scene& scene, int n, const VoxelFragment& f, std::vector<VoxelFragment>& out) {
  const VoxelDepthTie tie = voxel_depth_tie(scene, n, f);
  const int index = f.voxel[tie.axis];
  // A sliver's depth has no bound (its snapped plane may tilt without limit): any layer of its
  // column (medium seed 2: a sliver 0.8 px wide across four layers, written two layers over).
  const int lo = std::isinf(tie.margin) ? 0 : std::max(0, int(std::floor(tie.depth - tie.margin)));
  const int hi = std::isinf(tie.margin) ? n - 1 : std::min(n - 1, int(std::floor(tie.depth + tie.margin)));
  bool any = false;
  for (int layer = lo; layer <= hi; ++layer) {
    if (layer == index) continue;
    VoxelFragment moved = f;
    moved.voxel[tie.axis] = layer;
    out.push_back(moved);
    any = true;
  }
  return any;
}

// A fragment whose depth lies within its margin of a voxel boundary may be written to the voxel
// on the other side: it may be dropped here and added there. So may a fragment a snap may add
// (medium seed 2: a fragment only the Possible world covers, written one layer over).
void add_depth_ties(const Scene& scene, Voxelization& vox, std::vector<VoxelFragment>& added) {
  for (size_t i = 0; i < vox.fragments.size(); ++i)
    if (depth_tie_neighbours(scene, vox.n, vox.fragments[i], added)) vox.may_drop[i] = 1;
  const size_t snapped = added.size();
  for (size_t k = 0; k < snapped; ++k) {
    const VoxelFragment f = added[k];  // a copy: the vector grows
    depth_tie_neighbours(scene, vox.n, f, added);
  }
}

// vox.may_add = `added` sorted, one per key: a fragment found by several shifts is the same
// fragment (evaluated at its pixel centre, or its closest point, whichever samples covered it).
void keep_unique(Voxelization& vox, std::vector<VoxelFragment>& added) {
  std::sort(added.begin(), added.end(), [&](const VoxelFragment& a, const VoxelFragment& b) { return key_less(vox, a, b); });
  for (const VoxelFragment& f : added)
    if (vox.may_add.empty() || !same_key(vox.may_add.back(), f)) vox.may_add.push_back(f);
}

}  // namespace

MeanRange admissible_mean_range(const std::vector<double>& certain_lo, const std::vector<double>& certain_hi,
                                std::vector<double> uncertain_lo, std::vector<double> uncertain_hi) {
  MeanRange r;
  r.hi = largest_mean(certain_hi, std::move(uncertain_hi));
  r.lo = -largest_mean(negated(certain_lo), negated(std::move(uncertain_lo)));
  return r;
}

void add_coverage_ties(const Scene& scene, Voxelization& vox) {
  vox.may_drop.assign(vox.fragments.size(), 0);
  vox.may_add.clear();
  std::vector<VoxelFragment> added;
  if (vox.samples.empty()) {
    // The conservative voxelizer: GL's conservative modes decide the same boxes with their own
    // arithmetic (kConservativeArithmetic): a triangle meeting a box only that close to its
    // faces may go either way. Grown boxes only add fragments, shrunk ones only drop them.
    merge_shifted(vox, voxelize_conservative(scene, vox.n, kConservativeArithmetic), vox.may_drop, added);
    merge_shifted(vox, voxelize_conservative(scene, vox.n, -kConservativeArithmetic), vox.may_drop, added);
    keep_unique(vox, added);
    return;
  }
  // Each vertex snaps on its own (one step per axis at most): what every snap covers keeps its
  // fragments, what some snap covers may add one (stages/voxelize.h SnapWorld). The four common
  // shifts of the sample pattern are among those snaps, but they missed seed 2429: a fragment whose
  // only covered sample lies on its triangle's top edge (e = 0), kept by every common shift, which
  // llvmpipe did not write. Per vertex, an edge also turns (extrapolated samples beyond its ends).
  for (const SnapWorld world : {SnapWorld::Certain, SnapWorld::Possible})
    merge_shifted(vox, voxelize_gpu_rule(scene, vox.n, vox.samples, AlphaTest::Apply, world), vox.may_drop, added);
  add_voxel_alpha_ties(scene, vox, vox.may_drop, added);
  add_depth_ties(scene, vox, added);  // every fragment kept or added may also change layer
  keep_unique(vox, added);
}

Volume occupancy_ties(const Voxelization& vox) {
  Volume ties(vox.n, vox.n, vox.n, 1);
  ties.channel_names = {"tie"};
  if (vox.may_drop.size() != vox.fragments.size()) return ties;  // add_coverage_ties not run
  // Fragments are sorted by voxel: a voxel may be left empty when each of its fragments may drop.
  for (size_t b = 0, e = 0; b < vox.fragments.size(); b = e) {
    bool all_drop = true;
    for (e = b; e < vox.fragments.size() && vox.fragments[e].voxel == vox.fragments[b].voxel; ++e)
      all_drop = all_drop && vox.may_drop[e];
    const ivec3 v = vox.fragments[b].voxel;
    if (all_drop) *ties.voxel(v.x, v.y, v.z) = 1.0f;
  }
  for (const VoxelFragment& f : vox.may_add)
    if (*vox.occupancy.voxel(f.voxel.x, f.voxel.y, f.voxel.z) == 0.0f) *ties.voxel(f.voxel.x, f.voxel.y, f.voxel.z) = 1.0f;
  return ties;
}

Volume fragment_count_ranges(const Voxelization& vox) {
  if (vox.may_drop.size() != vox.fragments.size()) return {};  // add_coverage_ties not run
  Volume range(vox.n, vox.n, vox.n, 2);
  range.channel_names = {"lo", "hi"};
  for (size_t i = 0; i < vox.fragments.size(); ++i) {
    const ivec3 v = vox.fragments[i].voxel;
    float* r = range.voxel(v.x, v.y, v.z);
    r[0] += vox.may_drop[i] ? 0.0f : 1.0f;
    r[1] += 1.0f;
  }
  for (const VoxelFragment& f : vox.may_add) range.voxel(f.voxel.x, f.voxel.y, f.voxel.z)[1] += 1.0f;
  return range;
}

void widen_for_coverage_ties(const Scene& scene, const Voxelization& vox, const std::vector<vec3>& values,
                             const std::vector<float>& fragment_slack, const std::vector<ShadowMap>& maps,
                             const VctSettings& settings, const BounceLight* bounce, Volume& slack,
                             Volume& exact) {
  if (vox.may_drop.size() != vox.fragments.size()) return;  // add_coverage_ties not run
  Voxelization extra;
  extra.n = vox.n;
  extra.fragments = vox.may_add;
  const std::vector<vec3> extra_values = fragment_radiance(scene, extra, maps, settings, bounce);
  const std::vector<float> extra_slack = fragment_shading_slack(scene, extra, maps, settings, bounce);
  // Each fragment enters the reduction as reduction_input (clamped by the fixed-point and CAS
  // schemes), and so does each end of its interval (the clamp is monotone): the mean of the raw
  // values is not the reference's stored value where a fragment's light is negative (large hunt
  // seed 25: an extrapolated vertex colour, green -0.70, stored as 0).
  const auto input = [&](double v) { return double(reduction_input(float(v), settings.reduction)); };
  for_each_uncertain_voxel(vox, [&](const VoxelRuns& r) {
    double widest = 0.0;
    for (int c = 0; c < 3; ++c) {
      std::vector<double> clo, chi, ulo, uhi;
      double mean = 0.0;  // a voxel only extra fragments reach holds no light in the reference
      for (size_t k = r.begin; k < r.end; ++k) {
        const double v = double(values[k][c]), s = double(fragment_slack[k]);
        mean += input(v);
        (vox.may_drop[k] ? ulo : clo).push_back(input(v - s));
        (vox.may_drop[k] ? uhi : chi).push_back(input(v + s));
      }
      if (r.end > r.begin) mean /= double(r.end - r.begin);
      for (size_t k = r.extra_begin; k < r.extra_end; ++k) {
        ulo.push_back(input(double(extra_values[k][c]) - double(extra_slack[k])));
        uhi.push_back(input(double(extra_values[k][c]) + double(extra_slack[k])));
      }
      const MeanRange m = admissible_mean_range(clo, chi, std::move(ulo), std::move(uhi));
      widest = std::max({widest, m.hi - mean, mean - m.lo});
      // Every fragment may land in a neighbour: GL may write none here, and a voxel the fills
      // still occupy keeps RGB 0 (stages/voxel_fill.h; seed 290's thickened voxel).
      if (clo.empty()) widest = std::max(widest, std::abs(mean));
    }
    const ivec3 v = r.end > r.begin ? vox.fragments[r.begin].voxel : vox.may_add[r.extra_begin].voxel;
    float& s = *slack.voxel(v.x, v.y, v.z);
    s = std::max(s, std::nextafter(float(widest), std::numeric_limits<float>::infinity()));  // rounded up
    if (exact.voxel_count() > 0) *exact.voxel(v.x, v.y, v.z) = 0.0f;
  });
}

}  // namespace vct
