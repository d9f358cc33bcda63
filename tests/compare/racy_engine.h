// The synthetic foreign engine's voxels (issue 21): each voxel keeps the binary16 running mean of
// its fragments in reverse order with every third update lost (a racing store overwrote it), as
// the source design's non-atomic load/average/store can leave them. Shared by the foreign-engine
// tests.
#pragma once

#include <vector>

#include "core/volume.h"
#include "stages/running_mean.h"
#include "stages/voxelize.h"

namespace vct::cmp::test {

/// `base` with every voxel that has fragments replaced by that racy mean of `values` (one per
/// fragment of `vox`, sorted by voxel as the voxelizers emit them); opacity 1 there.
inline Volume racy_running_mean(const Voxelization& vox, const std::vector<vec3>& values, Volume base) {
  size_t b = 0;
  while (b < vox.fragments.size()) {
    size_t e = b;
    while (e < vox.fragments.size() && vox.fragments[e].voxel == vox.fragments[b].voxel) ++e;
    vec4 out(0.0f, 0.0f, 0.0f, 1.0f);
    for (int k = 0; k < 3; ++k) {
      std::vector<float> kept;
      for (size_t i = e; i-- > b;)
        if ((i - b) % 3 != 2) kept.push_back(values[i][k]);
      out[k] = running_mean_half_sequential(kept);
    }
    const ivec3 c = vox.fragments[b].voxel;
    base.set_rgba(c.x, c.y, c.z, out);
    b = e;
  }
  return base;
}

}  // namespace vct::cmp::test
