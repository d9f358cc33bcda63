// tools/vct_dump/vct_dump.h: a stage set written from CPU buffers (as an engine would after its
// read-backs) reads back value for value through the stage-set reader, rows the right way up,
// and `vct compare` judges it: exit 0 against a reference holding the same values, 1 with one
// voxel off, 2 for a manifest naming a convention that does not exist. 4-channel images (EXR) and
// the nested display convention read back, and the display transform is what `vct compare` judges
// a tone-mapped 8-bit final with.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "compare/stage_compare.h"
#include "find_verdict.h"
#include "vct_dump.h"

namespace vct::cmp {
namespace {

namespace fs = std::filesystem;

constexpr int kW = 4, kH = 3, kN = 4;

// A 4x3 RGB image given bottom row first (a GL read-back): value = 100*row_from_top + 10*x + c.
std::vector<float> bottom_first_rgb() {
  std::vector<float> v(size_t(kW * kH * 3));
  for (int yb = 0; yb < kH; ++yb)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) v[size_t((yb * kW + x) * 3 + c)] = float(100 * (kH - 1 - yb) + 10 * x + c);
  return v;
}

// RGBA voxels: occupied on the x = 1 plane with light depending on (y, z).
std::vector<float> voxels() {
  std::vector<float> v(size_t(kN * kN * kN * 4), 0.0f);
  for (int z = 0; z < kN; ++z)
    for (int y = 0; y < kN; ++y) {
      float* p = &v[size_t((((z * kN + y) * kN) + 1) * 4)];
      p[0] = 0.1f * float(y), p[1] = 0.05f * float(z), p[2] = 0.25f, p[3] = 1.0f;
    }
  return v;
}

std::string dump(const std::string& name, const std::vector<float>& vox) {
  const std::string dir = (fs::temp_directory_path() / ("vct_dump_test_" + name)).string();
  fs::remove_all(dir);
  fs::create_directories(dir);
  vct_dump::StageSetWriter w(dir, "dump-test");
  w.set_storage("rgba32f");
  w.set_reduction("exact_mean");
  w.set_setting("grid", kN);
  w.set_fact("renderer", "unit test");
  w.set_fact("msaa_samples", 4);
  w.set_convention("mip_scale", 1.0);
  const std::vector<float> rgb = bottom_first_rgb();
  EXPECT_TRUE(w.image("image.final", kW, kH, 3, rgb.data(), vct_dump::Rows::BottomFirst)) << w.error();
  const std::vector<float> depth(size_t(kW * kH), 0.5f);
  EXPECT_TRUE(w.image("shadow_map.0", kW, kH, 1, depth.data(), vct_dump::Rows::TopFirst)) << w.error();
  EXPECT_TRUE(w.volume("voxel.radiance", kN, kN, kN, 4, vox.data())) << w.error();
  EXPECT_TRUE(w.finish()) << w.error();
  return dir;
}

TEST(VctDump, ReadsBackValueForValueRowZeroOnTop) {
  const std::vector<float> vox = voxels();
  const StageSet s = read_stage_set(dump("values", vox));
  EXPECT_EQ(s.backend, "dump-test");
  EXPECT_EQ(s.facts.msaa_samples, 4);
  EXPECT_EQ(s.facts.renderer, "unit test");
  EXPECT_EQ(s.settings.value("grid", 0), kN);
  const Image& img = s.images.at("image.final");
  ASSERT_EQ(img.width, kW);
  ASSERT_EQ(img.height, kH);
  ASSERT_EQ(img.channels, 3);
  // Row 0 = top: the value 100*0 + 10*x + c there; the bottom row is 200 + ...
  EXPECT_EQ(img.at(2, 0, 1), 21.0f);
  EXPECT_EQ(img.at(3, kH - 1, 2), 232.0f);
  EXPECT_EQ(s.images.at("shadow_map.0").at(1, 1, 0), 0.5f);
  const Volume& v = s.volumes.at("voxel.radiance");
  ASSERT_EQ(v.channels, 4);
  EXPECT_EQ(v.data, vox);
}

TEST(VctDump, RejectsChannelCountsNoImageHolds) {
  vct_dump::StageSetWriter w(fs::temp_directory_path().string(), "x");
  const std::vector<float> five(20, 0.0f);
  EXPECT_FALSE(w.image("gbuffer.material", 2, 2, 5, five.data(), vct_dump::Rows::TopFirst));
  EXPECT_FALSE(w.finish());
  EXPECT_NE(w.error().find("1 to 4 channels"), std::string::npos);
}

// gbuffer.material (4 channels) and a 2-channel image go to OpenEXR, which PFM cannot hold:
// value = 100*row_from_top + 10*x + c, given bottom row first, read back top first.
TEST(VctDump, FourAndTwoChannelImagesReadBackThroughExr) {
  const std::string dir = (fs::temp_directory_path() / "vct_dump_test_rgba").string();
  fs::remove_all(dir);
  fs::create_directories(dir);
  vct_dump::StageSetWriter w(dir, "dump-test");
  for (int channels : {4, 2}) {
    std::vector<float> v(size_t(kW * kH * channels));
    for (int yb = 0; yb < kH; ++yb)
      for (int x = 0; x < kW; ++x)
        for (int c = 0; c < channels; ++c)
          v[size_t((yb * kW + x) * channels + c)] = float(100 * (kH - 1 - yb) + 10 * x + c) + 0.25f;
    const std::string stage = channels == 4 ? "gbuffer.material" : "image.two";
    EXPECT_TRUE(w.image(stage, kW, kH, channels, v.data(), vct_dump::Rows::BottomFirst)) << w.error();
  }
  ASSERT_TRUE(w.finish()) << w.error();
  const StageSet s = read_stage_set(dir);
  const Image& m = s.images.at("gbuffer.material");
  ASSERT_EQ(m.width, kW);
  ASSERT_EQ(m.height, kH);
  ASSERT_EQ(m.channels, 4);
  EXPECT_EQ(m.at(2, 0, 0), 20.25f);   // top row, x = 2, R
  EXPECT_EQ(m.at(2, 0, 3), 23.25f);   // A stays the 4th channel although the file stores A first
  EXPECT_EQ(m.at(3, kH - 1, 1), 231.25f);
  const Image& t = s.images.at("image.two");
  ASSERT_EQ(t.channels, 2);
  EXPECT_EQ(t.at(1, 1, 1), 111.25f);
}

// colour_image_from_gl asks GL for as many channels as it writes (GL_RGBA for 4) and flips GL's
// bottom-first rows; settings of any arithmetic type (size_t, float) are written as numbers.
TEST(VctDump, ColourImageFromGlAsksForItsChannelsAndFlipsRows) {
  const std::string dir = (fs::temp_directory_path() / "vct_dump_test_from_gl").string();
  fs::remove_all(dir);
  fs::create_directories(dir);
  vct_dump::StageSetWriter w(dir, "dump-test");
  w.set_setting("grid", size_t(kN));
  w.set_setting("cone_quality", 0.5f);
  unsigned asked_format = 0;
  int asked_bytes = 0;
  auto fake_get_texture_image = [&](unsigned, int, unsigned format, unsigned, int bytes, void* pixels) {
    asked_format = format, asked_bytes = bytes;
    float* p = static_cast<float*>(pixels);
    for (int yb = 0; yb < kH; ++yb)  // GL's row 0 is the bottom row
      for (int x = 0; x < kW; ++x)
        for (int c = 0; c < 4; ++c) p[(yb * kW + x) * 4 + c] = float(100 * yb + 10 * x + c);
  };
  EXPECT_TRUE(vct_dump::colour_image_from_gl(w, "gbuffer.material", fake_get_texture_image, 7, kW, kH, 4)) << w.error();
  EXPECT_EQ(asked_format, 0x1908u);  // GL_RGBA
  EXPECT_EQ(asked_bytes, kW * kH * 4 * 4);
  EXPECT_FALSE(vct_dump::colour_image_from_gl(w, "gbuffer.odd", fake_get_texture_image, 7, kW, kH, 5));
  EXPECT_NE(w.error().find("1 to 4 channels"), std::string::npos);
  // The failed stage makes finish() refuse: a half-dumped set never gets a manifest.
  EXPECT_FALSE(w.finish());
  EXPECT_FALSE(fs::exists(dir + "/vct-stages.json"));
  vct_dump::StageSetWriter ok(dir, "dump-test");
  ok.set_setting("grid", size_t(kN));
  ok.set_setting("cone_quality", 0.5f);
  ASSERT_TRUE(vct_dump::colour_image_from_gl(ok, "gbuffer.material", fake_get_texture_image, 7, kW, kH, 4));
  ASSERT_TRUE(ok.finish()) << ok.error();
  const StageSet s = read_stage_set(dir);
  EXPECT_EQ(s.settings.value("grid", 0), kN);
  EXPECT_EQ(s.settings.value("cone_quality", 0.0), 0.5);
  const Image& m = s.images.at("gbuffer.material");
  EXPECT_EQ(m.at(1, 0, 3), float(100 * (kH - 1) + 10 + 3));  // top row = GL's last row
  EXPECT_EQ(m.at(1, kH - 1, 2), 12.0f);                     // bottom row = GL's row 0
}

// conventions.display is a nested object: written with vct_dump::Object, it reads back as the
// display transform the judge applies.
TEST(VctDump, NestedDisplayConventionReadsBack) {
  const std::string dir = (fs::temp_directory_path() / "vct_dump_test_display").string();
  fs::remove_all(dir);
  fs::create_directories(dir);
  vct_dump::StageSetWriter w(dir, "dump-test");
  w.set_convention("mip_scale", 1.9);
  w.set_convention("display", vct_dump::Object()
                                  .set("operator", "reinhard")
                                  .set("gamma", 2.2)
                                  .set("bits", 8)
                                  .set("stages", std::vector<std::string>{"image.final", "image.direct"}));
  const std::vector<float> rgb = bottom_first_rgb();
  ASSERT_TRUE(w.image("image.final", kW, kH, 3, rgb.data(), vct_dump::Rows::BottomFirst)) << w.error();
  ASSERT_TRUE(w.finish()) << w.error();
  const StageSet s = read_stage_set(dir);
  EXPECT_EQ(s.conventions.mip_scale, 1.9);
  EXPECT_EQ(s.conventions.display.op, ToneOperator::Reinhard);
  EXPECT_EQ(s.conventions.display.gamma, 2.2);
  EXPECT_EQ(s.conventions.display.bits, 8);
  EXPECT_EQ(s.conventions.display.stages, (std::vector<std::string>{"image.final", "image.direct"}));
}

int run_compare(const std::string& ref, const std::string& test) {
  const std::string cmd = std::string(VCT_BINARY) + " compare " + ref + " " + test + " > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

TEST(VctDump, JudgedByVctCompare) {
  const std::vector<float> vox = voxels();
  // The reference: the same values written by the project's own stage-set writer.
  StageSet ref;
  ref.backend = "ref";
  const StageSet dumped = read_stage_set(dump("same", vox));
  ref.images = dumped.images;
  ref.volumes = dumped.volumes;
  const std::string ref_dir = (fs::temp_directory_path() / "vct_dump_test_ref").string();
  fs::remove_all(ref_dir);
  write_stage_set(ref_dir, ref);
  EXPECT_EQ(run_compare(ref_dir, dump("same", vox)), 0);
  std::vector<float> bad = vox;
  bad[size_t((((2 * kN + 2) * kN) + 1) * 4)] += 0.2f;  // one voxel's red off
  const Report r = compare_stage_sets(ref, read_stage_set(dump("bad", bad)));
  EXPECT_EQ(r.first_failing(), "voxel.radiance");
  EXPECT_EQ(run_compare(ref_dir, dump("bad", bad)), 1);
  // A convention the oracle does not know is bad input, not a silent pass.
  const std::string odd = dump("odd", vox);
  std::ifstream in(odd + "/vct-stages.json");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string m = ss.str();
  m.replace(m.find("\"mip_scale\""), 11, "\"mip_scael\"");
  std::ofstream(odd + "/vct-stages.json") << m;
  EXPECT_EQ(run_compare(ref_dir, odd), 2);
}

// Both directions through `vct compare`: an 8-bit Reinhard + gamma 2.2 final of the reference's
// own linear image passes once the dump declares that display transform (and fails without the
// declaration: 8-bit display values are far from linear radiance); one pixel brighter by 1/8 of
// its display value still fails under the declaration.
TEST(VctDump, DeclaredDisplayTransformIsJudgedInDisplaySpace) {
  StageSet ref;
  ref.backend = "ref";
  Image linear(kW, kH, 3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) linear.at(x, y, c) = 0.05f + 0.3f * float(x) + 0.2f * float(y) + 0.1f * float(c);
  ref.images["image.final"] = linear;
  const std::string ref_dir = (fs::temp_directory_path() / "vct_dump_test_display_ref").string();
  fs::remove_all(ref_dir);
  write_stage_set(ref_dir, ref);
  DisplayTransform d;
  d.op = ToneOperator::Reinhard, d.gamma = 2.2, d.bits = 8;
  auto write = [&](const std::string& name, bool declare, float bump) {
    const std::string dir = (fs::temp_directory_path() / ("vct_dump_test_display_" + name)).string();
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::vector<float> shown(size_t(kW * kH * 3));
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        for (int c = 0; c < 3; ++c) shown[size_t((y * kW + x) * 3 + c)] = float(d.encode(linear.at(x, y, c)));
    shown[size_t((1 * kW + 2) * 3)] *= 1.0f + bump;
    vct_dump::StageSetWriter w(dir, "tone-mapped");
    if (declare) w.set_convention("display", vct_dump::Object().set("operator", "reinhard").set("gamma", 2.2).set("bits", 8));
    EXPECT_TRUE(w.image("image.final", kW, kH, 3, shown.data(), vct_dump::Rows::TopFirst)) << w.error();
    EXPECT_TRUE(w.finish()) << w.error();
    return dir;
  };
  EXPECT_EQ(run_compare(ref_dir, write("declared", true, 0.0f)), 0);
  EXPECT_EQ(run_compare(ref_dir, write("undeclared", false, 0.0f)), 1);
  EXPECT_EQ(run_compare(ref_dir, write("declared_bad", true, 0.125f)), 1);
}

}  // namespace
}  // namespace vct::cmp
