// Per-stage times of repeated frames, and the stage groups in which the CPU reference and the GL
// build can be compared (the two cut stages slightly differently: e.g. GL's voxelize + resolve +
// mips against the CPU's voxelize + inject + mips). Used by `vct bench` and bench/gl_bench.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace vct {

using StageTimes = std::map<std::string, double>;  // stage name -> milliseconds

/// Median over runs of each stage's time (a stage missing from some runs: median of the others).
StageTimes median_times(const std::vector<StageTimes>& runs);

struct StageGroup {
  std::string name;
  std::vector<std::string> gl, ref;  // stage names summed on each side
};

/// shadow maps, g-buffer, voxelize+inject+mips, direct, indirect+composite, particles, total.
const std::vector<StageGroup>& stage_groups();

/// Sum of the listed stages' times (absent stages count 0).
double sum_stages(const StageTimes& t, const std::vector<std::string>& names);

}  // namespace vct
