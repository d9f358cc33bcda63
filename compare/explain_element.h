// One element's admission, explained (vct compare --explain X,Y[,Z]; Python compare(explain=...)):
// the rule that admitted it, both values and the bound that applied, in the stage verdict's
// extra["explain"]. Judges record it while they walk their elements.
#pragma once

#include <array>
#include <vector>

#include "compare/admission.h"
#include "compare/element_loop.h"
#include "compare/stage_compare.h"
#include "compare/verdict.h"

namespace vct::cmp {

/// Whether opt.explain names element (x, y) of an image (z < 0) or (x, y, z) of a volume.
bool explains(const CompareOptions& opt, int x, int y, int z = -1);

/// extra["explain"] = {at, rule, kind, reference, test, error, bound}.
void record_explained(StageVerdict& v, Rule rule, const std::array<int, 3>& at, const std::vector<float>& reference,
                      const std::vector<float>& test, const WorstChannel& worst);

}  // namespace vct::cmp
