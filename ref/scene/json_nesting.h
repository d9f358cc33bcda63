// How deeply a JSON text nests arrays and objects, measured without parsing it. tinygltf turns
// the parsed JSON into its own Value tree by recursion (extras, extensions), so a document nested
// 20 000 levels deep ran out of stack (issue 19); the loader refuses one nested deeper than
// kMaxJsonNesting before any parser sees it (docs/scenes.md, "Limits").
#pragma once

#include <cstddef>
#include <string_view>

namespace vct {

/// The deepest a glTF document may nest. glTF's own structure needs 6 levels (root, meshes, a
/// mesh, primitives, a primitive, attributes); 128 leaves extras and extensions far more room
/// than any exporter uses, and at the parsers' frame sizes it needs well under 1 MiB of stack.
inline constexpr size_t kMaxJsonNesting = 128;

struct NestingScan {
  size_t depth = 0;        // deepest nesting seen (stops counting past the limit)
  size_t offset = 0;       // byte where the limit was passed (valid when exceeded)
  bool exceeded = false;
};

/// Counts '[' and '{' outside strings (a backslash escapes the next byte inside one). Stops at
/// the first byte that nests deeper than `limit`. Unbalanced or broken text is left to the parser.
NestingScan scan_json_nesting(std::string_view text, size_t limit = kMaxJsonNesting);

}  // namespace vct
