// GL's cube-map addressing (GL 4.5 §8.13, "Cube Map Texture Selection", Table 8.19), written out
// plainly for the point lights' shadow cubes: which face a direction selects, where on that face it
// lands, and the inverse (the direction through a face coordinate). The GL side has its own copy in
// gl/shaders/lights.glsl on purpose (docs/pipeline.md, "Shadow maps": point lights).
#pragma once

#include "core/math.h"

namespace vct {

/// One row of Table 8.19: the face's outward major axis, and the world axes that sc and tc read
/// (sc = dot(r, sc_axis), tc = dot(r, tc_axis), ma = dot(r, major_axis) > 0 on the face).
struct CubeFaceAxes {
  vec3 major_axis;
  vec3 sc_axis;
  vec3 tc_axis;
};

/// Face f in GL's order +x, -x, +y, -y, +z, -z (TEXTURE_CUBE_MAP_POSITIVE_X + f).
const CubeFaceAxes& cube_face_axes(int face);

/// The face a direction selects: its largest-magnitude coordinate. The spec leaves ties to the
/// implementation ("the rule must be deterministic and depend only on (rx, ry, rz)"); we choose x
/// over y over z on equal magnitudes (also Mesa's rule), and so does lights.glsl.
int cube_face(const vec3& r);

/// Face coordinates of r on `face`: s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2 (equation 8.6);
/// t = 0 is the bottom row of the face image (GL texture space).
vec2 cube_face_st(int face, const vec3& r);

/// The direction through face coordinate (s, t) of `face` (not unit; its major component is 1):
/// the inverse of cube_face_st, also for coordinates past the face's edge.
vec3 cube_face_direction(int face, const vec2& st);

/// A texel of a `size`² cube face addressed from face `home`, possibly past its edge.
struct CubeTexel {
  int face, x, y;
};
/// Texel (x, y) of face `home` as a cube lookup reads it: itself when inside the face; past the
/// edge, the face and texel the direction through that virtual texel's centre selects (GL's own
/// selection, so a PCF tap lands where a cube lookup would).
CubeTexel cube_texel(int home, int x, int y, int size);

/// World -> clip space of face f of a cube centred at `center`: a 90 degree square perspective
/// whose NDC x, y are the face's sc/|ma|, tc/|ma| (so window (x, y) is the face's (s, t) texel).
mat4 cube_face_view_proj(int face, const vec3& center, float near_plane, float far_plane);

}  // namespace vct
