// Tangent frames for meshes that do not bring their own: per-triangle UV-gradient tangents
// accumulated per vertex, then Gram-Schmidt against the vertex normal. This is not MikkTSpace
// (which glTF names); docs/scenes.md says where the two differ.
#pragma once

#include <vector>

#include "core/math.h"

namespace vct {

/// A unit vector perpendicular to unit `n` (deterministic; used where UVs give no direction).
vec3 any_perpendicular(const vec3& n);

/// Tangents (xyz unit, w = handedness) for every vertex. `uv` may be empty (then tangents are
/// any_perpendicular(normal), w = +1). Triangles whose UVs are degenerate do not contribute.
std::vector<vec4> generate_tangents(const std::vector<vec3>& positions, const std::vector<vec3>& normals,
                                    const std::vector<vec2>& uv, const std::vector<uvec3>& triangles);

/// Re-orthogonalizes a given tangent against `n` (Gram-Schmidt); falls back to any_perpendicular
/// when the tangent is (nearly) parallel to the normal.
vec4 orthogonalize_tangent(const vec3& n, const vec4& t);

}  // namespace vct
