// Tangent handedness ties (docs/compare.md, "Tangent handedness"): glTF 2.0 gives TANGENT's w, the
// bitangent's sign (+1 or -1), per vertex (§3.7.2.1, "XYZW vertex tangents where ... W is a sign
// value indicating handedness") and defines nothing between vertices that disagree. A triangle
// whose vertices disagree (a mesh mirrored in UV across it; our generated tangents, which are
// per vertex, not split per corner as MikkTSpace's) has no defined handedness inside: the
// reference takes vertex 0's sign (scene/surface.cpp), a GL interpolating the vec4 takes the sign
// of the interpolated w, the Khronos sample viewer normalizes the interpolated cross(n, t) w. Each
// gives one of the two signs at every point, so where a normal map is read on such a triangle
// both bitangents are admissible.
#pragma once

#include <cstdint>

#include "scene/scene.h"
#include "scene/surface.h"

namespace vct {

/// True when `triangle` has tangents whose handedness (sign of w) differs between its vertices.
bool tangent_handedness_mixed(const Scene& scene, uint32_t triangle);

/// True when the handedness tie matters at `triangle`: its handedness is mixed and its material
/// reads a normal map (only the normal map uses the bitangent).
bool handedness_may_flip(const Scene& scene, uint32_t triangle);

/// `p` with the other handedness (its tangent's w negated): the other admissible bitangent.
SurfacePoint with_other_handedness(SurfacePoint p);

}  // namespace vct
