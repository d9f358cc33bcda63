// Rays through the base voxel level: the exact counterpart of a cone (docs/attribution.md). A ray is
// the cone marcher (stages/cone_trace.h) with aperture 0: its diameter stays one voxel, so every
// lookup is at lod 0 (the base level, trilinear, GL 4.5 §8.14) and the front-to-back compositing
// is the same, with the same start offset and step (quality x one voxel). What a ray does not
// have is prefiltering: no mip level, no step that grows with the footprint.
#pragma once

#include <cstdint>

#include "core/math.h"
#include "stages/cone_trace.h"
#include "stages/mip_sampler.h"

namespace vct::attr {

/// Radiance (rgb) a ray from texture-space `origin` along unit `dir` gathers in the base level.
vec3 base_level_ray(const MipSampler& mips, const MarchParams& params, const vec3& origin, const vec3& dir);

/// The cone's own march (its start offset, its step = diameter x quality growing with distance,
/// its front-to-back compositing: stages/cone_trace.cpp) but every lookup at lod 0 on the cone's
/// axis: what the cone would gather without prefiltered levels. Splits VCT's prefiltering into
/// the step schedule (this vs rays filling the cone) and the mip lookups (VCT vs this).
vec3 base_level_cone_steps(const MipSampler& mips, const MarchParams& params, const Cone& cone);

/// A uniformly distributed direction (in solid angle) inside the cone of full opening
/// `aperture` around unit `axis`; u in [0,1)^2.
vec3 direction_in_cone(const vec3& axis, float aperture, vec2 u);

/// Seeds one pixel's random stream: independent for every (pixel, stream, seed, salt).
uint64_t pixel_seed(int x, int y, int width, uint32_t stream, uint32_t seed, uint32_t salt);

}  // namespace vct::attr
