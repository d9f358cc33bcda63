// The file-access policy of issue 19 (ref/scene/gltf_file_access.h, docs/scenes.md "File
// access"): a scene's URIs may name only files inside its folder. Each refused case is also
// loaded with allow_outside_scene_dir, where the same file is read, so every refusal shown here
// is the policy's and not a missing or broken file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "core/error.h"
#include "core/image.h"
#include "gltf_test_doc.h"
#include "io/image_io.h"
#include "scene/gltf_loader.h"

namespace vct {
namespace {

namespace fs = std::filesystem;
using test::GltfDoc;

// temp_dir()/outside.png (2 x 2, red) lies beside the scene folder temp_dir()/scene/.
fs::path scene_dir() {
  static const fs::path dir = [] {
    const fs::path d = test::temp_dir() / "scene";
    fs::create_directories(d / "textures");
    Image red(2, 2, 3);
    for (int i = 0; i < 4; ++i) red.data[size_t(i) * 3] = 1.0f;
    write_png((test::temp_dir() / "outside.png").string(), red, 1.0f, ToneMap::Clamp);
    write_png((d / "textures" / "inside.png").string(), red, 1.0f, ToneMap::Clamp);
    return d;
  }();
  return dir;
}

std::string textured_scene(const std::string& name, const std::string& uri) {
  GltfDoc d = test::quad_doc();
  d.j["images"] = {{{"uri", uri}}};
  d.j["textures"] = {{{"source", 0}}};
  d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  const fs::path p = scene_dir() / (name + ".gltf");
  std::ofstream(p, std::ios::binary) << d.text();
  return p.string();
}

SceneLoadOptions allowed() {
  SceneLoadOptions o;
  o.allow_outside_scene_dir = true;
  return o;
}

// Loads `path`, expecting the policy's one-line refusal naming `uri`; returns the message.
std::string refusal(const std::string& path, const std::string& uri) {
  try {
    (void)load_gltf_file(path);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": images[0] uri '" + uri + "' is refused: ", 0), 0u) << msg;
    EXPECT_NE(msg.find("--allow-outside-scene-dir"), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    return msg;
  }
  ADD_FAILURE() << path << " loaded";
  return "";
}

// The red texel the outside file holds, read through the scene.
void expect_red_texture(const Scene& s) {
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].width, 2);
  EXPECT_EQ(int(s.textures[0].rgba8[0]), 255);
  EXPECT_EQ(int(s.textures[0].rgba8[1]), 0);
}

TEST(GltfFileAccess, DotDotLeavingTheFolderIsRefusedUnlessAllowed) {
  const std::string path = textured_scene("dotdot", "../outside.png");
  EXPECT_NE(refusal(path, "../outside.png").find("'..' leaves the scene's folder"), std::string::npos);
  expect_red_texture(load_gltf_file(path, allowed()));
}

TEST(GltfFileAccess, EtcPasswdOfTheIssueIsRefusedBeforeItIsRead) {
  const std::string uri = "../../../../../../etc/passwd";
  const std::string msg = refusal(textured_scene("passwd", uri), uri);
  EXPECT_EQ(msg.find("undecodable"), std::string::npos) << msg;  // refused as a path, not as an image
}

TEST(GltfFileAccess, PercentEncodedDotDotIsDecodedAsTinygltfDoes) {
  const std::string path = textured_scene("encoded", "%2e%2e/outside.png");
  EXPECT_NE(refusal(path, "%2e%2e/outside.png").find("'..' leaves"), std::string::npos);
  expect_red_texture(load_gltf_file(path, allowed()));
}

TEST(GltfFileAccess, AbsolutePathAndFileUriAreRefused) {
  const std::string abs = (test::temp_dir() / "outside.png").string();
  EXPECT_NE(refusal(textured_scene("absolute", abs), abs).find("absolute path"), std::string::npos);
  expect_red_texture(load_gltf_file(textured_scene("absolute", abs), allowed()));  // tinygltf alone cannot
  const std::string file_uri = "file://" + abs;
  EXPECT_NE(refusal(textured_scene("file_uri", file_uri), file_uri).find("file: URIs are not read"), std::string::npos);
}

TEST(GltfFileAccess, SymlinkPointingOutIsRefusedUnlessAllowed) {
  const fs::path link = scene_dir() / "link.png";
  fs::remove(link);
  fs::create_symlink(test::temp_dir() / "outside.png", link);
  const std::string path = textured_scene("symlink", "link.png");
  EXPECT_NE(refusal(path, "link.png").find("symbolic link"), std::string::npos);
  expect_red_texture(load_gltf_file(path, allowed()));
}

TEST(GltfFileAccess, BufferUriOutsideIsRefusedAndNamed) {
  GltfDoc d = test::quad_doc();
  std::ofstream(test::temp_dir() / "outside.bin", std::ios::binary) << d.bin;
  d.j["buffers"][0] = {{"uri", "../outside.bin"}, {"byteLength", d.bin.size()}};
  const fs::path p = scene_dir() / "buffer_out.gltf";
  std::ofstream(p, std::ios::binary) << d.text();
  try {
    (void)load_gltf_file(p.string());
    FAIL() << "loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("buffers[0] uri '../outside.bin' is refused"), std::string::npos) << e.what();
  }
  EXPECT_EQ(load_gltf_file(p.string(), allowed()).triangle_count(), 2u);
}

TEST(GltfFileAccess, FilesInsideTheFolderAndDataUrisLoad) {
  expect_red_texture(load_gltf_file(textured_scene("inside", "textures/inside.png")));
  expect_red_texture(load_gltf_file(textured_scene("inside_dotdot", "textures/../textures/inside.png")));
  const std::string png = test::slurp_file((scene_dir() / "textures" / "inside.png").string());
  expect_red_texture(load_gltf_file(textured_scene("data_uri", "data:image/png;base64," + test::base64(png))));
}

// tinygltf looks for a URI below the working directory when it is not beside the scene. The
// policy sits in its file callbacks too, so that second place is not read either.
TEST(GltfFileAccess, TinygltfsWorkingDirectoryFallbackGoesThroughThePolicy) {
  const std::string path = textured_scene("cwd_fallback", "only_in_cwd.png");  // makes outside.png
  const fs::path cwd = test::temp_dir() / "cwd";
  fs::create_directories(cwd);
  fs::copy_file(test::temp_dir() / "outside.png", cwd / "only_in_cwd.png", fs::copy_options::overwrite_existing);
  const fs::path old = fs::current_path();
  fs::current_path(cwd);
  std::string refused;
  try {
    (void)load_gltf_file(path);
  } catch (const InputError& e) {
    refused = e.what();
  }
  const Scene with_allowance = load_gltf_file(path, allowed());
  fs::current_path(old);
  EXPECT_NE(refused.find("'only_in_cwd.png'"), std::string::npos) << refused;
  EXPECT_NE(refused.find("could not be loaded"), std::string::npos) << refused;
  expect_red_texture(with_allowance);  // the fallback is real: allowed, it finds the file in cwd
}

}  // namespace
}  // namespace vct
