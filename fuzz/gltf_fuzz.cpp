// libFuzzer target for the glTF loader: any input must load or throw InputError, nothing else
// (no crash, no other exception, no sanitizer report). Inputs starting with the .glb magic go
// through load_gltf_file on a .glb file; the rest through load_gltf_text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "fuzz_inputs.h"
#include "scene/gltf_loader.h"

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
