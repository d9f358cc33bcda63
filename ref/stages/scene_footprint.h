// What a loaded scene adds to the memory estimate (core/memory_budget.h), issue 37.
#pragma once

#include "core/memory_budget.h"
#include "scene/scene.h"

namespace vct {

/// Triangles, decoded texture bytes (every level of every texture), alpha tests and shadow layers.
SceneFootprint scene_footprint(const Scene& scene);

}  // namespace vct
