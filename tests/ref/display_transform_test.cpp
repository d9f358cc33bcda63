// The PNG previews' display transform (docs/report.md, "Display transform"): Khronos PBR Neutral
// on the whole colour, then the sRGB curve, 8 bits. Hand values from the tone mapper's definition.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_doc.h"
#include "io/image_io.h"

namespace vct {
namespace {

// The byte write_png stores for a displayed (tone-mapped) linear value.
int byte_of(float displayed) { return int(std::lround(255.0 * double(linear_to_srgb(displayed)))); }

Image one_row(std::initializer_list<vec3> pixels) {
  Image img(int(pixels.size()), 1, 3);
  int x = 0;
  for (const vec3& p : pixels) img.set_rgb(x++, 0, p);
  return img;
}

TEST(DisplayTransform, KhronosPbrNeutralHandValues) {
  // (0.5, 0.5, 0.5): offset 0.04 (min >= 0.08), peak 0.46 < 0.76: 0.46, no compression.
  // (0.02, 0.5, 0.5): toe offset 0.02 - 6.25 x 0.02^2 = 0.0175: (0.0025, 0.4825, 0.4825), hue kept.
  // (2, 2, 2): offset 0.04, peak 1.96; new peak 1 - 0.24^2 / (1.96 + 0.24 - 0.76) = 0.96.
  // (4, 0.5, 0.5): offset 0.04 -> (3.96, 0.46, 0.46); new peak 1 - 0.0576 / 3.44 = 0.983256;
  //   scaled (0.983256, 0.114218, 0.114218); desaturation g = 1 - 1 / (0.15 x 2.976744 + 1) = 0.308682;
  //   mixed toward 0.983256: (0.983256, 0.382473, 0.382473).
  const Image img = one_row({vec3(0.5f), vec3(0.02f, 0.5f, 0.5f), vec3(2.0f), vec3(4.0f, 0.5f, 0.5f)});
  const std::string path = (test::temp_dir() / "display.png").string();
  write_png(path, img);  // the default display transform
  const Image png = read_image(path);
  const float expected[4][3] = {{0.46f, 0.46f, 0.46f},
                                {0.0025f, 0.4825f, 0.4825f},
                                {0.96f, 0.96f, 0.96f},
                                {0.983256f, 0.382473f, 0.382473f}};
  for (int x = 0; x < 4; ++x)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(int(std::lround(png.at(x, 0, c) * 255.0f)), byte_of(expected[x][c])) << x << " " << c;
  EXPECT_STREQ(tone_map_name(ToneMap::KhronosPbrNeutral), "Khronos PBR Neutral");
}

TEST(DisplayTransform, HugeValuesStayBelowWhiteAndNonFiniteShowsBlack) {
  const Image img = one_row({vec3(1e6f), vec3(NAN, INFINITY, -INFINITY)});
  const std::string path = (test::temp_dir() / "display_huge.png").string();
  write_png(path, img);
  const Image png = read_image(path);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(int(std::lround(png.at(0, 0, c) * 255.0f)), 255);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(int(std::lround(png.at(1, 0, c) * 255.0f)), 0);
}

}  // namespace
}  // namespace vct
