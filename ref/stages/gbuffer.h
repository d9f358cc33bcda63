// The camera G-buffer: the software rasterizer's closest surface per pixel centre, then the one
// surface definition (scene/surface.h: interpolation, textures, normal mapping) evaluated there.
#pragma once

#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct {

/// settings.width x settings.height view through scene.camera (projection aspect = width/height).
/// Normals face the camera: back-facing triangles (clockwise in window space, GL's
/// gl_FrontFacing == false) get their shading normal negated.
GBuffer render_gbuffer(const Scene& scene, const VctSettings& settings);

}  // namespace vct
