// Every index a glTF document holds, checked on the raw JSON before tinygltf or the converter
// reads it (issue 38): tinygltf stores an absent index as -1, so "light": -1 or an index of the
// wrong type reached the converter as "absent" or as lights[-1]. One table lists every index
// property of glTF 2.0 and of the extensions we read (docs/scenes.md, "Indices").
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace vct::gltf {

/// Throws InputError(file, ...) naming the first index that is not a non-negative integer below
/// the size of the array it points into (a missing array has size 0).
void check_document_indices(const nlohmann::json& doc, const std::string& file);

}  // namespace vct::gltf
