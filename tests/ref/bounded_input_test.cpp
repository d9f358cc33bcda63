// Issue 38 items 2-3: one bounded reader for every input file. Only regular files are read (a FIFO
// would block, /dev/zero never ends), with a size cap; JSON is refused past 128 levels before any
// parser recurses, and parse errors quote at most a short excerpt of the input.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "core/error.h"
#include "core/settings.h"
#include "gltf_test_doc.h"
#include "io/bounded_file.h"
#include "io/bounded_json.h"
#include "io/image_io.h"
#include "io/nrrd.h"
#include "scene/gltf_loader.h"

namespace vct {
namespace {

// The message of the InputError `f` throws ("" if it throws none).
template <typename F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string fifo(const std::string& name) {
  const std::string path = (test::temp_dir() / name).string();
  ::unlink(path.c_str());
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
  return path;
}

std::string deep_json(size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

TEST(BoundedFile, ReadsARegularFileWhole) {
  const std::string path = test::write_file("twelve.txt", "0123456789ab");
  EXPECT_EQ(read_regular_file(path, 12, "test file"), "0123456789ab");
}

TEST(BoundedFile, RefusesAFileOverTheCapNamingBothSizes) {
  const std::string path = test::write_file("thirteen.txt", "0123456789abc");
  const std::string msg = refusal([&] { read_regular_file(path, 12, "test file"); });
  EXPECT_NE(msg.find(path + ": is 13 bytes; a test file may have at most 12"), std::string::npos) << msg;
}

TEST(BoundedFile, RefusesFifoDeviceDirectoryAndMissingFile) {
  const std::string pipe = fifo("scene_fifo.gltf");
  EXPECT_NE(refusal([&] { read_regular_file(pipe, 100, "glTF file"); }).find("is not a regular file"), std::string::npos);
  EXPECT_NE(refusal([] { read_regular_file("/dev/zero", 100, "glTF file"); }).find("/dev/zero: is not a regular file"),
            std::string::npos);
  EXPECT_NE(refusal([] { read_regular_file("/tmp", 100, "glTF file"); }).find("/tmp: is a directory, not a glTF file"),
            std::string::npos);
  const std::string missing = (test::temp_dir() / "missing.json").string();
  EXPECT_EQ(refusal([&] { read_regular_file(missing, 100, "x"); }), missing + ": file not found");
}

TEST(BoundedJson, RefusesThreeHundredThousandLevelsAtLevel129) {
  const std::string msg = refusal([] { parse_bounded_json(deep_json(300000), "deep.json"); });
  EXPECT_EQ(msg.rfind("deep.json: JSON nests deeper than 128 levels (at byte 128)", 0), 0u) << msg;
  EXPECT_TRUE(parse_bounded_json(deep_json(128), "ok.json").is_array());
}

TEST(BoundedJson, NumberOutOfRangeIsBrokenJsonNotAnInternalError) {
  const std::string msg = refusal([] { parse_bounded_json("{\"vct\": {\"grid\": 1e999}}", "big.json"); });
  EXPECT_EQ(msg.rfind("big.json: broken JSON: ", 0), 0u) << msg;
}

TEST(BoundedJson, ParseErrorQuotesAtMostAShortExcerpt) {
  // An unterminated string of 3 MB: nlohmann's message quotes the whole token it read.
  const std::string text = "{\"uri\": \"" + std::string(3u << 20, 'A');
  const std::string msg = refusal([&] { parse_bounded_json(text, "long.json"); });
  EXPECT_EQ(msg.rfind("long.json: broken JSON: ", 0), 0u) << msg.substr(0, 200);
  EXPECT_LE(msg.size(), 200u);
}

TEST(BoundedJson, InputExcerptIsOnePrintableLine) {
  EXPECT_EQ(input_excerpt("ab\ncd\x01", 80), "ab?cd?");
  EXPECT_EQ(input_excerpt(std::string(100, 'x'), 10), "xxxxxxxxxx...");
}

TEST(BoundedSettingsFile, DeepNumberOverflowDirectoryAndFifoAreInputErrors) {
  const std::string deep = test::write_file("deep_config.json", "{\"vct\": " + deep_json(300000) + "}");
  EXPECT_NE(refusal([&] { load_settings_file(deep, Settings{}); }).find("nests deeper than 128 levels"), std::string::npos);
  const std::string big = test::write_file("big_config.json", "{\"vct\": {\"shadow_bias\": 1e999}}");
  EXPECT_NE(refusal([&] { load_settings_file(big, Settings{}); }).find(big + ": broken JSON"), std::string::npos);
  const std::string dir = test::temp_dir().string();
  EXPECT_NE(refusal([&] { load_settings_file(dir, Settings{}); }).find("is a directory, not a settings file"), std::string::npos);
  const std::string pipe = fifo("config_fifo.json");
  EXPECT_NE(refusal([&] { load_settings_file(pipe, Settings{}); }).find("is not a regular file"), std::string::npos);
}

// Images and volumes `vct compare` reads (EXR, PNG, NRRD) come through the same reader.
TEST(BoundedStageFile, ImageAndVolumeFromAFifoOrDeviceAreRefused) {
  const std::string pipe = fifo("stage_fifo.exr");
  EXPECT_NE(refusal([&] { read_image(pipe); }).find("is not a regular file"), std::string::npos);
  EXPECT_NE(refusal([] { read_nrrd("/dev/zero"); }).find("/dev/zero: is not a regular file"), std::string::npos);
}

TEST(BoundedScene, FifoAndDeviceAreRefusedWithoutReading) {
  const std::string pipe = fifo("fifo_scene.gltf");
  EXPECT_NE(refusal([&] { load_gltf_file(pipe); }).find("is not a regular file"), std::string::npos);
  EXPECT_NE(refusal([] { load_gltf_file("/dev/zero"); }).find("/dev/zero: is not a regular file"), std::string::npos);
}

TEST(BoundedScene, CorruptBase64BufferIsQuotedShort) {
  test::GltfDoc d = test::quad_doc();
  d.j["buffers"][0] = {{"uri", "data:application/octet-stream;base64," + std::string(3u << 20, '!')},
                       {"byteLength", d.bin.size()}};
  const std::string path = test::write_file("corrupt_base64.gltf", d.text());
  const std::string msg = refusal([&] { load_gltf_file(path); });
  ASSERT_FALSE(msg.empty());
  EXPECT_LE(msg.size(), path.size() + 400) << msg.substr(0, 400);
}

}  // namespace
}  // namespace vct
