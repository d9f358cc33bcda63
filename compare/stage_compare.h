// GPU (or external) stage outputs against the CPU reference, stage by stage, with the tolerance
// models of tolerance.h; error masks written beside the run (docs/compare.md).
#pragma once

#include <string>
#include <vector>

#include "compare/judge_context.h"
#include "compare/stage_set.h"
#include "compare/verdict.h"

namespace vct::cmp {

/// What a user chooses about a comparison. What the judge's passes derive (soft shadows, upstream
/// ties, depth format, decoded display) is in JudgeContext (compare/judge_context.h).
struct CompareOptions {
  size_t worst_n = 10;
  std::string mask_dir;     // absolute/relative directory for mask PNGs ("" = no masks)
  std::string mask_prefix;  // how masks are named in the verdicts (relative to the run dir)
  // x, y (images) or x, y, z (volumes): the element whose admission each verdict explains in
  // extra["explain"] (compare/explain_element.h); empty = none.
  std::vector<int> explain;
};

/// The images an image stage's rules read besides its two values (each may be null).
/// `edge_hint`: the reference's depth (camera-space stages), for the edge map.
/// `texture_slack`: the reference's GBuffer::texture_slack (freedoms/texture_slack.h), added to the
/// bound of the textured G-buffer stages; its alpha_tie channel adds edges.
/// `display`: the engine's declared display transform of this stage (compare/display_transform.h):
/// the reference's linear colour is mapped through it and each pixel's bound carried into display
/// space; nullptr = linear.
/// `tie_range`: the reference's GBuffer::tie_range (freedoms/gbuffer_ties.h), or for a shadow map its
/// ShadowMap::tie_range / cube_tie_range face (freedoms/shadow_map_ties.h): a beyond-bound pixel
/// inside the range of the values a correct GL may show there (plus its bound) is admitted as a
/// raster alternative, at any count, and any other fails (compare/tie_range.h).
struct ImageStageInputs {
  const Image* edge_hint = nullptr;
  const Image* texture_slack = nullptr;
  const DisplayTransform* display = nullptr;
  const Image* tie_range = nullptr;
  // A reference decoded from its own quantised display encoding (two runs of one engine): its
  // stored value was within one step of its true display value (GL 4.5 §2.3.5.1), a step the
  // display-space bound adds to the test's own (docs/compare.md, "Display transform").
  double reference_quantisation = 0.0;
};

/// The first pass of the judge (compare/judge.h runs them all): every stage of the two sets by its
/// rules (compare/admission.h), in pipeline order.
Report compare_stage_sets(const StageSet& reference, const StageSet& test, const CompareOptions& opt,
                          const JudgeContext& ctx);
Report compare_stage_sets(const StageSet& reference, const StageSet& test, const CompareOptions& opt = {});

/// One image stage: each pixel admitted by the first rule that holds (compare/admission.h: within
/// the bound, a range of raster alternatives, an admissible neighbour at an edge, a counted share),
/// then the counted shares decide (compare/counted_shares.h). `stage` selects the model.
StageVerdict judge_image_stage(const std::string& stage, const Image& ref, const Image& test,
                               const ImageStageInputs& in, const CompareOptions& opt, const JudgeContext& ctx);

/// judge_image_stage with a fresh context (two bare images, tests).
StageVerdict compare_image_stage(const std::string& stage, const Image& ref, const Image& test,
                                 const Image* edge_hint, const CompareOptions& opt,
                                 const Image* texture_slack = nullptr,
                                 const DisplayTransform* display = nullptr,
                                 const Image* tie_range = nullptr);

/// Two bare volumes, element-wise with abs/rel bound (vct compare A.nrrd B.nrrd).
StageVerdict compare_volume_plain(const std::string& stage, const Volume& ref, const Volume& test, double abs,
                                  double rel, const CompareOptions& opt);

}  // namespace vct::cmp
