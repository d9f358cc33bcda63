// Which files a scene may make vct read (docs/scenes.md, "File access"): by default only files
// inside the folder of the scene file, so a downloaded scene cannot make the tool read (and the
// report publish) /etc/passwd or ~/.ssh (issue 19). The policy is applied twice: to every
// external URI of the JSON before tinygltf runs (one line naming the URI), and again in the file
// callbacks tinygltf opens files through, so no path it builds is opened unchecked (it also
// tries each URI below the working directory).
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace vct::gltf {

class FileAccess {
 public:
  /// `scene_dir`: the folder external URIs resolve in ("" = the working directory).
  /// `allow_outside`: --allow-outside-scene-dir, every check passes.
  FileAccess(const std::string& scene_dir, bool allow_outside);

  /// Throws InputError(file, ...) naming `uri` when the policy refuses it, or when the file it names
  /// does not exist (the message gives the path searched); `where` is its JSON path ("images[2]").
  /// Data URIs always pass: they read no file.
  void check_uri(const std::string& file, const std::string& uri, const std::string& where) const;

  /// Why the file at `path` (as tinygltf built it) may not be opened; "" when it may.
  std::string refusal(const std::string& path) const;

  /// tinygltf's file callbacks, each checking refusal() first; they point at this object.
  tinygltf::FsCallbacks callbacks() const;

  const std::filesystem::path& scene_dir() const { return dir_; }

  /// tinygltf joins every URI to a folder ("<base>/<uri>", then "./<uri>"), which turns an
  /// absolute path into a relative one; given such a join of an absolute URI, the URI itself.
  /// Only when outside files are allowed (refused otherwise before tinygltf runs).
  std::string unjoin_absolute(const std::string& joined) const;

 private:
  std::filesystem::path dir_;  // absolute, symlinks resolved
  std::string base_;           // the folder as tinygltf was given it
  bool allow_outside_;
};

/// Every external URI the document names (buffers[].uri, images[].uri) through check_uri.
void check_document_uris(const nlohmann::json& doc, const std::string& file, const FileAccess& access);

/// A URI as tinygltf turns it into a path (its dlib::urldecode: %XX is the byte, '+' a space).
std::string decode_uri_as_tinygltf(const std::string& uri);

}  // namespace vct::gltf
