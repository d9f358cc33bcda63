#include "compare/isolated_stages.h"

#include <algorithm>
#include <cmath>

#include "compare/bounce_frames.h"
#include "compare/tie_range.h"
#include "compare/tolerance.h"
#include "compare/volume_judges.h"
#include "freedoms/coverage_ties.h"
#include "freedoms/direct_ties.h"
#include "freedoms/voxel_freedoms.h"
#include "stages/cube_map.h"
#include "stages/direct.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/multibounce.h"
#include "stages/particles.h"
#include "stages/pipeline.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

namespace vct::cmp {

namespace {
// The test's own shadow maps with the matrices both backends look them up through (GL takes the
// CPU's; a stage set's maps carry none: stage_set_frame.cpp), as render_shadow_maps builds them.
// Empty unless every light has its map.
std::vector<ShadowMap> test_maps_with_matrices(const Scene& scene, const FrameResult& test, const VctSettings& s) {
  if (test.shadow_maps.size() != scene.lights.size()) return {};
  std::vector<ShadowMap> maps = test.shadow_maps;
  for (size_t i = 0; i < maps.size(); ++i) {
    const Light& light = scene.lights[i];
    ShadowMap& m = maps[i];
    if (light.is_point()) {
      const vec2 range = light_depth_range(light, scene.bounds);
      for (int f = 0; f < 6; ++f) {
        if (m.cube[size_t(f)].empty() || m.cube[size_t(f)].width != m.cube[0].width) return {};
        m.cube_view_proj[size_t(f)] = cube_face_view_proj(f, light.position, range.x, range.y);
      }
    } else {
      if (m.depth.empty()) return {};
      m.view_proj = light_view_proj(scene, i, s);
    }
  }
  return maps;
}
}  // namespace

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

namespace {
// `test` without its volumes (voxels, occupancy, holes, mips, bounce frames): what the re-trace
// writes into and the isolated comparison reads; the cones read the test's mips in place.
FrameResult frame_without_volumes(const FrameResult& test) {
  FrameResult r;
  r.backend = test.backend;
  r.shadow_maps = test.shadow_maps;
  r.gbuffer = test.gbuffer;
  r.images = test.images;
  r.multibounce_energy = test.multibounce_energy;
  r.timings_ms = test.timings_ms;
  r.facts = test.facts;
  r.info = test.info;
  return r;
}

// The re-trace of reference_on_test_inputs into `r` (a copy of `test`, with or without its volumes).
FrameResult retrace_on_test_inputs(FrameResult r, const Scene& scene, const FrameResult& test, const VctSettings& s,
                                   const DisplayTransform* display, int march_end) {
  r.backend = "ref-on-" + test.backend + "-inputs";
  // The composite adds the test's own direct light, so image.final judges the cones and the
  // composite, not direct light a second time (image.direct is judged below); an engine's
  // display-encoded direct light is not radiance, so it is added decoded (docs/compare.md,
  // "Display transform"). With soft shadows direct light is re-traced anyway.
  if (direct_input_of(display) == DirectInput::Decoded && !s.soft_shadows)
    decode_display_direct(*display, r.images.direct);
  trace_cone_stages(scene, s, r, test.mips, march_end);
  std::vector<ShadowMap> maps;
  if (!s.soft_shadows) {
    // image.direct re-shaded from the test's G-buffer and shadow maps (docs/compare.md, "Shading
    // stages on the test's own inputs"); without the test's maps it is not judged here (missing,
    // so the end-to-end verdict stands).
    maps = test_maps_with_matrices(scene, test, s);
    r.images.direct = maps.empty() && !scene.lights.empty() ? Image() : shade_direct(scene, r.gbuffer, maps, s);
  }
  // The only ties left on these inputs: PCF taps the lookup's float arithmetic may flip; none for
  // emission. Replaces any raster range the test carried (its G-buffer stages are not judged here).
  r.gbuffer.tie_range = shading_tie_range(scene, r.gbuffer, maps, s, s.soft_shadows ? Image() : r.images.direct,
                                          r.images.emission);
  // With soft shadows image.direct is cone-traced: no shadow map decides its visibility, so there
  // is no PCF range to admit by (a range without its maps would admit anything from 0 to the
  // unshadowed light); it is judged like the other cone stages (docs/compare.md, "Admission rules").
  if (s.soft_shadows) r.gbuffer.tie_range = without_tie_range_group(r.gbuffer.tie_range, stage_names::kImageDirect);
  return r;
}

// reference_on_test_inputs without the test's volumes: all the isolated comparison reads.
FrameResult images_on_test_inputs(const Scene& scene, const FrameResult& test, const VctSettings& s,
                                  const DisplayTransform* display, int march_end = 0) {
  return retrace_on_test_inputs(frame_without_volumes(test), scene, test, s, display, march_end);
}
}  // namespace

FrameResult reference_on_test_inputs(const Scene& scene, const FrameResult& test, const VctSettings& s,
                                     const DisplayTransform* display, int march_end) {
  return retrace_on_test_inputs(test, scene, test, s, display, march_end);
}

bool has_own_shadow_maps(const Scene& scene, const FrameResult& test, const VctSettings& s) {
  return !scene.lights.empty() && !test_maps_with_matrices(scene, test, s).empty();
}

VoxelInjection::VoxelInjection(const Scene& scene, const FrameResult& test, const VctSettings& s)
    : scene_(scene), s_(s) {
  maps_ = scene.lights.empty() ? std::vector<ShadowMap>() : test_maps_with_matrices(scene, test, s);
  if (maps_.empty()) maps_ = render_shadow_maps(scene, s);  // the reference's own, as its frame used them
  // The reference's own voxelization (stages/pipeline.cpp), with its coverage ties.
  const std::vector<vec2> positions = test.facts.sample_positions.empty()
                                          ? standard_sample_positions(s.msaa_samples)
                                          : test.facts.sample_positions;
  vox_ = s.voxelizer == Voxelizer::Conservative ? voxelize_conservative(scene, s.grid)
                                                 : voxelize_gpu_rule(scene, s.grid, positions);
  add_coverage_ties(scene, vox_);
}

VoxelGrid VoxelInjection::frame(const Volume* bounce_input) const {
  if (!bounce_input) return judged_voxels(scene_, vox_, maps_, s_);
  const VoxelMips previous = build_mips(*bounce_input, s_.anisotropic);
  const BounceLight bounce = make_bounce_light(scene_, previous, s_);
  return judged_voxels(scene_, vox_, maps_, s_, &bounce);
}

std::optional<VoxelGrid> reference_voxels_on_test_inputs(const Scene& scene, const FrameResult& test,
                                                         const VctSettings& s) {
  const bool bounce_input = s.bounces >= 2 && test.bounce_input.voxel_count() > 0 && test.bounce_input.nx == s.grid;
  // The running mean's interval is computed beside the frame (freedoms/reference_freedoms.cpp), not
  // re-derived here.
  if (s.reduction == Reduction::RunningMeanHalf) return std::nullopt;
  if (!bounce_input && !has_own_shadow_maps(scene, test, s)) return std::nullopt;
  return VoxelInjection(scene, test, s).frame(bounce_input ? &test.bounce_input : nullptr);
}

JudgeContext voxels_on_own_inputs_context(const VctSettings& s) {
  // On the test's own maps no shadow-map tie is left to share. The coverage ties cover the
  // sample rule and the gs mode's box arithmetic; a hardware conservative raster over-estimates
  // by what its driver reports, which only the occupancy judge reads, so those modes keep the
  // share (docs/compare.md, "Voxel shading slack").
  JudgeContext own_maps;
  const bool hardware_conservative = s.conservative_raster == ConservativeRaster::Nv ||
                                     s.conservative_raster == ConservativeRaster::Intel;
  if (!hardware_conservative) own_maps.shading_tie_fraction = 0.0;
  return own_maps;
}

namespace {
const StageVerdict* find_stage(const Report& r, const std::string& stage) {
  for (const StageVerdict& v : r.stages)
    if (v.stage == stage) return &v;
  return nullptr;
}

// `v` (end to end) replaced by `iso`, the end-to-end verdict kept in the note and extra.
void replace_with_isolated(StageVerdict& v, const StageVerdict& iso, const char* inputs) {
  nlohmann::json e2e = {{"verdict", to_string(v.verdict)}, {"note", v.note}, {"rms", v.rms}, {"max_abs", v.max_abs},
                        {"admitted_by", v.admitted.json()}};
  const std::string e2e_note = v.note;
  const Verdict e2e_verdict = v.verdict;
  const size_t e2e_beyond = v.out_of_bound;
  std::string e2e_mask = v.mask;
  v = iso;
  // The isolated re-judgement writes no mask; a warn that only the end-to-end difference explains
  // is shown by the end-to-end mask (the report's first screen shows the warned stage's mask).
  if (v.mask.empty()) v.mask = std::move(e2e_mask);
  v.note = std::string("on ") + inputs + ": " + iso.note + " | end to end: " + to_string(e2e_verdict) + " (" +
           e2e_note + ")";
  // Upstream ties explain an end-to-end difference only as far as the isolated stage passes. Then
  // every element beyond the end-to-end bound is within the isolated one: the re-judgement on the
  // test's own inputs is what admitted it (compare/admission.h, own-inputs).
  if (v.verdict == Verdict::Pass && e2e_verdict != Verdict::Pass) {
    v.verdict = Verdict::Warn;
    const Rule within = v.admitted[Rule::WithinBound] > 0 ? Rule::WithinBound : Rule::RadianceWithinBound;
    const size_t moved = std::min(e2e_beyond, v.admitted[within]);
    v.admitted.count[size_t(within)] -= moved;
    v.admitted.add(Rule::OwnInputs, moved);
  }
  v.extra["end_to_end"] = e2e;
}
}  // namespace

bool is_shading_on_own_inputs(const std::string& stage, bool soft_shadows) {
  return stage == stage_names::kImageEmission || (!soft_shadows && stage == stage_names::kImageDirect);
}

void apply_isolated_verdicts(Report& end_to_end, const Report& isolated, bool soft_shadows) {
  for (StageVerdict& v : end_to_end.stages) {
    const bool shading = is_shading_on_own_inputs(v.stage, soft_shadows);
    if (!shading && !is_cone_traced(v.stage, soft_shadows)) continue;
    const StageVerdict* iso = find_stage(isolated, v.stage);
    if (!iso || iso->verdict == Verdict::Missing) continue;
    replace_with_isolated(v, *iso, shading ? "the test's own G-buffer and shadow maps" : "the test's own voxels");
  }
}

namespace {
// The cone images a march-end variant changes (the indirect cones and what the composite makes of them).
// The cone images the march-end tie replaces, with the stage each is judged as.
struct MarchEndImage {
  Image FrameImages::*slot;
  const char* stage;
};
constexpr MarchEndImage kMarchEndImages[] = {
    {&FrameImages::indirect_diffuse, stage_names::kImageIndirectDiffuse},
    {&FrameImages::indirect_specular, stage_names::kImageIndirectSpecular},
    {&FrameImages::diffuse_term, stage_names::kImageDiffuseTerm},
    {&FrameImages::specular_term, stage_names::kImageSpecularTerm},
    {&FrameImages::final_image, stage_names::kImageFinal}};

// The largest channel difference between reference value `r` and the test's stored `t`, in the
// space the stage is judged in: a stage the engine wrote display-encoded is compared after the
// reference's colour goes through the same transform (compare/display_transform.h), as its
// verdict is; "closest" in linear units against a display-encoded value would pick at random.
float largest_difference(const Image& r, const Image& t, int x, int y, const DisplayTransform* display) {
  float d = 0.0f;
  for (int c = 0; c < std::min(r.channels, t.channels); ++c) {
    const float ref = display && c < 3 ? float(display->apply(double(r.at(x, y, c)))) : r.at(x, y, c);
    d = std::max(d, std::abs(ref - t.at(x, y, c)));
  }
  return d;
}

bool any_cone_stage_fails(const Report& r, bool soft_shadows) {
  for (const StageVerdict& v : r.stages)
    if (is_cone_traced(v.stage, soft_shadows) && v.verdict == Verdict::Fail) return true;
  return false;
}
}  // namespace

FrameResult closest_march_end(const FrameResult& plain, const FrameResult& shorter, const FrameResult& longer,
                              const FrameResult& test, size_t* pixels_moved, const DisplayTransform* display) {
  FrameResult out = plain;
  size_t moved = 0;
  for (const MarchEndImage& image : kMarchEndImages) {
    Image& o = out.images.*image.slot;
    const Image& t = test.images.*image.slot;
    const Image* variants[2] = {&(shorter.images.*image.slot), &(longer.images.*image.slot)};
    const DisplayTransform* space = display && display->applies_to(image.stage) ? display : nullptr;
    if (o.empty() || t.width != o.width || t.height != o.height) continue;
    for (int y = 0; y < o.height; ++y)
      for (int x = 0; x < o.width; ++x) {
        float best = largest_difference(o, t, x, y, space);
        const Image* chosen = nullptr;
        for (const Image* v : variants) {
          if (v->width != o.width || v->height != o.height) continue;
          const float d = largest_difference(*v, t, x, y, space);
          if (d < best) best = d, chosen = v;
        }
        if (!chosen) continue;
        for (int c = 0; c < o.channels; ++c) o.at(x, y, c) = chosen->at(x, y, c);
        ++moved;
      }
  }
  if (pixels_moved) *pixels_moved = moved;
  return out;
}

namespace {
// What the isolated comparison judges: the stages apply_isolated_verdicts takes (cone-traced, and
// shading on the test's own inputs), beside the images compare_stage_sets reads for every image
// stage (depth for edges, texture slack, tie range). Every other stage of the re-traced frame is
// the test's own copy, equal by construction, and judging it again cost about a third of this
// phase (docs/performance.md, "Where validate's time goes"). The verdicts of the judged stages do
// not change: (1) they read only their own images, the context images and the options; (2) the
// voxels are the test's own, so none differs, none is tainted, and upstream_tie_fraction is 0
// with or without them; (3) both sides keep the same names, so which side has a stage, and
// whether a family's chain is broken (all its members pass the same test), stay as they were.
bool isolated_stage(const std::string& name, bool soft_shadows) {
  return is_cone_traced(name, soft_shadows) || is_shading_on_own_inputs(name, soft_shadows) ||
         name == stage_names::kGbufferDepth || name == stage_names::kGbufferTextureSlack ||
         name == stage_names::kGbufferTieRange;
}

// `soft_shadows` as compare_stage_sets will judge: either set's settings.
StageSet isolated_reference_set(const FrameResult& r, const VctSettings& s, bool soft_shadows) {
  StageSet set = stage_set_header(r, s);
  for (const StageRow& row : stage_rows()) {
    if (row.kind != StageKind::Image) continue;
    for (int i : frame_members(r, row))
      if (isolated_stage(stage_name(row, i), soft_shadows)) set.images[stage_name(row, i)] = *frame_image(r, row, i);
  }
  return set;
}

// The test's set with the same stages kept (its header, conventions included, unchanged).
StageSet isolated_test_set(const StageSet& test, bool soft_shadows) {
  StageSet set = stage_set_without_stages(test);  // no copy of the volumes it would drop
  for (const auto& [name, img] : test.images)
    if (isolated_stage(name, soft_shadows)) set.images[name] = img;
  return set;
}
}  // namespace

namespace {
// voxel.radiance re-judged on the test's own shadow maps (and, multibounce, its own bounce input).
void judge_radiance_on_test_inputs(Report& end_to_end, const Scene& scene, const FrameResult& test,
                                   const VctSettings& s, const StageSet& test_set, const CompareOptions& opt) {
  // The voxels on the test's own shadow maps (and, multibounce, its own bounce input): a texel
  // that differs on GL's own map then moves no voxel (docs/compare.md, "Voxel radiance on the
  // test's own shadow maps"), with no share of shading ties: what the shadow maps do not explain,
  // the reference's slack does (snap, LOD, coverage ties; docs/compare.md, "Voxel shading slack").
  // The re-injection costs what the reference's injection and slack
  // cost (atrium, 256^2, grid 128: +7 s), so one frame re-injects only where the end-to-end
  // verdict has shading ties to explain; with a bounce input always (its bounce light differs
  // everywhere).
  const bool bounce_input = s.bounces >= 2 && test.bounce_input.voxel_count() > 0;
  const StageVerdict* e2e_radiance = find_stage(end_to_end, stage_names::kVoxelRadiance);
  const bool shading_ties = e2e_radiance && e2e_radiance->extra.value("shading_ties", 0) > 0;
  std::optional<VoxelGrid> grid;
  if (bounce_input || shading_ties) grid = reference_voxels_on_test_inputs(scene, test, s);
  if (grid) {
    // Only voxel.radiance is taken from this judgement, and its judge reads the reference's voxel
    // stages (radiance, fragments, shading slack, exactness, CAS bounds: all the grid's) and the
    // test set's header, radiance and fragments; so the reference side is the grid alone, as in
    // compare/bounce_frames.cpp, not a copy of the test's frame judged stage by stage again
    // (demo_room at 256^3: ~1.3 GB of copies and every other stage's judgement; docs/performance.md).
    FrameResult r;
    r.backend = "ref-on-" + test.backend + "-voxel-inputs";
    r.facts = test.facts;  // the reduction the test declares (stage_set_header reads it)
    r.voxels = std::move(*grid);
    const StageSet reference = stage_set_from_frame(std::move(r), s);
    const char* radiance = stage_names::kVoxelRadiance;
    if (!reference.volumes.count(radiance) || !test_set.volumes.count(radiance)) return;  // missing: e2e stands
    Taint taint;
    const StageVerdict v = compare_radiance(reference, test_set, opt, voxels_on_own_inputs_context(s), taint);
    for (StageVerdict& e : end_to_end.stages)
      if (e.stage == radiance && v.verdict != Verdict::Missing)
        replace_with_isolated(e, v,
                              bounce_input ? "the test's own shadow maps and bounce input" : "the test's own shadow maps");
  }
}
}  // namespace

void judge_cones_on_test_inputs(Report& end_to_end, const Scene& scene, const FrameResult& test, const VctSettings& s,
                                const StageSet& test_set, const CompareOptions& opt) {
  const DisplayTransform* display = &test_set.conventions.display;
  const DirectInput direct = s.soft_shadows ? DirectInput::Linear : direct_input_of(display);
  const FrameResult ref_on_test = images_on_test_inputs(scene, test, s, display);
  JudgeContext iso_ctx;
  iso_ctx.direct_decoded_from_display = direct == DirectInput::Decoded;
  const bool soft = s.soft_shadows || soft_shadows_of(test_set);
  const StageSet test_judged = isolated_test_set(test_set, soft);
  Report isolated = compare_stage_sets(isolated_reference_set(ref_on_test, s, soft), test_judged, opt, iso_ctx);
  // The march-end tie (docs/compare.md): only where the plain re-trace fails a cone stage, each
  // cone-image pixel is judged against the closest of the three admissible march ends.
  if (any_cone_stage_fails(isolated, s.soft_shadows)) {
    size_t moved = 0;
    const FrameResult closest = closest_march_end(ref_on_test, images_on_test_inputs(scene, test, s, display, -1),
                                                  images_on_test_inputs(scene, test, s, display, +1), test, &moved,
                                                  display);
    const Report plain = std::move(isolated);
    isolated = compare_stage_sets(isolated_reference_set(closest, s, soft), test_judged, opt, iso_ctx);
    for (StageVerdict& v : isolated.stages)
      if (is_cone_traced(v.stage, s.soft_shadows)) {
        const StageVerdict* p = find_stage(plain, v.stage);
        v.note += "; closest march end (a first or last sample within its position's precision of a face, "
                  "or the last of max_distance, docs/compare.md) taken at " +
                  std::to_string(moved) + " pixel values of the cone images; plain re-trace: " +
                  (p ? to_string(p->verdict) + ", " + std::to_string(p->out_of_bound) + " beyond" : std::string("-"));
        v.extra["march_end_alternatives"] = moved;
        if (p) v.extra["plain_retrace"] = {{"verdict", to_string(p->verdict)}, {"out_of_bound", p->out_of_bound}};
      }
  }
  if (direct == DirectInput::Undecodable)
    for (StageVerdict& v : isolated.stages)
      if (v.stage == stage_names::kImageFinal) v.verdict = Verdict::Missing;  // end-to-end verdict stays
  apply_isolated_verdicts(end_to_end, isolated, s.soft_shadows);
  judge_radiance_on_test_inputs(end_to_end, scene, test, s, test_set, opt);
  judge_bounce_frames(end_to_end, scene, test, s, test_set, opt);  // reads voxel.radiance's verdict
}

}  // namespace vct::cmp
