// The isotropic and anisotropic mip steps of the GL backend, judged on the test's own level below
// (docs/compare.md "Mip rounding"). gl/shaders/mip_iso.comp fetches the eight children with texelFetch, sums them
// in float, scales by 1/8 (exact) and rounds explicitly (gl/shaders/half_round.glsl: to nearest
// even for RGBA16F; to the nearest unorm8 step for RGBA8), so each stored value is a function of
// the children up to the float sum's rounding. Where the interval that rounding leaves holds no
// rounding midpoint, one value only is admissible: a store that truncates (GL fault
// half_truncate) or a filter that is not the box fails here although every value stays within the
// end-to-end mip bound. Only for our GL backend: GL leaves the rounding of a store's float->half
// conversion to the implementation, so another engine's mips are judged end to end only.
#pragma once

#include <cstddef>
#include <string>

#include "core/volume.h"

namespace vct::cmp {

struct MipRoundingCheck {
  size_t checked = 0;     // voxel channels compared
  size_t violations = 0;  // outside every value the rounded box filter of the children admits
  int worst_x = -1, worst_y = -1, worst_z = -1;  // the first violation, for the note
};

/// parent: level L (n³), child: the same test's level L-1 ((2n)³), storage "rgba16f" | "rgba8"
/// (anything else: nothing checked). Sizes that do not fit: nothing checked.
MipRoundingCheck check_iso_mip_rounding(const Volume& child, const Volume& parent, const std::string& storage);

/// The anisotropic step of gl/shaders/mip_aniso.comp for `direction` (AnisoDir: +x, −x, +y, −y,
/// +z, −z): along the direction's axis the front child is composited over the back one, the four
/// pairs are averaged, alpha is clamped to 1, then rounded as for the isotropic step. `child` is
/// the shared base level for level 1, else the same direction's level below.
MipRoundingCheck check_aniso_mip_rounding(const Volume& child, const Volume& parent, const std::string& storage,
                                          int direction);

}  // namespace vct::cmp
