#include "compare/metamorphic_map.h"

#include <algorithm>
#include <iterator>

#include "scene/scene_transform.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace st = stage_names;

namespace {

// Every pixel's first three channels through `f` (world-space G-buffer attributes).
template <class F>
void map_rgb(Image& img, F f) {
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) img.set_rgb(x, y, f(img.rgb(x, y)));
}

// Base voxel -> test voxel, for a volume of n^3 voxels; nullopt-like (-1) outside.
template <class IndexMap>
Volume remap(const Volume& test, IndexMap to_test) {
  Volume out(test.nx, test.ny, test.nz, test.channels);
  out.channel_names = test.channel_names;
  for (int z = 0; z < test.nz; ++z)
    for (int y = 0; y < test.ny; ++y)
      for (int x = 0; x < test.nx; ++x) {
        const ivec3 j = to_test(ivec3(x, y, z), test.nx);
        if (!test.contains(j.x, j.y, j.z)) continue;  // brought in from outside: stays 0
        const float* src = test.voxel(j.x, j.y, j.z);
        std::copy(src, src + test.channels, out.voxel(x, y, z));
      }
  return out;
}

// Mip level of a volume stage (0 for voxel.*).
int level_of(const std::string& stage) {
  const auto ref = find_stage(stage);
  return ref && ref->row->index == StageIndex::MipLevel ? ref->index : 0;
}

bool is_cube(const Volume& v) {
  return v.nx == v.ny && v.ny == v.nz;
}

}  // namespace

StageSet untranslated(const StageSet& test, const vec3& t) {
  StageSet out = test;
  auto pos = out.images.find(st::kGbufferPosition);
  if (pos != out.images.end()) {
    const Image& coverage =
        out.images.count(st::kGbufferCoverage) ? out.images.at(st::kGbufferCoverage) : Image();
    Image& p = pos->second;
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < p.width; ++x)  // uncovered pixels hold zeros on both sides
        if (coverage.empty() || coverage.at(x, y, 0) > 0.0f) p.set_rgb(x, y, p.rgb(x, y) - t);
  }
  return out;
}

StageSet unshifted(const StageSet& test, const ivec3& k, const vec3& t, bool soft_shadows) {
  StageSet out = untranslated(test, t);
  for (auto it = out.images.begin(); it != out.images.end();) {
    const auto ref = find_stage(it->first);
    const bool cone = ref && judged_on_own_inputs(*ref->row, soft_shadows);
    it = cone ? out.images.erase(it) : std::next(it);
  }
  for (auto it = out.volumes.begin(); it != out.volumes.end();) {
    const int step = 1 << level_of(it->first);
    if (k.x % step || k.y % step || k.z % step || !is_cube(it->second)) {
      it = out.volumes.erase(it);
      continue;
    }
    const ivec3 kl = k / step;
    it->second = remap(it->second, [kl](const ivec3& i, int) { return i + kl; });
    ++it;
  }
  return out;
}

ivec3 turned_voxel(const ivec3& i, int n, int axis) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  ivec3 j = i;
  j[c] = i[b];
  j[b] = n - 1 - i[c];
  return j;
}

StageSet unturned(const StageSet& test, int axis) {
  StageSet out = test;
  auto back = [axis](const vec3& v) { return unturn90(v, axis); };
  for (auto it = out.images.begin(); it != out.images.end();) {
    const auto ref = find_stage(it->first);
    if (ref && ref->row->index == StageIndex::Light) {
      it = out.images.erase(it);
      continue;
    }
    if (it->first == st::kGbufferPosition || it->first == st::kGbufferNormal)
      map_rgb(it->second, back);
    ++it;
  }
  auto index_map = [axis](const ivec3& i, int n) { return turned_voxel(i, n, axis); };
  for (auto& [stage, vol] : out.volumes) {
    if (!is_cube(vol)) continue;
    const auto ref = find_stage(stage);
    const int dir = ref ? aniso_direction(*ref->row) : -1;
    if (dir < 0) {
      vol = remap(vol, index_map);
      continue;
    }
    // Direction d of the base frame is direction turn(d) of the turned one.
    vec3 e(0.0f);
    e[dir / 2] = dir % 2 ? -1.0f : 1.0f;
    const vec3 te = turn90(e, axis);
    const int ta = te.x != 0.0f ? 0 : te.y != 0.0f ? 1 : 2;
    const int tdir = 2 * ta + (te[ta] < 0.0f ? 1 : 0);
    const std::string source = stage_name(mip_row(tdir), ref->index);
    vol = remap(test.volumes.at(source), index_map);
  }
  return out;
}

size_t keep_turn_invariant_cones(StageSet& mapped, const StageSet& base, int diffuse_cone_count) {
  auto normal = base.images.find(st::kGbufferNormal);
  if (normal == base.images.end()) return 0;
  const Image& n = normal->second;
  const bool quarter_steps = (diffuse_cone_count - 1) % 4 == 0;
  auto axis_aligned = [](const vec3& v) {
    return int(v.x == 0.0f) + int(v.y == 0.0f) + int(v.z == 0.0f) == 2;
  };
  size_t left_out = 0;
  for (int y = 0; y < n.height; ++y)
    for (int x = 0; x < n.width; ++x) {
      if (quarter_steps && axis_aligned(n.rgb(x, y))) continue;
      ++left_out;
      for (const char* stage :
           {st::kImageIndirectDiffuse, st::kImageDiffuseTerm, st::kImageFinal}) {
        auto m = mapped.images.find(stage);
        auto b = base.images.find(stage);
        if (m == mapped.images.end() || b == base.images.end() || b->second.width != n.width)
          continue;
        std::copy(b->second.pixel(x, y), b->second.pixel(x, y) + b->second.channels,
                  m->second.pixel(x, y));
      }
    }
  return left_out;
}

StageSet common_stages(const StageSet& a, const StageSet& with) {
  StageSet out = a;
  for (auto it = out.images.begin(); it != out.images.end();)
    it = with.images.count(it->first) ? std::next(it) : out.images.erase(it);
  for (auto it = out.volumes.begin(); it != out.volumes.end();)
    it = with.volumes.count(it->first) ? std::next(it) : out.volumes.erase(it);
  return out;
}

}  // namespace vct::cmp
