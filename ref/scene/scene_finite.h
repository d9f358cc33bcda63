// The last check of a loaded scene (issue 38): every number the renderers read from a light, the
// camera or an emitter is finite after conversion to float and after the node transforms, so a
// light of intensity 1e39 (finite as the file's double, Inf as a float) or a transform chain that
// overflows float is refused with the object's name instead of rendering NaN or black with exit 0.
#pragma once

#include <string>

#include "scene/scene.h"

namespace vct {

/// Throws InputError(file, ...) naming the first light, camera or emitter with a non-finite value,
/// or a light whose intensity × colour overflows float.
void check_scene_finite(const Scene& scene, const std::string& file);

}  // namespace vct
