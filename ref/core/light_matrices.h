// An engine's shadow projections (settings shadow_view_proj and shadow_ortho_box, issue 21):
// per light, the full world -> clip matrix its shadow map was rendered with, or for a directional
// light the orthographic box it fits in the oracle's light view (stages/shadow_map.h,
// directional_light_view_proj: looking along the light from one volume edge behind the volume's
// centre). Entries are "LIGHT:numbers" separated by ';', LIGHT the light's index in the scene.
// A matrix is 16 numbers in GL's column-major order (glUniformMatrix4fv without transpose, glm's
// memory layout: m[column][row]); a box is left,right,bottom,top,near,far as glm::ortho takes them.
#pragma once

#include <array>
#include <map>
#include <string>

#include "core/math.h"

namespace vct {

/// Light index -> world -> clip matrix. Throws InputError("", "shadow_view_proj ...") for an entry
/// that is not "LIGHT:16 finite numbers" or a light given twice.
std::map<int, mat4> parse_light_matrices(const std::string& text);

/// Light index -> {left, right, bottom, top, near, far}. Throws InputError("", "shadow_ortho_box
/// ...") for a malformed entry, a light given twice, or an empty box (left >= right, bottom >= top,
/// near >= far).
std::map<int, std::array<float, 6>> parse_ortho_boxes(const std::string& text);

/// `m` as shadow_view_proj writes it (9 significant digits: reads back to the same floats).
std::string light_matrix_text(int light, const mat4& m);

}  // namespace vct
