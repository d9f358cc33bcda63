#include "stages/march_schedule.h"

namespace vct {

MarchSchedule::MarchSchedule(float aperture, const MarchParams& params, float voxel)
    : aperture_(aperture),
      start_offset_(params.start_offset),
      quality_(params.quality),
      min_lod_(params.min_lod),
      voxel_(voxel) {
  // As the march forms them (cone_trace.cpp): the same tan, the same recurrence, the same sums.
  const float tan_half = std::tan(0.5f * aperture);
  for (float t = params.start_offset; t < params.max_distance && steps_.size() < kMaxSteps;) {
    steps_.push_back(march_step(t, tan_half, voxel, params));
    t += steps_.back().step;
  }
}

}  // namespace vct
