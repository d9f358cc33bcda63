// libFuzzer target for the glTF loader: any input must load or throw InputError, nothing else
// (no crash, no other exception, no sanitizer report). Inputs starting with the .glb magic go
// through load_gltf_file on a .glb file; the rest through load_gltf_text. Mutations: three in
// four structural (gltf_mutator.h) when the input is JSON, else libFuzzer's own byte mutations
// (with fuzz/gltf.dict), which also break the syntax the structural ones keep.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.h"
#include "fuzz_inputs.h"
#include "gltf_mutator.h"
#include "scene/gltf_loader.h"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
  const char* bytes = reinterpret_cast<const char*>(data);
  if (seed % 4 != 0 && !vct::fuzz::is_glb(bytes, size)) {
    if (const auto mutated = vct::fuzz::mutate_gltf_json(std::string(bytes, size), seed / 4, max_size)) {
      std::memcpy(data, mutated->data(), mutated->size());
      return mutated->size();
    }
  }
  return LLVMFuzzerMutate(data, size, max_size);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const char* bytes = reinterpret_cast<const char*>(data);
  try {
    if (vct::fuzz::is_glb(bytes, size)) {
      vct::load_gltf_file(vct::fuzz::write_scratch("fuzz.glb", bytes, size));
    } else {
      vct::load_gltf_text(std::string(bytes, size), "fuzz.gltf", vct::fuzz::scratch_dir().string());
    }
  } catch (const vct::InputError&) {
    // the documented answer to bad input
  }
  return 0;
}
