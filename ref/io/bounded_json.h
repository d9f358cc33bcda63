// The one JSON reader of the tool (issue 38): every JSON it reads (glTF scenes, --config,
// stage-set manifests, run.json, settings dicts from Python) is parsed here, with a cap on its
// nesting and on its size. nlohmann's parser is iterative, but copying, comparing, dumping or
// converting a parsed value recurses once per level, and tinygltf converts the parsed JSON into
// its own Value tree by recursion: a document ~300 000 levels deep ended the process with a stack
// overflow (issues 19 and 38). The nesting is counted on the bytes, before any parser sees them
// (docs/scenes.md, "Limits").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace vct {

/// The deepest any JSON input may nest. glTF's own structure needs 6 levels (root, meshes, a
/// mesh, primitives, a primitive, attributes) and the tool's own files fewer than 10; 128 leaves
/// extras and extensions far more room than any exporter uses, and at the parsers' frame sizes it
/// needs well under 1 MiB of stack.
inline constexpr size_t kMaxJsonNesting = 128;

/// The largest JSON file other than a scene (settings, manifests, run.json): the tool's own
/// manifests are ~100 KiB; 64 MiB is far above any of them and far below the memory of a machine.
inline constexpr uint64_t kMaxJsonFileBytes = 64ull << 20;

struct NestingScan {
  size_t depth = 0;        // deepest nesting seen (stops counting past the limit)
  size_t offset = 0;       // byte where the limit was passed (valid when exceeded)
  bool exceeded = false;
};

/// Counts '[' and '{' outside strings (a backslash escapes the next byte inside one). Stops at
/// the first byte that nests deeper than `limit`. Unbalanced or broken text is left to the parser.
NestingScan scan_json_nesting(std::string_view text, size_t limit = kMaxJsonNesting);

/// Parses `text` after checking its nesting. Throws InputError(name, ...) with one line that quotes
/// at most a short excerpt of the text: "nests deeper than 128 levels", or "broken JSON: ..."
/// (syntax errors, and numbers out of range such as 1e999).
nlohmann::json parse_bounded_json(std::string_view text, const std::string& name);

/// read_regular_file (bounded_file.h) then parse_bounded_json. `kind` names the file in messages.
nlohmann::json read_bounded_json_file(const std::string& path, const std::string& kind,
                                      uint64_t max_bytes = kMaxJsonFileBytes);

/// `text` as one printable line of at most `max_chars` characters (control bytes and non-ASCII
/// shown as '?', the cut marked "..."): what error messages quote of an input.
std::string input_excerpt(std::string_view text, size_t max_chars = 80);

}  // namespace vct
