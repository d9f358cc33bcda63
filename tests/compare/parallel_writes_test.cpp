// The stage-set and bias writers run one task per file (docs/performance.md, "Where validate's
// time goes"): the files, the manifest and the measured numbers must be the same bytes for 1, 2
// and 8 threads, and the same as the sequential writer's (1 thread).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <map>
#include <string>

#include "compare/bias.h"
#include "compare/stage_set.h"
#include "core/parallel.h"
#include "io/atomic_file.h"

namespace vct::cmp {
namespace {

namespace fs = std::filesystem;

// Every file under `dir` (relative name -> bytes).
std::map<std::string, std::string> files_under(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = read_file(e.path().string());
  return out;
}

Image ramp(int w, int h, int c, float scale) {
  Image img(w, h, c);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = scale * float((i * 2654435761u) % 1000u) / 1000.0f;
  return img;
}

StageSet some_stages() {
  StageSet s;
  s.backend = "ref";
  for (const char* name : {"image.final", "image.direct", "image.indirect_diffuse", "image.indirect_specular",
                           "image.emission", "gbuffer.normal", "gbuffer.position", "gbuffer.depth"})
    s.images[name] = ramp(40, 24, std::string(name) == "gbuffer.depth" ? 1 : 3, 2.0f);
  Volume v(8, 8, 8, 4);
  for (size_t i = 0; i < v.data.size(); ++i) v.data[i] = float(i % 17) / 16.0f;
  s.volumes["voxel.radiance"] = v;
  s.volumes["mip.iso.1"] = Volume(4, 4, 4, 4);
  return s;
}

struct Written {
  std::map<std::string, std::string> files;
  std::string bias;
};

Written write_with(int threads) {
  set_thread_count(threads);
  const std::string dir =
      (fs::temp_directory_path() / ("vct_parallel_writes_" + std::to_string(::getpid()) + "_" + std::to_string(threads)))
          .string();
  fs::remove_all(dir);
  StageSet s = some_stages();
  write_stage_set(dir + "/set", s);
  std::map<std::string, Image> pt;
  for (const auto& [stage, aov] : bias_pairs()) {
    pt[aov] = ramp(40, 24, 3, 1.5f);
    pt[aov + "_var"] = ramp(40, 24, 3, 0.01f);
  }
  nlohmann::json bias = nlohmann::json::array();
  for (const BiasComponent& b : measure_bias(s, pt, {3.0, dir + "/bias", "bias/"})) bias.push_back(to_json(b));
  Written w{files_under(dir), bias.dump()};
  fs::remove_all(dir);
  set_thread_count(0);
  return w;
}

TEST(ParallelWrites, SameBytesFor1_2_8Threads) {
  const Written one = write_with(1);
  // 10 stages (EXR/NRRD + PNG each) + manifest; a heat and a z map per available bias component.
  EXPECT_EQ(one.files.count("set/vct-stages.json"), 1u);
  EXPECT_EQ(one.files.count("set/image_final.exr") + one.files.count("set/image_final.png") +
                one.files.count("set/voxel_radiance.nrrd") + one.files.count("set/voxel_radiance.png"),
            4u);
  EXPECT_GE(one.files.size(), 21u);
  EXPECT_EQ(one.files.count("bias/full_heat.png") + one.files.count("bias/full_z.png"), 2u);
  for (int threads : {2, 8}) {
    const Written w = write_with(threads);
    EXPECT_EQ(w.bias, one.bias) << threads << " threads";
    ASSERT_EQ(w.files.size(), one.files.size()) << threads << " threads";
    for (const auto& [name, bytes] : one.files) {
      ASSERT_TRUE(w.files.count(name)) << name;
      EXPECT_TRUE(w.files.at(name) == bytes) << name << " differs with " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace vct::cmp
