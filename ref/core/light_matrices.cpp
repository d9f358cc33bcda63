#include "core/light_matrices.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace vct {

namespace {

// "LIGHT:a,b,c,..." -> (LIGHT, numbers); `key` names the setting in errors.
std::pair<int, std::vector<float>> parse_entry(const std::string& entry, const std::string& key) {
  const auto fail = [&]() -> std::pair<int, std::vector<float>> {
    throw InputError("", key + ": '" + entry + "' is not LIGHT:numbers");
  };
  const size_t colon = entry.find(':');
  if (colon == std::string::npos) return fail();
  int light = -1;
  try {
    size_t used = 0;
    light = std::stoi(entry.substr(0, colon), &used);
    if (used != colon) return fail();
  } catch (const std::exception&) {
    return fail();
  }
  if (light < 0) return fail();
  std::vector<float> values;
  std::istringstream in(entry.substr(colon + 1));
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t first = item.find_first_not_of(" \t\n"), last = item.find_last_not_of(" \t\n");
    if (first == std::string::npos) return fail();
    item = item.substr(first, last - first + 1);
    size_t used = 0;
    float v = 0.0f;
    try {
      v = std::stof(item, &used);
    } catch (const std::exception&) {
      return fail();
    }
    if (used != item.size() || !std::isfinite(v)) return fail();
    values.push_back(v);
  }
  return {light, values};
}

template <typename Value, typename Make>
std::map<int, Value> parse_entries(const std::string& text, const std::string& key, size_t count, const Make& make) {
  std::map<int, Value> out;
  std::istringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ';')) {
    const size_t first = entry.find_first_not_of(" \t\n");
    if (first == std::string::npos) continue;  // trailing ';' or blank
    entry = entry.substr(first, entry.find_last_not_of(" \t\n") - first + 1);
    const auto [light, values] = parse_entry(entry, key);
    if (values.size() != count)
      throw InputError("", key + ": '" + entry + "' has " + std::to_string(values.size()) + " numbers, expected " +
                               std::to_string(count));
    if (!out.emplace(light, make(entry, values)).second)
      throw InputError("", key + ": light " + std::to_string(light) + " is given twice");
  }
  return out;
}

}  // namespace

std::map<int, mat4> parse_light_matrices(const std::string& text) {
  return parse_entries<mat4>(text, "shadow_view_proj", 16, [](const std::string&, const std::vector<float>& v) {
    mat4 m(0.0f);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = v[size_t(c * 4 + r)];
    return m;
  });
}

std::map<int, std::array<float, 6>> parse_ortho_boxes(const std::string& text) {
  return parse_entries<std::array<float, 6>>(
      text, "shadow_ortho_box", 6, [](const std::string& entry, const std::vector<float>& v) {
        if (!(v[0] < v[1] && v[2] < v[3] && v[4] < v[5]))
          throw InputError("", "shadow_ortho_box: '" + entry + "' is an empty box (need left < right, bottom < top, near < far)");
        return std::array<float, 6>{v[0], v[1], v[2], v[3], v[4], v[5]};
      });
}

std::string light_matrix_text(int light, const mat4& m) {
  std::ostringstream o;
  o.precision(9);
  o << light << ':';
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) o << (c + r ? "," : "") << m[c][r];
  return o.str();
}

}  // namespace vct
