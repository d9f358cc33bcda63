// A diffuse cone set given as data (setting diffuse_cone_set, issue 21): an engine's own cones,
// each a direction in the tangent frame (x = tangent, y = bitangent, z = surface normal), a full
// aperture in degrees and a weight, written "x,y,z,aperture_deg,weight" and separated by
// whitespace. The source design's set (righier/gidemo voxelcone.frag TraceDiffuse) is
// "0,0,1,30,1 1,0,1,30,1 -1,0,1,30,1 0,1,1,30,1 0,-1,1,30,1": five cones at 45 degrees, summed.
// Empty text keeps the oracle's set from diffuse_cone_count / diffuse_cone_tilt_deg
// (stages/cone_sets.h).
#pragma once

#include <string>
#include <vector>

#include "core/math.h"

namespace vct {

struct DeclaredCone {
  vec3 direction{0.0f, 0.0f, 1.0f};  // unit, tangent frame
  float aperture_deg = 30.0f;       // full opening angle
  float weight = 1.0f;
};

/// The cones of `text` in order, directions normalised. Throws InputError("", "diffuse_cone_set
/// ...") for an entry that is not five finite numbers, a zero or downward (z < 0) direction, an
/// aperture outside (0, 180), a negative weight, or more than 16 cones (sh::MAX_DIFFUSE_CONES).
std::vector<DeclaredCone> parse_declared_cones(const std::string& text);

}  // namespace vct
