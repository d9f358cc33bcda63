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

namespace vct::cmp {

/// The reference's cone-traced images computed from `test`'s G-buffer, direct light, particles
/// and mips; the other stages are copied from `test`. Soft shadows (cone-traced direct light)
/// are re-traced too when enabled. `display`: the test's declared display transform; when it
/// names image.direct, the composite adds that image decoded to linear light
/// (DisplayTransform::decode; decode_display_direct).
FrameResult reference_on_test_inputs(const Scene& scene, const FrameResult& test, const VctSettings& s,
                                     const DisplayTransform* display = nullptr);

/// How the test's image.direct enters the re-traced composite under a declared display
/// transform: as it is (not display-encoded), decoded (a concave transform: image.final's bound
/// grows by one step), or not at all (a transform no decoded value can be bounded through:
/// image.final keeps its end-to-end verdict).
enum class DirectInput { Linear, Decoded, Undecodable };
DirectInput direct_input_of(const DisplayTransform* display);

/// `direct` (display-encoded by `display`, colour channels) decoded to linear light in place.
void decode_display_direct(const DisplayTransform& display, Image& direct);

/// A multibounce frame's voxels as the reference computes them from the test's own bounce input:
/// its last frame injected again with the bounce light traced in mips it builds from
/// test.bounce_input (the test's frame before the last), particles added. End to end, every
/// voxel the test's earlier frames legitimately moved (a tie, a shading slack) changes the bounce
/// light of its neighbours, and the reference's own frames cannot show that. Nullopt when the test
/// ran one frame (no bounce input).
std::optional<VoxelGrid> reference_voxels_on_test_bounce_input(const Scene& scene, const FrameResult& test,
                                                              const VctSettings& s);

/// For every cone-traced stage, replaces the end-to-end verdict by the isolated one (stage judged
/// on the test's own inputs) and keeps the end-to-end verdict in the note and in
/// extra["end_to_end"], so a cone stage fails only when the test's marcher is wrong.
/// `soft_shadows`: direct light was cone-traced, so it is replaced too.
void apply_isolated_verdicts(Report& end_to_end, const Report& isolated, bool soft_shadows);

/// The whole isolated judgement, as `vct validate` and `vct compare --scene` run it: the reference
/// re-traced on `test`'s inputs, judged against `test_set` (the stage set of `test`) with `opt`
/// (no masks by default), then applied to `end_to_end`; in multibounce frames voxel.radiance too
/// (reference_voxels_on_test_bounce_input).
void judge_cones_on_test_inputs(Report& end_to_end, const Scene& scene, const FrameResult& test, const VctSettings& s,
                                const StageSet& test_set, const CompareOptions& opt = {});

}  // namespace vct::cmp
