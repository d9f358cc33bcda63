// Light injection and per-voxel reduction: the light leaving each voxel fragment (diffuse direct
// light with shadow maps + emission [+ a bounce term]) combined per voxel by the settings'
// reduction and quantized to the settings' storage format.
#pragma once

#include <functional>
#include <vector>

#include "core/settings.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "stages/stage_types.h"
#include "stages/voxelize.h"

namespace vct {

/// Extra light leaving a fragment (multibounce: restitution * albedo * indirect from the previous
/// frame's mips). Called concurrently; must be thread-safe and deterministic.
using BounceLight = std::function<vec3(const VoxelFragment&, const SurfaceMaterial&)>;

/// The light leaving one fragment with material `m`: diffuse_outgoing_radiance (shading normal)
/// + emission (+ bounce).
vec3 light_leaving(const Scene& scene, const VoxelFragment& f, const SurfaceMaterial& m,
                   const std::vector<ShadowMap>& maps, const VctSettings& settings,
                   const BounceLight* bounce);

/// The light each fragment carries: diffuse_outgoing_radiance (shading normal after normal
/// mapping) + emission (+ bounce). Fragment order as in `vox`.
std::vector<vec3> fragment_radiance(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                                    const VctSettings& settings, const BounceLight* bounce = nullptr);

/// Level-0 voxels: RGB from settings.reduction over the voxel's fragments, A = 1 where occupied
/// (and where stages/voxel_fill.h adds the solid interior or thickening), then settings.storage
/// quantization; `fragments` counts. `values_out`, when given, receives each fragment's light
/// (fragment_radiance). The judge's volumes beside the voxels (shading slack, exactness, the
/// reduction's interval) are the oracle's own work: freedoms/voxel_freedoms.h.
VoxelGrid inject_and_reduce(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                            const VctSettings& settings, const BounceLight* bounce = nullptr,
                            std::vector<vec3>* values_out = nullptr);

/// reduce_fragments, then stages/voxel_fill.h's opacity: the grid inject_and_reduce makes from `values`.
VoxelGrid reduce_and_fill(const Scene& scene, const Voxelization& vox, const std::vector<vec3>& values,
                          const VctSettings& settings);

/// The reduction alone, from per-fragment values (same order as vox.fragments).
VoxelGrid reduce_fragments(const Voxelization& vox, const std::vector<vec3>& values, const VctSettings& settings);

}  // namespace vct
