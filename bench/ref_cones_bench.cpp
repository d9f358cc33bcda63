// CPU reference stage timings: the built-in scene (or argv[1]) at 64^3, 128^3, 256^3, isotropic
// vs anisotropic, one frame each, per-stage milliseconds and the aniso/iso ratio of the cone
// stages. Prints; never passes or fails. Usage: ref_cones_bench [SCENE] [--size W] [--grids 64,128]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "scene/gltf_loader.h"
#include "freedoms/reference_frame.h"

namespace {

std::vector<int> parse_grids(const std::string& text) {
  std::vector<int> grids;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) grids.push_back(std::atoi(item.c_str()));
  return grids;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vct;
  std::string scene_path;
  int size = 128;
  std::vector<int> grids = {64, 128, 256};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc) {
      size = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--grids") && i + 1 < argc) {
      grids = parse_grids(argv[++i]);
    } else {
      scene_path = argv[i];
    }
  }
  const Scene scene = load_scene(scene_path);
  std::printf("scene %s, %dx%d pixels, %d threads\n", scene.source.c_str(), size, size, thread_count());
  std::map<std::string, std::map<std::string, double>> rows;  // column -> stage -> ms
  std::vector<std::string> columns;
  std::set<std::string> stages;
  for (int grid : grids) {
    for (bool aniso : {false, true}) {
      Settings s;
      s.vct.width = s.vct.height = size;
      s.vct.grid = grid;
      s.vct.anisotropic = aniso;
      s.vct.shadow_map_size = 1024;
      const FrameResult f = render_ref_frame(scene, s);
      const std::string col = std::to_string(grid) + (aniso ? " aniso" : " iso");
      columns.push_back(col);
      for (const auto& [stage, ms] : f.timings_ms) {
        rows[col][stage] = ms;
        stages.insert(stage);
      }
      std::fprintf(stderr, "  done %s\n", col.c_str());
    }
  }
  std::printf("%-24s", "stage [ms]");
  for (const std::string& c : columns) std::printf("%12s", c.c_str());
  std::printf("\n");
  for (const std::string& st : stages) {
    std::printf("%-24s", st.c_str());
    for (const std::string& c : columns) std::printf("%12.1f", rows[c].count(st) ? rows[c][st] : 0.0);
    std::printf("\n");
  }
  std::printf("\naniso / iso ratio of indirect_cones and mips:\n");
  for (int grid : grids) {
    const std::string iso = std::to_string(grid) + " iso", an = std::to_string(grid) + " aniso";
    std::printf("  %4d^3: cones %.2fx, mips %.2fx\n", grid, rows[an]["indirect_cones"] / rows[iso]["indirect_cones"],
                rows[an]["mips"] / rows[iso]["mips"]);
  }
  return 0;
}
