#include "compare/isolated_stages.h"

#include <algorithm>

#include "compare/tolerance.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/multibounce.h"
#include "stages/particles.h"
#include "stages/pipeline.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

namespace vct::cmp {

DirectInput direct_input_of(const DisplayTransform* display) {
  if (!display || !display->applies_to(stage_names::kImageDirect)) return DirectInput::Linear;
  return display->decodable() ? DirectInput::Decoded : DirectInput::Undecodable;
}

void decode_display_direct(const DisplayTransform& display, Image& direct) {
  for (int y = 0; y < direct.height; ++y)
    for (int x = 0; x < direct.width; ++x)
      for (int c = 0; c < std::min(direct.channels, 3); ++c)
        direct.at(x, y, c) = float(display.decode(direct.at(x, y, c)));
}

FrameResult reference_on_test_inputs(const Scene& scene, const FrameResult& test, const VctSettings& s,
                                     const DisplayTransform* display) {
  FrameResult r = test;
  r.backend = "ref-on-" + test.backend + "-inputs";
  // An engine's display-encoded direct light is not radiance: the composite adds it decoded
  // (docs/compare.md, "Display transform"). With soft shadows it is re-traced anyway.
  if (direct_input_of(display) == DirectInput::Decoded && !s.soft_shadows)
    decode_display_direct(*display, r.images.direct);
  trace_cone_stages(scene, s, r);
  return r;
}

std::optional<VoxelGrid> reference_voxels_on_test_bounce_input(const Scene& scene, const FrameResult& test,
                                                              const VctSettings& s) {
  if (s.bounces < 2 || test.bounce_input.voxel_count() == 0 || test.bounce_input.nx != s.grid) return std::nullopt;
  // The reference's own voxelization and shadow maps, as its frame used them (pipeline.cpp).
  const std::vector<vec2> positions = test.facts.sample_positions.empty()
                                          ? standard_sample_positions(s.msaa_samples)
                                          : test.facts.sample_positions;
  const Voxelization vox = s.voxelizer == Voxelizer::Conservative ? voxelize_conservative(scene, s.grid)
                                                                   : voxelize_gpu_rule(scene, s.grid, positions);
  const std::vector<ShadowMap> maps = render_shadow_maps(scene, s);
  const VoxelMips previous = build_mips(test.bounce_input, s.anisotropic);
  const BounceLight bounce = make_bounce_light(scene, previous, s);
  VoxelGrid grid = inject_and_reduce(scene, vox, maps, s, &bounce);
  add_particles_to_voxels(scene, s, grid.radiance);
  return grid;
}

namespace {
const StageVerdict* find_stage(const Report& r, const std::string& stage) {
  for (const StageVerdict& v : r.stages)
    if (v.stage == stage) return &v;
  return nullptr;
}

// `v` (end to end) replaced by `iso`, the end-to-end verdict kept in the note and extra.
void replace_with_isolated(StageVerdict& v, const StageVerdict& iso, const char* inputs) {
  nlohmann::json e2e = {{"verdict", to_string(v.verdict)}, {"note", v.note}, {"rms", v.rms}, {"max_abs", v.max_abs}};
  const std::string e2e_note = v.note;
  const Verdict e2e_verdict = v.verdict;
  std::string e2e_mask = v.mask;
  v = iso;
  v.extra["end_to_end"] = e2e;
  // The isolated re-judgement writes no mask; a warn that only the end-to-end difference explains
  // is shown by the end-to-end mask (the report's first screen shows the warned stage's mask).
  if (v.mask.empty()) v.mask = std::move(e2e_mask);
  v.note = std::string("on ") + inputs + ": " + iso.note + " | end to end: " + to_string(e2e_verdict) + " (" +
           e2e_note + ")";
  // Upstream ties explain an end-to-end difference only as far as the isolated stage passes.
  if (v.verdict == Verdict::Pass && e2e_verdict != Verdict::Pass) v.verdict = Verdict::Warn;
}
}  // namespace

void apply_isolated_verdicts(Report& end_to_end, const Report& isolated, bool soft_shadows) {
  for (StageVerdict& v : end_to_end.stages) {
    if (!is_cone_traced(v.stage, soft_shadows)) continue;
    const StageVerdict* iso = find_stage(isolated, v.stage);
    if (!iso || iso->verdict == Verdict::Missing) continue;
    replace_with_isolated(v, *iso, "the test's own voxels");
  }
}

void judge_cones_on_test_inputs(Report& end_to_end, const Scene& scene, const FrameResult& test, const VctSettings& s,
                                const StageSet& test_set, const CompareOptions& opt) {
  const DisplayTransform* display = &test_set.conventions.display;
  const DirectInput direct = s.soft_shadows ? DirectInput::Linear : direct_input_of(display);
  const FrameResult ref_on_test = reference_on_test_inputs(scene, test, s, display);
  CompareOptions iso_opt = opt;
  iso_opt.direct_decoded_from_display = direct == DirectInput::Decoded;
  Report isolated = compare_stage_sets(stage_set_from_frame(ref_on_test, s), test_set, iso_opt);
  if (direct == DirectInput::Undecodable)
    for (StageVerdict& v : isolated.stages)
      if (v.stage == stage_names::kImageFinal) v.verdict = Verdict::Missing;  // end-to-end verdict stays
  apply_isolated_verdicts(end_to_end, isolated, s.soft_shadows);
  // Multibounce: the last frame's voxels on the test's own bounce input.
  if (std::optional<VoxelGrid> grid = reference_voxels_on_test_bounce_input(scene, test, s)) {
    FrameResult r = test;
    r.backend = "ref-on-" + test.backend + "-bounce-input";
    r.voxels = std::move(*grid);
    const Report iso = compare_stage_sets(stage_set_from_frame(r, s), test_set, opt);
    const StageVerdict* v = find_stage(iso, stage_names::kVoxelRadiance);
    for (StageVerdict& e : end_to_end.stages)
      if (v && e.stage == stage_names::kVoxelRadiance && v->verdict != Verdict::Missing)
        replace_with_isolated(e, *v, "the test's own bounce input");
  }
}

}  // namespace vct::cmp
