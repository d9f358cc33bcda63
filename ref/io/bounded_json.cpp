#include "io/bounded_json.h"

#include "core/error.h"
#include "io/bounded_file.h"

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

std::string input_excerpt(std::string_view text, size_t max_chars) {
  std::string out;
  for (char c : text.substr(0, max_chars)) {
    const auto u = static_cast<unsigned char>(c);
    out += u >= 0x20 && u < 0x7f ? c : '?';
  }
  return text.size() > max_chars ? out + "..." : out;
}

nlohmann::json parse_bounded_json(std::string_view text, const std::string& name) {
  const NestingScan nesting = scan_json_nesting(text);
  if (nesting.exceeded) {
    throw InputError(name, "JSON nests deeper than " + std::to_string(kMaxJsonNesting) + " levels (at byte " +
                               std::to_string(nesting.offset) + "); vct reads JSON nested at most " +
                               std::to_string(kMaxJsonNesting) + " deep (docs/scenes.md, \"Limits\")");
  }
  try {
    return nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for numbers like 1e999
    // nlohmann's message quotes the last token read, which may be megabytes of one string.
    const std::string what = e.what();
    const size_t cut = what.find("] ");
    throw InputError(name, "broken JSON: " + input_excerpt(cut == std::string::npos ? what : what.substr(cut + 2), 160));
  }
}

nlohmann::json read_bounded_json_file(const std::string& path, const std::string& kind, uint64_t max_bytes) {
  return parse_bounded_json(read_regular_file(path, max_bytes, kind), path);
}

}  // namespace vct
