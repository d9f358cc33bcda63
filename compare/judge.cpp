#include "compare/judge.h"

#include "compare/conservative_occupancy.h"
#include "compare/driver_facts_notes.h"
#include "compare/isolated_stages.h"

namespace vct::cmp {

bool judges_on_own_inputs(const JudgeInputs& in) { return in.scene && in.test_frame && in.settings; }

Report judge(const StageSet& reference, const StageSet& test, const JudgeInputs& in, const CompareOptions& opt) {
  Report rep = compare_stage_sets(reference, test, opt, JudgeContext());
  judge_conservative_mode(rep, reference, test, in.scene, opt.worst_n);
  // The isolated pass writes no masks: a stage it re-judges keeps the end-to-end mask.
  if (judges_on_own_inputs(in))
    judge_cones_on_test_inputs(rep, *in.scene, *in.test_frame, *in.settings, test, {opt.worst_n, "", "", {}});
  note_driver_facts(rep, test.facts, reference.facts);
  return rep;
}

}  // namespace vct::cmp
