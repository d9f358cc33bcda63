// Whether the capture tests can run here: RenderDoc's command line and its Python module for
// /usr/bin/python3 (both optional, installed by scripts/setup.sh), and a build RenderDoc can inject
// into. renderdoccmd injects its library with LD_PRELOAD, ahead of everything, which an
// AddressSanitizer binary refuses ("ASan runtime does not come first in initial library list"):
// the sanitizer tier (scripts/sanitize.sh) skips the captures.
#pragma once

#include <cstdlib>
#include <string>

namespace vct::test {

/// Why RenderDoc cannot be used here ("" when it can).
inline std::string renderdoc_missing() {
  if (std::system("command -v renderdoccmd > /dev/null 2>&1") != 0) return "renderdoccmd not installed (apt-get install renderdoccmd)";
  if (std::system("/usr/bin/python3 -c 'import renderdoc' > /dev/null 2>&1") != 0)
    return "python3-renderdoc not installed for /usr/bin/python3 (apt-get install python3-renderdoc)";
  return "";
}

/// Why this build cannot capture a frame ("" when it can).
inline std::string capture_impossible() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  return "a sanitizer build cannot run under RenderDoc's LD_PRELOAD injection";
#else
  return renderdoc_missing();
#endif
}

}  // namespace vct::test
