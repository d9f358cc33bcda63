// libFuzzer target for `vct compare A B --scene builtin:cornell_box` up to the cone re-trace:
// one input is a whole small stage set B (fuzz_inputs.h: write_named_stage_set), taken through
// read_stage_set, the settings from B's manifest, the frame rebuild against the built-in scene and
// the stage-by-stage judgement against a fixed reference A (scene_compare_steps.h). The re-trace
// itself is left out: seconds per input. Every input must pass or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene_compare_steps.h"

namespace {
const vct::fuzz::SceneCompareFixture* fixture = nullptr;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fixture = new vct::fuzz::SceneCompareFixture(vct::fuzz::make_scene_compare_fixture());  // lives for the process
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vct::fuzz::run_scene_compare_steps(std::string(reinterpret_cast<const char*>(data), size), *fixture);
  return 0;
}
