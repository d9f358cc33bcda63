// The test frame behind a stage set, as far as the cone-traced stages need it, so that
// `vct compare A B --scene SCENE` can judge B's cone stages on B's own inputs like `vct validate`
// does (compare/isolated_stages.h) even when B is an external renderer's dump.
#pragma once

#include <string>
#include <vector>

#include "compare/stage_set.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::cmp {

/// The stages reference_on_test_inputs reads, for this scene and these settings: the G-buffer
/// (coverage, position, normal, albedo, material, specular_color, emission), image.direct (unless
/// soft shadows re-trace it), image.particles (when the scene has emitters and particles are on),
/// voxel.radiance and the full mip chain down to 1^3 (mip.iso.L, or the six mip.<dir>.L when
/// anisotropic).
std::vector<std::string> cone_input_stages(const Scene& scene, const VctSettings& s);

/// Rebuilds the test FrameResult from `set` (the cone inputs above, plus info and the outputs it
/// holds). Throws InputError (one line) naming the first missing stage, a size or channel count
/// that does not match `s` (width x height, grid^3, GL level sizes), or a scene that cannot be the
/// one B rendered (G-buffer positions that do not project to their pixels through the scene's
/// camera; a shadow-map count other than the scene's spot-light count).
/// A partial G-buffer (gbuffer.depth + gbuffer.normal, no gbuffer.position) is completed first
/// (compare/partial_gbuffer.h): position from depth, the other missing cone inputs from `reference`
/// (nullptr: none, so they are named as missing).
FrameResult frame_from_stage_set(const StageSet& set, const Scene& scene, const VctSettings& s,
                                 const StageSet* reference = nullptr);

}  // namespace vct::cmp
