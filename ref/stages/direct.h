// Direct lighting from the punctual lights: Cook–Torrance and each kind's falloff from the shared header
// (vct::sh), visibility from the PCF shadow maps.
#pragma once

#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "shared/vct_shared.h"
#include "stages/stage_types.h"

namespace vct {

/// Radiance leaving `p` toward `view_dir` (unit, from p toward the viewer) from all lights:
/// sum over lights of f(l, v) * E(light) * max(n.l, 0) * shadow_visibility.
vec3 direct_radiance(const Scene& scene, const std::vector<ShadowMap>& maps, const VctSettings& settings, const vec3& p,
                     const vec3& n, const vec3& view_dir, const SurfaceMaterial& m);

/// Light i's term of direct_radiance before its shadow visibility: f(l, v) * E * n.l, or 0 where
/// n.l <= 0 or the light gives nothing (direct_radiance = sum of this times visibility).
vec3 unshadowed_light(const Scene& scene, size_t i, const VctSettings& settings, const vec3& p, const vec3& n,
                      const vec3& view_dir, const sh::SurfacePbr& pbr);

/// The BRDF's surface parameters of a G-buffer material (sh::surface_pbr).
sh::SurfacePbr surface_of(const SurfaceMaterial& m);

/// Lambertian outgoing radiance albedo * E / pi with E the shadowed irradiance (n.l included):
/// what voxel injection stores (the seed injects diffuse light only).
vec3 diffuse_outgoing_radiance(const Scene& scene, const std::vector<ShadowMap>& maps, const VctSettings& settings,
                               const vec3& p, const vec3& n, const vec3& albedo);

/// direct_radiance at every covered G-buffer pixel (0 elsewhere); emission is not included.
Image shade_direct(const Scene& scene, const GBuffer& g, const std::vector<ShadowMap>& maps,
                   const VctSettings& settings);

}  // namespace vct
