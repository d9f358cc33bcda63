#include "freedoms/reduction_interval.h"

#include <algorithm>
#include <cmath>

#include "stages/reduction.h"

namespace vct {

namespace {

// Spacing of binary16 values at |v| (2^-24 below the normal range).
float half_ulp(float v) {
  const float a = std::abs(v);
  if (a < std::ldexp(1.0f, -14)) return std::ldexp(1.0f, -24);
  int e = 0;
  std::frexp(a, &e);  // a = f * 2^e, f in [0.5, 1)
  return std::ldexp(1.0f, e - 1 - 10);
}

}  // namespace

ValueInterval running_mean_interval(const std::vector<float>& values) {
  if (values.empty()) return {};
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  const float lo = quantize_half(*mn), hi = quantize_half(*mx);
  return {lo - 2.0f * half_ulp(lo), hi + 2.0f * half_ulp(hi)};
}

namespace {
// Per voxel and RGB channel, `interval` of the voxel's fragment values; alpha 1 where occupied.
// Runs of fragments per voxel (sorted by voxel), each reduced on its own: any thread count gives
// the same volumes (sequential here; the cost is one pass over the fragments).
template <class Interval>
void interval_volumes(const Voxelization& vox, const std::vector<vec3>& values, Interval interval, Volume& lo,
                      Volume& hi) {
  lo = Volume(vox.n, vox.n, vox.n, 4);
  hi = Volume(vox.n, vox.n, vox.n, 4);
  lo.channel_names = hi.channel_names = {"R", "G", "B", "A"};
  size_t b = 0;
  std::vector<float> ch;
  while (b < vox.fragments.size()) {
    size_t e = b;
    while (e < vox.fragments.size() && vox.fragments[e].voxel == vox.fragments[b].voxel) ++e;
    const ivec3 c = vox.fragments[b].voxel;
    vec4 l(0.0f, 0.0f, 0.0f, 1.0f), h(0.0f, 0.0f, 0.0f, 1.0f);
    for (int k = 0; k < 3; ++k) {
      ch.clear();
      for (size_t i = b; i < e; ++i) ch.push_back(values[i][k]);
      const auto iv = interval(ch);
      l[k] = iv.lo;
      h[k] = iv.hi;
    }
    lo.set_rgba(c.x, c.y, c.z, l);
    hi.set_rgba(c.x, c.y, c.z, h);
    b = e;
  }
}
}  // namespace

void running_mean_interval_volumes(const Voxelization& vox, const std::vector<vec3>& values, Volume& lo,
                                   Volume& hi) {
  interval_volumes(vox, values, running_mean_interval, lo, hi);
}

void cas_interval_volumes(const Voxelization& vox, const std::vector<vec3>& values, Volume& lo, Volume& hi) {
  interval_volumes(vox, values, cas_interval, lo, hi);
}

void add_reduction_interval(const Voxelization& vox, const std::vector<vec3>& values, const VctSettings& settings,
                            VoxelGrid& g) {
  if (settings.reduction == Reduction::CasRgba8) cas_interval_volumes(vox, values, g.cas_lo, g.cas_hi);
  if (settings.reduction == Reduction::RunningMeanHalf) running_mean_interval_volumes(vox, values, g.cas_lo, g.cas_hi);
}

void add_light_to_interval(const std::vector<AddedLight>& additions, Volume& lo, Volume& hi) {
  for (const AddedLight& a : additions) {
    const auto& [v, add] = a;
    if (!lo.contains(v.x, v.y, v.z)) continue;
    float* l = lo.voxel(v.x, v.y, v.z);
    float* h = hi.voxel(v.x, v.y, v.z);
    for (int c = 0; c < 3; ++c) {
      const float nl = l[c] + add[c], nh = h[c] + add[c];
      l[c] = nl - half_ulp(nl);
      h[c] = nh + half_ulp(nh);
    }
  }
}

}  // namespace vct
