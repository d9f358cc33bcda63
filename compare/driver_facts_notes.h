// The driver's facts in the verdicts: each stage whose tolerance model rests on a fact about the
// driver says in its note when the driver did not report that fact (BackendFacts::unreported), or
// when the CPU could not mirror it (sample positions, sub-pixel precision). docs/gl_backend.md,
// "Driver facts".
#pragma once

#include "compare/verdict.h"
#include "stages/backend_facts.h"

namespace vct::cmp {

/// Appends one sentence per relevant fact to the notes of `rep`'s stages. `test` are the facts of
/// the GPU side, `reference` those of the CPU side (what its emulation assumed).
void note_driver_facts(Report& rep, const BackendFacts& test, const BackendFacts& reference);

}  // namespace vct::cmp
