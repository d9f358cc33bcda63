// The CaptureReader of `vct import-capture` (compare/capture_import.h) that replays a RenderDoc
// capture: tools/import_capture/rdc_read.py under the system python3, which has Debian's
// python3-renderdoc module (the project's venv does not: the module is built for Debian's
// interpreter). The script writes each texture as float32 into a temporary folder read here.
#pragma once

#include <string>
#include <vector>

#include "compare/capture_import.h"

namespace vct::app {

class RenderDocReader : public cmp::CaptureReader {
 public:
  /// `python`: the interpreter that has the renderdoc module ($VCT_RENDERDOC_PYTHON, else
  /// /usr/bin/python3); `script`: rdc_read.py (found in the source tree when empty).
  explicit RenderDocReader(std::string python = "", std::string script = "");
  std::vector<cmp::CapturedTexture> read(const std::string& capture, const std::vector<cmp::CaptureStage>& stages) override;

 private:
  std::string python_, script_;
};

}  // namespace vct::app
