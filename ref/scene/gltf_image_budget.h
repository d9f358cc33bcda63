// Textures are judged by the size their header claims before anything is decoded (issue 19):
// tinygltf decodes every image while it parses, so its image callback is replaced by one that
// reads the header (io/encoded_image_header.h), refuses an image that would not fit in the
// memory left, with the size in the message, and only then calls tinygltf's own decoder.
#pragma once

#include <cstdint>
#include <string>

#include <tiny_gltf.h>

namespace vct::gltf {

struct ImageBudget {
  uint64_t available = 0;  // bytes every decoded image of the scene may take together
  uint64_t kept = 0;       // what the images decoded so far keep (tinygltf's copy + the Scene's)
  std::string refusal;     // the message, once an image was refused
};

/// The bytes decoding a width x height image with `bits` per channel needs at its peak: stb's
/// RGBA output and tinygltf's copy of it (tinygltf always asks for 4 channels), plus the Scene's
/// RGBA8 texture made from it (gltf_materials.cpp) and its mip chain (scene/texture_mips.h).
uint64_t image_decode_bytes(uint64_t width, uint64_t height, int bits);

/// What stays allocated per image after decoding: tinygltf's copy, the Scene's RGBA8 and its
/// mip chain.
uint64_t image_kept_bytes(uint64_t width, uint64_t height, int bits);

/// A tinygltf::LoadImageDataFunction; `user` is an ImageBudget. On refusal it fills
/// budget.refusal and returns false, so tinygltf stops before decoding.
bool load_image_within_budget(tinygltf::Image* image, int index, std::string* err, std::string* warn, int req_width,
                              int req_height, const unsigned char* bytes, int size, void* user);

}  // namespace vct::gltf
