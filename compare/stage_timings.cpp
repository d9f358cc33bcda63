#include "stage_timings.h"

#include <algorithm>

#include "freedoms/reference_freedoms.h"  // freedom_steps

namespace vct {

StageTimes median_times(const std::vector<StageTimes>& runs) {
  std::map<std::string, std::vector<double>> all;
  for (const auto& r : runs)
    for (const auto& [k, v] : r) all[k].push_back(v);
  StageTimes out;
  for (auto& [k, v] : all) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    out[k] = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
  return out;
}

namespace {
std::vector<std::string> freedom_timings() {
  std::vector<std::string> names;
  for (const FreedomStep& step : freedom_steps()) names.emplace_back(step.timing);
  return names;
}
}  // namespace

const std::vector<StageGroup>& stage_groups() {
  static const std::vector<StageGroup> g = {
      {"shadow maps", {"shadow_maps"}, {"shadow_maps"}},
      {"g-buffer", {"depth_prepass", "gbuffer"}, {"gbuffer"}},
      // The CPU's "voxelize" is the conservative voxelizer (always run, for the holes map).
      {"voxelize+inject+mips",
       {"voxelize", "resolve", "voxel_fill", "mips", "particles_voxels"},
       {"voxelize", "voxelize_gpu_rule", "inject", "bounce_inject", "mips", "particles_voxels",
        "inject_mips_multibounce"}},
      {"direct", {"direct"}, {"direct", "direct_soft_shadows"}},
      {"indirect+composite", {"indirect_cones"}, {"indirect_cones", "composite"}},
      {"particles", {"particles"}, {"particles"}},
      // The reference's own work for the judge (freedoms/reference_freedoms.h): GL does none of it.
      {"oracle extras (ref only)", {}, freedom_timings()},
      {"total, VCT work", {"total"}, {"total_vct"}},
      {"total", {"total"}, {"total"}},
  };
  return g;
}

double sum_stages(const StageTimes& t, const std::vector<std::string>& names) {
  double s = 0.0;
  for (const auto& k : names) {
    const auto it = t.find(k);
    if (it != t.end()) s += it->second;
  }
  return s;
}

}  // namespace vct
