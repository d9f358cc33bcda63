// The display transform the compare tests declare for an engine's display-encoded images
// (compare/display_transform.h): Reinhard, gamma 2.2, 8-bit, on the given image stages.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "compare/display_transform.h"

namespace vct::cmp {

inline DisplayTransform reinhard_22_8(std::vector<std::string> stages = {"image.final"}) {
  DisplayTransform d;
  d.op = ToneOperator::Reinhard;
  d.gamma = 2.2;
  d.bits = 8;
  d.stages = std::move(stages);
  return d;
}

}  // namespace vct::cmp
