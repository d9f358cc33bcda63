#include "scene/json_nesting.h"

namespace vct {

NestingScan scan_json_nesting(std::string_view text, size_t limit) {
  NestingScan scan;
  size_t depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;  // the escaped byte cannot end the string
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) {
        scan.exceeded = true;
        scan.offset = i;
        scan.depth = depth;
        return scan;
      }
      if (depth > scan.depth) scan.depth = depth;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return scan;
}

}  // namespace vct
