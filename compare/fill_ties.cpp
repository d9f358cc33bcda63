#include "compare/fill_ties.h"

namespace vct::cmp {

std::vector<uint8_t> surface_differences(const Volume& ref_fragments, const Volume& test_fragments) {
  std::vector<uint8_t> out(ref_fragments.voxel_count(), 0);
  for (size_t i = 0; i < out.size(); ++i) {
    const float r = ref_fragments.data[i * size_t(ref_fragments.channels)];
    const float t = test_fragments.data[i * size_t(test_fragments.channels)];
    out[i] = r != t ? 1 : 0;
  }
  return out;
}

bool ray_meets(const Volume& grid, const std::vector<uint8_t>& differs, size_t i) {
  const int x = int(i % size_t(grid.nx)), y = int((i / size_t(grid.nx)) % size_t(grid.ny)),
            z = int(i / (size_t(grid.nx) * size_t(grid.ny)));
  static constexpr int kSteps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& d : kSteps)
    for (int xx = x + d[0], yy = y + d[1], zz = z + d[2]; grid.contains(xx, yy, zz);
         xx += d[0], yy += d[1], zz += d[2])
      if (differs[(size_t(zz) * size_t(grid.ny) + size_t(yy)) * size_t(grid.nx) + size_t(xx)]) return true;
  return false;
}

}  // namespace vct::cmp
