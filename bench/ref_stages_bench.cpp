// Per-stage times of the CPU reference, part 1 (shadow maps .. mips), at 64^3, 128^3 and 256^3 on
// the built-in Cornell box (falls back to a procedural room if the loader fails). Prints a table;
// never passes or fails. Usage: ref_stages_bench [--threads N] [--grids 64,128] [--dump DIR]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "../tests/ref/stage_test_scene.h"
#include "core/parallel.h"
#include "io/run_dir.h"
#include "scene/gltf_loader.h"
#include "stages/direct.h"
#include "stages/dumps.h"
#include "stages/gbuffer.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

using namespace vct;

namespace {

struct Row {
  std::string stage;
  double ms;
  std::string note;
};

template <class F>
double timed(F&& f) {
  Stopwatch w;
  f();
  return w.ms();
}

}  // namespace

int main(int argc, char** argv) {
  int threads = 0;
  std::vector<int> grids = {64, 128, 256};
  std::string dump;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--dump") && i + 1 < argc) dump = argv[++i];
    else if (!std::strcmp(argv[i], "--grids") && i + 1 < argc) {
      grids.clear();
      for (char* t = std::strtok(argv[++i], ","); t; t = std::strtok(nullptr, ",")) grids.push_back(std::atoi(t));
    }
  }
  set_thread_count(threads);
  Scene scene;
  try {
    scene = load_scene("");
  } catch (const std::exception& e) {
    std::printf("load_scene(\"\") failed (%s); using the procedural room\n", e.what());
    scene = test::stage_room();
  }
  std::printf("scene %s: %zu triangles, %zu spot lights, %d threads\n", scene.source.c_str(), scene.triangle_count(),
              scene.lights.size(), thread_count());

  VctSettings st;  // defaults: 512x512, shadow map 2048^2
  std::vector<Row> rows;
  std::vector<ShadowMap> maps;
  GBuffer g;
  Image direct;
  rows.push_back({"shadow_maps", timed([&] { maps = render_shadow_maps(scene, st); }),
                  std::to_string(st.shadow_map_size) + "^2"});
  rows.push_back({"gbuffer", timed([&] { g = render_gbuffer(scene, st); }), "512x512"});
  rows.push_back({"direct", timed([&] { direct = shade_direct(scene, g, maps, st); }), "512x512"});
  std::printf("\n%-24s %10s   %s\n", "stage", "ms", "notes");
  for (const Row& r : rows) std::printf("%-24s %10.1f   %s\n", r.stage.c_str(), r.ms, r.note.c_str());

  for (int n : grids) {
    rows.clear();
    st.grid = n;
    Voxelization c, gp1, gp8;
    rows.push_back({"voxelize_conservative", timed([&] { c = voxelize_conservative(scene, n); }), ""});
    rows.back().note = std::to_string(c.covered) + " voxels, " + std::to_string(c.fragments.size()) + " fragments";
    rows.push_back({"voxelize_gpu_rule_1x", timed([&] { gp1 = voxelize_gpu_rule(scene, n, 1); }), ""});
    rows.push_back({"voxelize_gpu_rule_8x", timed([&] { gp8 = voxelize_gpu_rule(scene, n, 8); }), ""});
    Volume h1, h8;
    rows.push_back({"hole_map", timed([&] { h1 = hole_map(c, gp1); h8 = hole_map(c, gp8); }), ""});
    double holes1 = 0, holes8 = 0;
    for (size_t i = 0; i < h1.data.size(); ++i) holes1 += double(h1.data[i]), holes8 += double(h8.data[i]);
    rows[1].note = std::to_string(gp1.covered) + " voxels, " + std::to_string(int64_t(holes1)) + " holes";
    rows[2].note = std::to_string(gp8.covered) + " voxels, " + std::to_string(int64_t(holes8)) + " holes";
    VoxelGrid vg;
    for (Reduction r : {Reduction::ExactMean, Reduction::FixedPoint, Reduction::CasRgba8}) {
      st.reduction = r;
      rows.push_back({"inject_" + to_string(r), timed([&] { vg = inject_and_reduce(scene, c, maps, st); }), ""});
    }
    st.reduction = Reduction::ExactMean;
    vg = inject_and_reduce(scene, c, maps, st);
    VoxelMips iso, an;
    rows.push_back({"mips_iso", timed([&] { iso = build_mips(vg.radiance, false); }), ""});
    rows.back().note = std::to_string(mips_memory(iso, st.storage).gpu_bytes / 1024) + " KiB on GPU (" + to_string(st.storage) + ")";
    rows.push_back({"mips_aniso", timed([&] { an = build_mips(vg.radiance, true); }), ""});
    rows.back().note = std::to_string(mips_memory(an, st.storage).gpu_bytes / 1024) + " KiB on GPU";
    std::printf("\n-- grid %d^3 --\n", n);
    for (const Row& r : rows) std::printf("%-24s %10.1f   %s\n", r.stage.c_str(), r.ms, r.note.c_str());
    if (!dump.empty() && n == grids.front()) {
      FrameResult f;
      f.backend = "ref";
      f.shadow_maps = maps;
      f.gbuffer = g;
      f.images.direct = direct;
      f.conservative_occupancy = c.occupancy;
      f.holes = h8;
      f.voxels = vg;
      f.mips = an;
      RunDir dir(dump);
      write_frame_dumps(dir, f, scene);
      std::printf("dumps written to %s\n", dump.c_str());
    }
  }
  return 0;
}
