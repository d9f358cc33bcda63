#include "compare/isolated_stages.h"

#include "compare/tolerance.h"
#include "stages/pipeline.h"

namespace vct::cmp {

FrameResult reference_on_test_inputs(const Scene& scene, const FrameResult& test, const VctSettings& s) {
  FrameResult r = test;
  r.backend = "ref-on-" + test.backend + "-inputs";
  trace_cone_stages(scene, s, r);
  return r;
}

namespace {
const StageVerdict* find_stage(const Report& r, const std::string& stage) {
  for (const StageVerdict& v : r.stages)
    if (v.stage == stage) return &v;
  return nullptr;
}
}  // namespace

void apply_isolated_verdicts(Report& end_to_end, const Report& isolated, bool soft_shadows) {
  for (StageVerdict& v : end_to_end.stages) {
    if (!is_cone_traced(v.stage, soft_shadows)) continue;
    const StageVerdict* iso = find_stage(isolated, v.stage);
    if (!iso || iso->verdict == Verdict::Missing) continue;
    nlohmann::json e2e = {{"verdict", to_string(v.verdict)}, {"note", v.note}, {"rms", v.rms}, {"max_abs", v.max_abs}};
    const std::string e2e_note = v.note;
    const Verdict e2e_verdict = v.verdict;
    v = *iso;
    v.extra["end_to_end"] = e2e;
    v.note = "on " + std::string("the test's own voxels: ") + iso->note + " | end to end: " + to_string(e2e_verdict) +
             " (" + e2e_note + ")";
    // Upstream ties explain an end-to-end difference only as far as the isolated stage passes.
    if (v.verdict == Verdict::Pass && e2e_verdict != Verdict::Pass) v.verdict = Verdict::Warn;
  }
}

void judge_cones_on_test_inputs(Report& end_to_end, const Scene& scene, const FrameResult& test, const VctSettings& s,
                                const StageSet& test_set, const CompareOptions& opt) {
  const FrameResult ref_on_test = reference_on_test_inputs(scene, test, s);
  apply_isolated_verdicts(end_to_end, compare_stage_sets(stage_set_from_frame(ref_on_test, s), test_set, opt),
                          s.soft_shadows);
}

}  // namespace vct::cmp
