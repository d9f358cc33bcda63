#include "scene/gltf_file_access.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/bounded_file.h"
#include "scene/gltf_loader.h"

namespace vct::gltf {

namespace fs = std::filesystem;

namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 0;  // as tinygltf: an invalid digit counts as 0
}

bool starts_with_nocase(const std::string& s, const char* prefix) {
  for (size_t i = 0; prefix[i]; ++i) {
    if (i >= s.size() || std::tolower(static_cast<unsigned char>(s[i])) != prefix[i]) return false;
  }
  return true;
}

// URIs go into one-line messages: printable ASCII only, and not too long.
std::string printable(const std::string& s) {
  std::string out;
  for (char c : s.substr(0, 200)) {
    const auto u = static_cast<unsigned char>(c);
    out += u >= 0x20 && u < 0x7f ? c : '?';
  }
  return s.size() > 200 ? out + "..." : out;
}

fs::path resolved(const fs::path& p) {
  std::error_code ec;
  fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);  // follows every symlink that exists
  return ec ? fs::absolute(p).lexically_normal() : r;
}

bool inside(const fs::path& p, const fs::path& dir) {
  const fs::path rel = p.lexically_relative(dir);
  return !rel.empty() && !rel.is_absolute() && *rel.begin() != "..";
}

bool is_data_uri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

// Why the policy refuses `uri` (as written in the file) in `dir`; "" when it does not.
std::string uri_refusal(const std::string& uri, const fs::path& dir) {
  if (is_data_uri(uri)) return "";
  const std::string path = decode_uri_as_tinygltf(uri);
  if (starts_with_nocase(uri, "file:") || starts_with_nocase(path, "file:")) return "file: URIs are not read";
  if (!path.empty() && (path[0] == '/' || path[0] == '\\')) return "it is an absolute path";
  if (path.size() >= 2 && std::isalpha(static_cast<unsigned char>(path[0])) && path[1] == ':')
    return "it is an absolute path";
  const fs::path lexical = (dir / path).lexically_normal();
  if (!inside(lexical, dir)) return "its '..' leaves the scene's folder";
  if (!inside(resolved(lexical), dir)) return "it is (or goes through) a symbolic link to outside the scene's folder";
  return "";
}

bool file_exists(const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  return access->refusal(path).empty() && tinygltf::FileExists(path, nullptr);
}

// No ~ or $VAR expansion; only an absolute URI (allowed outside files) is taken back from its join.
std::string expand_path(const std::string& path, void* user) {
  return static_cast<const FileAccess*>(user)->unjoin_absolute(path);
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  const std::string why = access->refusal(path);
  if (!why.empty()) {
    if (err) *err += why;
    return false;
  }
  // Regular files only, at most kMaxSceneFileBytes (a FIFO would block, /dev/zero never ends).
  try {
    const std::string bytes = read_regular_file(path, kMaxSceneFileBytes, "file a scene reads");
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    if (err) *err += e.what();
    return false;
  }
}

bool write_nothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "vct does not write glTF files";
  return false;
}

}  // namespace

std::string decode_uri_as_tinygltf(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += char(hex_value(uri[i + 1]) << 4 | hex_value(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

FileAccess::FileAccess(const std::string& scene_dir, bool allow_outside)
    : dir_(resolved(scene_dir.empty() ? fs::path(".") : fs::path(scene_dir))),
      base_(scene_dir),
      allow_outside_(allow_outside) {}

std::string FileAccess::unjoin_absolute(const std::string& joined) const {
  if (!allow_outside_) return joined;
  for (const std::string& folder : {base_, std::string(".")}) {
    if (folder.empty()) continue;  // tinygltf does not join to an empty folder
    const std::string prefix = folder.back() == '/' ? folder : folder + "/";
    if (joined.size() > prefix.size() && joined.compare(0, prefix.size(), prefix) == 0 && joined[prefix.size()] == '/')
      return joined.substr(prefix.size());
  }
  return joined;
}

void FileAccess::check_uri(const std::string& file, const std::string& uri, const std::string& where) const {
  const std::string why = allow_outside_ ? "" : uri_refusal(uri, dir_);
  if (!why.empty()) {
    throw InputError(file, where + " uri '" + printable(uri) + "' is refused: " + why + " (" +
                               printable(dir_.string()) +
                               "); scenes read only files inside their own folder unless --allow-outside-scene-dir "
                               "is given");
  }
  if (is_data_uri(uri) || starts_with_nocase(uri, "file:")) return;
  // tinygltf's own message is a bare "File not found"; name the paths it would have read: the
  // scene's folder, then the working directory (its FindFile order).
  const fs::path path(decode_uri_as_tinygltf(uri));
  std::vector<std::string> searched;
  for (const fs::path& folder : {fs::path(base_.empty() ? "." : base_), fs::path(".")}) {
    const fs::path candidate = path.is_absolute() ? path : fs::absolute(folder / path).lexically_normal();
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return;
    const std::string shown = printable(candidate.string());
    if (std::find(searched.begin(), searched.end(), shown) == searched.end()) searched.push_back(shown);
  }
  std::string list = searched[0];
  for (size_t i = 1; i < searched.size(); ++i) list += ", then " + searched[i];
  throw InputError(file, where + " uri '" + printable(uri) + "': file not found (searched " + list + ")");
}

std::string FileAccess::refusal(const std::string& path) const {
  if (allow_outside_) return "";
  if (inside(resolved(path), dir_)) return "";
  return printable(path) + " is outside the scene's folder " + printable(dir_.string());
}

tinygltf::FsCallbacks FileAccess::callbacks() const {
  return {&file_exists, &expand_path, &read_whole_file, &write_nothing, const_cast<FileAccess*>(this)};
}

void check_document_uris(const nlohmann::json& doc, const std::string& file, const FileAccess& access) {
  for (const char* key : {"buffers", "images"}) {
    if (!doc.contains(key) || !doc[key].is_array()) continue;
    const auto& list = doc[key];
    for (size_t i = 0; i < list.size(); ++i) {
      if (!list[i].is_object() || !list[i].contains("uri") || !list[i]["uri"].is_string()) continue;
      access.check_uri(file, list[i]["uri"].get<std::string>(), std::string(key) + "[" + std::to_string(i) + "]");
    }
  }
}

}  // namespace vct::gltf
