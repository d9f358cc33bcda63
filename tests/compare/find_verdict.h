// The verdict of one stage in a report, for tests (throws when the report has no such stage, so
// a renamed stage fails the test instead of reading garbage).
#pragma once

#include <stdexcept>
#include <string>

#include "compare/verdict.h"

namespace vct::cmp::test {

inline const StageVerdict& find(const Report& r, const std::string& stage) {
  for (const auto& s : r.stages)
    if (s.stage == stage) return s;
  throw std::runtime_error("no stage " + stage);
}

}  // namespace vct::cmp::test
