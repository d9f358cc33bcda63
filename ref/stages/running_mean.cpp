#include "stages/running_mean.h"

#include "stages/reduction.h"

namespace vct {

float running_mean_half_sequential(const std::vector<float>& values) {
  float s = 0.0f;
  for (size_t k = 0; k < values.size(); ++k)
    s = quantize_half((s * float(k) + values[k]) / float(k + 1));
  return s;
}

}  // namespace vct
