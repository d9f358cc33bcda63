// Judging each cone-traced stage on the test backend's own inputs.
//
// End to end, a legitimate tie upstream (a fragment on a voxel boundary landing one voxel over,
// as the GL spec allows) can open or close a one-voxel gap, and every cone through it then sees
// different light: the cone images differ although both marchers are right. A conformance suite
// judges each stage on identical inputs, so the oracle re-runs the reference's cone tracing and
// composite on the test's G-buffer, direct image and mips, and judges the test's cone images
// against that. The end-to-end difference stays in the report as context.
#pragma once

#include <optional>

#include "compare/display_transform.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "compare/verdict.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct::cmp {

/// The reference's cone-traced images computed from `test`'s G-buffer, direct light, particles
/// and mips; the other stages are copied from `test`. Soft shadows (cone-traced direct light)
/// are re-traced too when enabled; otherwise direct light is re-shaded from `test`'s G-buffer and
/// shadow maps (left empty when `test` lacks a light's map). gbuffer.tie_range then holds the
/// shading stages' admissible ranges on these inputs (freedoms/direct_ties.h), nothing else.
/// `display`: the test's declared display transform; when it names image.direct, the composite
/// adds that image decoded to linear light (DisplayTransform::decode; decode_display_direct).
/// `march_end`: the indirect cones' MarchParams::march_end (-1 / +1: the march-end tie's
/// alternatives, docs/compare.md "The march-end tie").
FrameResult reference_on_test_inputs(const Scene& scene, const FrameResult& test, const VctSettings& s,
                                     const DisplayTransform* display = nullptr, int march_end = 0);

/// How the test's image.direct enters the re-traced composite under a declared display
/// transform: as it is (not display-encoded), decoded (a concave transform: image.final's bound
/// grows by one step), or not at all (a transform no decoded value can be bounded through:
/// image.final keeps its end-to-end verdict).
enum class DirectInput { Linear, Decoded, Undecodable };
DirectInput direct_input_of(const DisplayTransform* display);

/// `direct` (display-encoded by `display`, colour channels) decoded to linear light in place.
void decode_display_direct(const DisplayTransform& display, Image& direct);

/// The march-end tie: `plain` with each pixel of its indirect cone images (and the terms and
/// final image made of them) replaced by `shorter`'s or `longer`'s (the re-trace with march_end
/// -1 / +1) where that is closer to `test` (largest channel difference), as dEQP accepts any
/// admissible result. `pixels_moved`: how many pixel values were replaced. `display`: the test's
/// declared display transform; "closest" is measured in display space for the stages it names.
FrameResult closest_march_end(const FrameResult& plain, const FrameResult& shorter, const FrameResult& longer,
                              const FrameResult& test, size_t* pixels_moved = nullptr,
                              const DisplayTransform* display = nullptr);

/// The voxels as the reference computes them from the test's own inputs: its own voxelization,
/// injected through the test's shadow maps (with the matrices both backends use; the reference's
/// own where the test has none) and, in a multibounce frame, with the bounce light traced in mips
/// built from test.bounce_input (the test's frame before the last); particles added; the shading
/// slack taken on those maps. End to end, a shadow-map texel that ties on GL's own map moves every
/// fragment that samples it, and every voxel an earlier frame legitimately moved changes the
/// bounce light of its neighbours: the reference's own frame cannot show either. Nullopt when
/// there is neither (no lights or no test maps, one frame), or with the running-mean reduction.
std::optional<VoxelGrid> reference_voxels_on_test_inputs(const Scene& scene, const FrameResult& test,
                                                         const VctSettings& s);

/// True when `test` holds a shadow map for every light of `scene` (none when it has no lights).
bool has_own_shadow_maps(const Scene& scene, const FrameResult& test, const VctSettings& s);

/// The reference's voxel injection on a test's inputs, one frame at a time: its own voxelization
/// (at the test's sample positions) and the test's shadow maps (the reference's own where the test
/// has none), built once for every frame judged (compare/bounce_frames.h).
class VoxelInjection {
 public:
  VoxelInjection(const Scene& scene, const FrameResult& test, const VctSettings& s);
  /// One frame: injected with the bounce light traced in mips built from `bounce_input` (none:
  /// frame 1), particles added, the shading slack taken on those inputs.
  VoxelGrid frame(const Volume* bounce_input) const;

 private:
  const Scene& scene_;
  const VctSettings& s_;
  std::vector<ShadowMap> maps_;
  Voxelization vox_;
};

/// How voxels re-injected on the test's own inputs are counted: no share of shading ties, except
/// under a hardware conservative raster (docs/compare.md, "Voxel shading slack").
JudgeContext voxels_on_own_inputs_context(const VctSettings& s);

/// True for the shading stages judged on the test's own G-buffer and shadow maps: image.emission,
/// and image.direct unless soft shadows cone-trace it.
bool is_shading_on_own_inputs(const std::string& stage, bool soft_shadows);

/// For every cone-traced stage and the shading stages (is_shading_on_own_inputs), replaces the
/// end-to-end verdict by the isolated one (stage judged on the test's own inputs) and keeps the
/// end-to-end verdict in the note and in extra["end_to_end"], so such a stage fails only when the
/// test's own arithmetic is wrong. `soft_shadows`: direct light was cone-traced, so it is replaced
/// as a cone stage.
void apply_isolated_verdicts(Report& end_to_end, const Report& isolated, bool soft_shadows);

/// The whole isolated judgement, as `vct validate` and `vct compare --scene` run it: the reference
/// re-traced on `test`'s inputs, judged against `test_set` (the stage set of `test`) with `opt`
/// (no masks by default) — where a cone stage fails there, again against the closest march end
/// (closest_march_end) — then applied to `end_to_end`; voxel.radiance too, on the test's shadow
/// maps and bounce input (reference_voxels_on_test_inputs), in a multibounce frame always, in a
/// single frame where the end-to-end verdict counted shading ties (the re-injection's cost).
void judge_cones_on_test_inputs(Report& end_to_end, const Scene& scene, const FrameResult& test, const VctSettings& s,
                                const StageSet& test_set, const CompareOptions& opt = {});

}  // namespace vct::cmp
