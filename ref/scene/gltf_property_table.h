// Every glTF property the loader reads, checked on the raw JSON before tinygltf or the converter
// sees it (issue 38). tinygltf stores an absent index as -1 and replaces a value of the wrong type,
// an unknown enum or an array of the wrong length by its default, so "light": -1 read lights[-1],
// a 15-number matrix became the identity and wrap 42 became REPEAT, all in silence. One table
// lists each property with its rule: an index into an array, a number in a range, an enum, an
// array of n numbers, a boolean, a string (docs/scenes.md, "What the loader refuses").
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace vct::gltf {

/// Throws InputError(file, ...) naming the first property (as a JSON path, "nodes[3].mesh") that
/// breaks its rule: an index that is not a non-negative integer below the size of the array it
/// points into (a missing array has size 0), a value of the wrong type, out of range or not one of
/// its enum values, an array of the wrong length.
void check_document_properties(const nlohmann::json& doc, const std::string& file);

}  // namespace vct::gltf
