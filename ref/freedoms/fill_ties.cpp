#include "freedoms/fill_ties.h"

#include "freedoms/coverage_ties.h"
#include "stages/voxel_fill.h"

namespace vct {

namespace {

size_t linear_index(const ivec3& v, int n) { return (size_t(v.z) * size_t(n) + size_t(v.y)) * size_t(n) + size_t(v.x); }

int facing_of(const Scene& scene, const VoxelFragment& f) {
  const uvec3 t = scene.triangles[f.triangle];
  return facing_direction(scene.positions[t.x], scene.positions[t.y], scene.positions[t.z]);
}

// One admissible extreme of the surface: its occupancy and facing masks.
struct SurfaceBound {
  std::vector<uint8_t> surface, masks;
  explicit SurfaceBound(size_t count) : surface(count, 0), masks(count, 0) {}
  void add(const Scene& scene, const VoxelFragment& f, int n) {
    const size_t i = linear_index(f.voxel, n);
    surface[i] = 1;
    masks[i] |= uint8_t(1u << facing_of(scene, f));
  }
};

// With the solid fill on: the surface's ties, less the voxels the reference fills (a fragment that
// may land there leaves them occupied; whether their fill may change is the judge's counted
// fill-ray rule).
Volume surface_ties_off_the_fill(const Scene& scene, const Voxelization& vox, int k, Volume ties) {
  const int n = vox.n;
  std::vector<uint8_t> surface(vox.occupancy.data.size());
  for (size_t i = 0; i < surface.size(); ++i) surface[i] = vox.occupancy.data[i] > 0.0f;
  const std::vector<uint8_t> masks = facing_masks(scene, vox);
  const std::vector<uint8_t> enclosed = enclosed_voxels(surface, masks, n);
  const std::vector<uint8_t> thick = k > 0 ? thickened_voxels(surface, masks, n, k) : std::vector<uint8_t>(surface.size(), 0);
  for (size_t i = 0; i < surface.size(); ++i)
    if (enclosed[i] || thick[i]) ties.data[i] = 0.0f;
  return ties;
}

}  // namespace

Volume occupancy_ties_with_fills(const Scene& scene, const Voxelization& vox, const VctSettings& settings) {
  Volume ties = occupancy_ties(vox);
  const int k = settings.surface_thickening_voxels;
  if (vox.may_drop.size() != vox.fragments.size() || (k <= 0 && !settings.solid_voxelization)) return ties;
  if (settings.solid_voxelization) return surface_ties_off_the_fill(scene, vox, k, std::move(ties));
  const int n = vox.n;
  const size_t count = size_t(n) * size_t(n) * size_t(n);
  SurfaceBound least(count), most(count);
  for (size_t i = 0; i < vox.fragments.size(); ++i) {
    most.add(scene, vox.fragments[i], n);
    if (!vox.may_drop[i]) least.add(scene, vox.fragments[i], n);
  }
  for (const VoxelFragment& f : vox.may_add) most.add(scene, f, n);
  const std::vector<uint8_t> thick_least = thickened_voxels(least.surface, least.masks, n, k);
  const std::vector<uint8_t> thick_most = thickened_voxels(most.surface, most.masks, n, k);
  for (size_t i = 0; i < count; ++i) {
    const bool may_be_occupied = most.surface[i] || thick_most[i];
    const bool may_be_empty = !least.surface[i] && !thick_least[i];
    if (may_be_occupied && may_be_empty) ties.data[i] = 1.0f;
  }
  return ties;
}

}  // namespace vct
