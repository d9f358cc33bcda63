// The limits of issue 19 (docs/scenes.md, "Limits"): JSON nesting is bounded before any parser
// runs, and every texture's header is judged against the memory budget before it is decoded,
// with the size in the message. The three inputs of the issue are here: 20 000-deep nesting and
// a PNG header claiming 100 000 x 100 000 pixels (the '../' URI is in gltf_file_access_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "core/image.h"
#include "gltf_test_doc.h"
#include "io/encoded_image_header.h"
#include "io/image_io.h"
#include "scene/gltf_image_budget.h"
#include "scene/gltf_loader.h"
#include "io/bounded_json.h"

namespace vct {
namespace {

using test::GltfDoc;

// The quad document with a root-level "extras" of `depth` nested arrays: the document then nests
// depth + 1 levels (the root object is one).
std::string nested_doc(size_t depth) {
  const std::string text = test::quad_doc().text();
  return "{\"extras\":" + std::string(depth, '[') + std::string(depth, ']') + "," + text.substr(1);
}

std::string load_error(const std::string& text, const SceneLoadOptions& o = {}) {
  try {
    (void)load_gltf_text(text, "limits.gltf", test::temp_dir().string(), o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonNesting, CountsBracketsOutsideStringsOnly) {
  EXPECT_EQ(scan_json_nesting("{\"a\": [[1], {\"b\": []}]}").depth, 4u);  // { [ { [
  EXPECT_EQ(scan_json_nesting("[\"[[[{{\", \"\\\"[[\"]").depth, 1u);  // brackets in strings, escaped quote
  const NestingScan s = scan_json_nesting("[[[[]]]]", 3);
  EXPECT_TRUE(s.exceeded);
  EXPECT_EQ(s.offset, 3u);  // the fourth '['
  EXPECT_FALSE(scan_json_nesting("[[[]]]", 3).exceeded);
}

TEST(GltfLimits, TwentyThousandDeepNestingIsRefusedNotACrash) {
  const std::string msg = load_error(nested_doc(20000));
  EXPECT_EQ(msg.rfind("limits.gltf: JSON nests deeper than 128 levels (at byte 137)", 0), 0u) << msg;  // 10 bytes of {"extras":, then the 128th [
}

TEST(GltfLimits, NestingUpToTheLimitLoads) {
  EXPECT_EQ(load_error(nested_doc(kMaxJsonNesting - 1)), "");
  EXPECT_NE(load_error(nested_doc(kMaxJsonNesting)).find("nests deeper than 128"), std::string::npos);
}

TEST(GltfLimits, DeepNestingInsideAGlbIsRefusedToo) {
  GltfDoc d = test::quad_doc();
  std::string glb = d.glb();
  // Rebuild the GLB around a JSON chunk that nests 20 000 deep.
  const uint32_t json_len = *reinterpret_cast<const uint32_t*>(&glb[12]);
  std::string json = glb.substr(20, json_len);
  json = "{\"extras\":" + std::string(20000, '[') + std::string(20000, ']') + "," + json.substr(1);
  while (json.size() % 4) json += ' ';
  const std::string bin_chunk = glb.substr(20 + json_len);
  std::string out = "glTF";
  test::append<uint32_t>(out, {2u, uint32_t(12 + 8 + json.size() + bin_chunk.size())});
  test::append<uint32_t>(out, {uint32_t(json.size()), 0x4E4F534Au});
  out += json + bin_chunk;
  const std::string path = test::write_file("deep.glb", out);
  try {
    (void)load_gltf_file(path);
    FAIL() << "loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nests deeper than 128"), std::string::npos) << e.what();
  }
}

// A PNG of only its signature and IHDR chunk (CRC not checked by a header reader).
std::string png_header_only(uint32_t w, uint32_t h, uint8_t bits, uint8_t colour) {
  std::string b("\x89PNG\r\n\x1a\n", 8);
  auto be32 = [&](uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) b += char((v >> s) & 0xFF);
  };
  be32(13);
  b += "IHDR";
  be32(w);
  be32(h);
  b += char(bits);
  b += char(colour);
  b += std::string(3, '\0');  // compression, filter, interlace
  be32(0);                    // CRC
  be32(0);
  b += "IEND";
  be32(0);
  return b;
}

std::string textured_doc(const std::string& uri) {
  GltfDoc d = test::quad_doc();
  d.j["images"] = {{{"uri", uri}}};
  d.j["textures"] = {{{"source", 0}}};
  d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  return d.text();
}

TEST(EncodedImageHeader, ReadsPngAndJpegHeadersByHand) {
  const std::string png = png_header_only(100000, 100000, 16, 2);
  auto h = read_encoded_image_header(reinterpret_cast<const unsigned char*>(png.data()), png.size());
  ASSERT_TRUE(h);
  EXPECT_EQ(h->format, "PNG");
  EXPECT_EQ(h->width, 100000u);
  EXPECT_EQ(h->height, 100000u);
  EXPECT_EQ(h->channels, 3);
  EXPECT_EQ(h->bits, 16);
  // SOI, an APP0 segment of 16 bytes, then SOF0: precision 8, height 0x1234, width 0x0567, 3 components.
  std::string jpg("\xFF\xD8\xFF\xE0\x00\x10", 6);
  jpg += std::string(14, 'J');
  jpg += std::string("\xFF\xC0\x00\x11\x08\x12\x34\x05\x67\x03", 10);
  jpg += std::string(9, '\0');
  h = read_encoded_image_header(reinterpret_cast<const unsigned char*>(jpg.data()), jpg.size());
  ASSERT_TRUE(h);
  EXPECT_EQ(h->format, "JPEG");
  EXPECT_EQ(h->width, 0x567u);
  EXPECT_EQ(h->height, 0x1234u);
  EXPECT_EQ(h->channels, 3);
  const std::string junk = "not an image";
  EXPECT_FALSE(read_encoded_image_header(reinterpret_cast<const unsigned char*>(junk.data()), junk.size()));
}

TEST(GltfLimits, PngClaimingHundredThousandSquaredIsRefusedWithItsSize) {
  test::write_file("huge.png", png_header_only(100000, 100000, 8, 6));
  const std::string msg = load_error(textured_doc("huge.png"));
  // 10^10 pixels: whichever limit speaks first (this machine's memory, or the decoder's 2 GiB),
  // the message says what the header claims and that nothing was decoded.
  EXPECT_EQ(msg.rfind("limits.gltf: image 0 'huge.png': its PNG header says 100000 x 100000 pixels, 4 channel(s) of 8 bits: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("refused before decoding"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("Unknown image format"), std::string::npos) << msg;
}

TEST(GltfLimits, ImageOverTheMemoryBudgetIsRefusedWithTheBytesItNeeds) {
  // 2 x stb's and tinygltf's RGBA8 (16 KiB each at 64 x 64) + the Scene's RGBA8 (16 KiB) = 48 KiB,
  // + its mip chain: (32^2 + 16^2 + 8^2 + 4^2 + 2^2 + 1) x 4 = 5460 bytes; 54612 bytes = 53.3 KiB.
  EXPECT_EQ(gltf::image_decode_bytes(64, 64, 8), 54612u);
  const std::string png = png_header_only(64, 64, 8, 6);
  test::write_file("small.png", png);
  SceneLoadOptions o;
  o.image_memory_budget = 40000;
  const std::string msg = load_error(textured_doc("small.png"), o);
  EXPECT_NE(
      msg.find(
          "decoding it needs 53.3 KiB, but only 39.1 KiB of the 39.1 KiB memory budget is left"),
      std::string::npos)
      << msg;
}

TEST(GltfLimits, TheBudgetCountsImagesAlreadyDecoded) {
  Image grey(64, 64, 3, 0.5f);
  write_png((test::temp_dir() / "real64.png").string(), grey, 1.0f, ToneMap::Clamp);
  GltfDoc d = test::quad_doc();
  d.j["images"] = {{{"uri", "real64.png"}}, {{"uri", "real64.png"}}};
  d.j["textures"] = {{{"source", 0}}, {{"source", 1}}};
  SceneLoadOptions o;
  o.image_memory_budget =
      54612;  // the first fits exactly; it keeps 37.3 KiB, so the second does not
  const std::string msg = load_error(d.text(), o);
  EXPECT_NE(msg.find("image 1 'real64.png'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("only 16.0 KiB of the 53.3 KiB memory budget is left"), std::string::npos)
      << msg;
  o.image_memory_budget = 2 * 54612;
  EXPECT_EQ(load_error(d.text(), o), "");
}

}  // namespace
}  // namespace vct

namespace vct {
namespace {

// Issue 38: a header-only PNG claiming 16384 x 16384 fits the memory budget of a large machine and
// the decoder's 2 GiB, and decoded as a black 1 GiB texture. Its bytes cannot hold that image.
TEST(GltfLimits, HeaderClaimingMoreThanItsBytesCanHoldIsRefused) {
  test::write_file("forged.png", png_header_only(16384, 16384, 8, 6));
  SceneLoadOptions o;
  o.image_memory_budget = 1ull << 40;  // the budget does not speak first
  const std::string msg = load_error(textured_doc("forged.png"), o);
  EXPECT_NE(msg.find("its PNG header says 16384 x 16384 pixels, 4 channel(s) of 8 bits, but its "), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("cannot hold that many (at most 1032 decoded bytes per encoded byte)"), std::string::npos) << msg;
}

}  // namespace
}  // namespace vct
