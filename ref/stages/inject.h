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

/// The light each fragment carries: diffuse_outgoing_radiance (shading normal after normal
/// mapping) + emission (+ bounce). Fragment order as in `vox`.
std::vector<vec3> fragment_radiance(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                                    const VctSettings& settings, const BounceLight* bounce = nullptr);

/// Per fragment, the largest |change| (over RGB) of its light when every textured slot is looked
/// up at the other lambdas a correct GL may use in the voxel raster (stages/voxel_lod.h), against
/// `values` (fragment_radiance). 0 for untextured materials.
std::vector<float> fragment_lod_slack(const Scene& scene, const Voxelization& vox,
                                      const std::vector<vec3>& values,
                                      const std::vector<ShadowMap>& maps,
                                      const VctSettings& settings,
                                      const BounceLight* bounce = nullptr);

/// Per voxel, the mean of its fragments' slacks (a bound on how far the voxel's mean may move).
Volume voxel_lod_slack(const Voxelization& vox, const std::vector<float>& slack);

/// Level-0 voxels: RGB from settings.reduction over the voxel's fragments, A = 1 where occupied
/// (and where stages/voxel_fill.h adds the solid interior or thickening),
/// then settings.storage quantization; `fragments` counts; cas_lo/cas_hi for Reduction::CasRgba8;
/// texture_slack (voxel_lod_slack) when a material has a texture.
VoxelGrid inject_and_reduce(const Scene& scene, const Voxelization& vox, const std::vector<ShadowMap>& maps,
                            const VctSettings& settings, const BounceLight* bounce = nullptr);

/// The reduction alone, from per-fragment values (same order as vox.fragments).
VoxelGrid reduce_fragments(const Voxelization& vox, const std::vector<vec3>& values, const VctSettings& settings);

}  // namespace vct
