// Does each CPU stage's time grow no faster than its work? (issue 9: voxelization ~ triangles +
// fragments, mips ~ N^3, cones ~ pixels x steps.) Varies one size at a time on the built-in
// Cornell box (or argv[1]) and prints the time per unit of work; a flat column means linear
// scaling. Prints; never passes or fails.
// Usage: scaling_bench [SCENE] [--threads N] [--quick]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench_timing.h"
#include "core/parallel.h"
#include "io/run_dir.h"
#include "scene/gltf_loader.h"
#include "stages/cone_trace.h"
#include "stages/gbuffer.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

using namespace vct;
using vct::bench::best_ms;

namespace {

/// Splits every triangle into four at its edge midpoints, `levels` times: 4^levels as many
/// triangles over the same surface, so the voxels covered stay the same.
Scene tessellate(Scene s, int levels) {
  for (int l = 0; l < levels; ++l) {
    std::vector<uvec3> tris;
    std::vector<uint32_t> mats;
    for (size_t t = 0; t < s.triangles.size(); ++t) {
      const uvec3 v = s.triangles[t];
      auto midpoint = [&](uint32_t a, uint32_t b) {
        s.positions.push_back(0.5f * (s.positions[a] + s.positions[b]));
        s.normals.push_back(glm::normalize(s.normals[a] + s.normals[b]));
        if (!s.tangents.empty()) s.tangents.push_back(s.tangents[a]);
        if (!s.uv0.empty()) s.uv0.push_back(0.5f * (s.uv0[a] + s.uv0[b]));
        if (!s.uv1.empty()) s.uv1.push_back(0.5f * (s.uv1[a] + s.uv1[b]));
        return uint32_t(s.positions.size() - 1);
      };
      const uint32_t ab = midpoint(v.x, v.y), bc = midpoint(v.y, v.z), ca = midpoint(v.z, v.x);
      for (const uvec3& n : {uvec3(v.x, ab, ca), uvec3(ab, v.y, bc), uvec3(ca, bc, v.z), uvec3(ab, bc, ca)}) {
        tris.push_back(n);
        mats.push_back(s.triangle_material[t]);
      }
    }
    s.triangles = std::move(tris);
    s.triangle_material = std::move(mats);
  }
  return s;
}

void voxelization_vs_triangles(const Scene& scene, int max_level, int repeat) {
  std::printf("\n-- voxelization vs triangles (grid 128, same surface; ns per triangle and per fragment) --\n");
  std::printf("%10s %10s %12s %10s %10s %10s\n", "triangles", "fragments", "voxelizer", "ms", "ns/tri", "ns/frag");
  for (int level = 0; level <= max_level; ++level) {
    const Scene s = tessellate(scene, level);
    for (int msaa : {0, 8}) {  // 0: conservative
      Voxelization v;
      const double ms = best_ms(repeat, [&] { v = msaa ? voxelize_gpu_rule(s, 128, msaa) : voxelize_conservative(s, 128); });
      std::printf("%10zu %10zu %12s %10.1f %10.1f %10.1f\n", s.triangle_count(), v.fragments.size(),
                  msaa ? "gpu-rule 8x" : "conservative", ms, 1e6 * ms / double(s.triangle_count()),
                  1e6 * ms / double(v.fragments.size()));
    }
  }
}

void voxelization_vs_grid(const Scene& scene, const std::vector<int>& grids, int repeat) {
  std::printf("\n-- voxelization vs grid (same triangles; fragments grow ~ N^2) --\n");
  std::printf("%6s %10s %10s %12s %10s %10s\n", "grid", "fragments", "covered", "voxelizer", "ms", "ns/frag");
  for (int n : grids) {
    for (int msaa : {0, 8}) {
      Voxelization v;
      const double ms = best_ms(repeat, [&] { v = msaa ? voxelize_gpu_rule(scene, n, msaa) : voxelize_conservative(scene, n); });
      std::printf("%6d %10zu %10lld %12s %10.1f %10.1f\n", n, v.fragments.size(), static_cast<long long>(v.covered),
                  msaa ? "gpu-rule 8x" : "conservative", ms, 1e6 * ms / double(v.fragments.size()));
    }
  }
}

void mips_vs_grid(const Scene& scene, const std::vector<int>& grids, int repeat) {
  std::printf("\n-- mips vs N^3 (ns per base voxel) --\n");
  std::printf("%6s %12s %10s %10s %12s %10s\n", "grid", "voxels", "iso ms", "ns/vox", "aniso ms", "ns/vox");
  VctSettings st;
  st.shadow_map_size = 512;
  const std::vector<ShadowMap> maps = render_shadow_maps(scene, st);
  for (int n : grids) {
    st.grid = n;
    const VoxelGrid vg = inject_and_reduce(scene, voxelize_conservative(scene, n), maps, st);
    const double n3 = double(n) * n * n;
    const double iso = best_ms(repeat, [&] { build_mips(vg.radiance, false); });
    const double an = best_ms(repeat, [&] { build_mips(vg.radiance, true); });
    std::printf("%6d %12.0f %10.1f %10.2f %12.1f %10.2f\n", n, n3, iso, 1e6 * iso / n3, an, 1e6 * an / n3);
  }
}

/// One cone per covered pixel along its normal (the diffuse aperture) and the march's step count,
/// counted in a separate untimed pass.
struct ConeWork {
  std::vector<Cone> cones;
  double steps = 0.0;
};

ConeWork normal_cones(const Scene& scene, const GBuffer& g, const VoxelMips& mips, const MarchParams& mp, float aperture) {
  ConeWork w;
  for (int y = 0; y < g.coverage.height; ++y)
    for (int x = 0; x < g.coverage.width; ++x)
      if (g.coverage.at(x, y, 0) > 0.0f)
        w.cones.push_back({scene.volume.to_texture(g.position.rgb(x, y)), g.normal.rgb(x, y), aperture});
  std::vector<ConeSample> record;
  for (const Cone& c : w.cones) {
    record.clear();
    trace_cone(mips, c, mp, &record);
    w.steps += double(record.size());
  }
  return w;
}

void cones_vs_work(const Scene& scene, const std::vector<int>& sizes, const std::vector<int>& grids, int repeat) {
  std::printf("\n-- cone marching vs pixels x steps (one 30-degree cone per covered pixel; ns per step) --\n");
  std::printf("%6s %6s %10s %12s %10s %10s %10s\n", "image", "grid", "cones", "steps", "steps/cone", "ms", "ns/step");
  VctSettings st;
  st.shadow_map_size = 512;
  const std::vector<ShadowMap> maps = render_shadow_maps(scene, st);
  for (int n : grids) {
    st.grid = n;
    const VoxelMips mips = build_mips(inject_and_reduce(scene, voxelize_conservative(scene, n), maps, st).radiance, false);
    const MarchParams mp = MarchParams::from_settings(st, n);
    for (int size : sizes) {
      st.width = st.height = size;
      const ConeWork w = normal_cones(scene, render_gbuffer(scene, st), mips, mp, float(st.diffuse_aperture_deg) * 0.0174532925f);
      std::vector<float> sink(w.cones.size());
      const double ms = best_ms(repeat, [&] {
        parallel_for(int64_t(w.cones.size()), [&](int64_t i) { sink[size_t(i)] = trace_cone(mips, w.cones[size_t(i)], mp).a; });
      });
      std::printf("%6d %6d %10zu %12.0f %10.1f %10.1f %10.1f\n", size, n, w.cones.size(), w.steps,
                  w.steps / double(w.cones.size()), ms, 1e6 * ms / w.steps);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path;
  int threads = 0;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--quick")) quick = true;
    else scene_path = argv[i];
  }
  set_thread_count(threads);
  const Scene scene = load_scene(scene_path);
  std::printf("scene %s: %zu triangles, %d threads%s\n", scene.source.c_str(), scene.triangle_count(), thread_count(),
              quick ? " (quick)" : "");
  const int repeat = quick ? 1 : 3;
  const std::vector<int> grids = quick ? std::vector<int>{32, 64} : std::vector<int>{32, 64, 128, 256};
  voxelization_vs_triangles(scene, quick ? 1 : 3, repeat);
  voxelization_vs_grid(scene, grids, repeat);
  mips_vs_grid(scene, grids, repeat);
  cones_vs_work(scene, quick ? std::vector<int>{64} : std::vector<int>{128, 256, 512}, {quick ? 32 : 128}, repeat);
  cones_vs_work(scene, {quick ? 64 : 256}, grids, repeat);
  return 0;
}
