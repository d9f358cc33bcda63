// libFuzzer target for the run-dir / external-dump reader: an input holds a vct-stages.json, a
// v.nrrd and an i.exr (fuzz_inputs.h); the manifest is read with read_stage_set (which reads the
// files it names) and the two data files directly with read_nrrd / read_image. Every input must
// read or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "compare/stage_set.h"
#include "core/error.h"
#include "fuzz_inputs.h"
#include "io/image_io.h"
#include "io/nrrd.h"

namespace {
template <class Fn>
void expect_input_error_or_success(Fn fn) {
  try {
    fn();
  } catch (const vct::InputError&) {
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vct::fuzz::write_stage_set_files(std::string(reinterpret_cast<const char*>(data), size));
  const auto dir = vct::fuzz::scratch_dir();
  expect_input_error_or_success([&] { vct::cmp::read_stage_set(dir.string()); });
  expect_input_error_or_success([&] { vct::read_nrrd((dir / "v.nrrd").string()); });
  expect_input_error_or_success([&] { vct::read_image((dir / "i.exr").string()); });
  return 0;
}
