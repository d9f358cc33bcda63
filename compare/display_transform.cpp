#include "compare/display_transform.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace vct::cmp {

namespace {

const std::vector<std::pair<ToneOperator, const char*>>& operator_names() {
  static const std::vector<std::pair<ToneOperator, const char*>> m{
      {ToneOperator::None, "none"}, {ToneOperator::Reinhard, "reinhard"}, {ToneOperator::Aces, "aces"}};
  return m;
}

// The tone operators on x >= 0. Reinhard: x / (1 + x). ACES: Narkowicz's 2015 fit of the ACES RRT
// + ODT, x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), clamped to [0, 1] (the form engines use).
double tone(ToneOperator op, double x) {
  switch (op) {
    case ToneOperator::Reinhard: return x / (1.0 + x);
    case ToneOperator::Aces: return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    case ToneOperator::None: break;
  }
  return x;
}

double positive_number(const std::string& manifest, const nlohmann::json& j, const char* key) {
  const nlohmann::json& v = j.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() <= 0.0)
    throw InputError(manifest, std::string("conventions.display.") + key + " must be a positive number");
  return v.get<double>();
}

}  // namespace

std::string to_string(ToneOperator op) {
  for (const auto& [value, name] : operator_names())
    if (value == op) return name;
  return "?";
}

bool DisplayTransform::applies_to(const std::string& stage) const {
  return declared() && std::find(stages.begin(), stages.end(), stage) != stages.end();
}

double DisplayTransform::apply(double linear) const {
  double y = tone(op, std::max(linear, 0.0) * exposure);
  // A unorm store clamps (GL 4.5 spec 2.3.5.2); an unquantised float output keeps values above 1.
  if (bits > 0 || op == ToneOperator::Aces) y = std::min(y, 1.0);
  return gamma == 1.0 ? y : std::pow(y, 1.0 / gamma);
}

double DisplayTransform::quantisation_allowance() const {
  return bits > 0 ? 1.0 / (std::exp2(double(bits)) - 1.0) : 0.0;
}

double DisplayTransform::encode(double linear) const {
  const double y = apply(linear);
  if (bits <= 0) return y;
  const double levels = std::exp2(double(bits)) - 1.0;
  return std::round(y * levels) / levels;
}

double DisplayTransform::carry_bound(double r, double b) const {
  const double at = apply(r);
  return std::max(apply(r + b) - at, at - apply(r - b)) + quantisation_allowance();
}

bool DisplayTransform::decodable() const {
  return (op == ToneOperator::None || op == ToneOperator::Reinhard) && gamma >= 1.0;
}

double DisplayTransform::decode(double stored) const {
  double y = std::max(stored, 0.0);
  if (bits > 0 || op == ToneOperator::Reinhard) y = std::min(y, 1.0);
  if (gamma != 1.0) y = std::pow(y, gamma);
  if (op == ToneOperator::Reinhard) {
    // x / (1 + x) < 1 for every finite x: a stored 1 is any value within a step of 1.
    y = std::min(y, 1.0 - 0.5 * (bits > 0 ? quantisation_allowance() : 1e-6));
    y = y / (1.0 - y);
  }
  return y / exposure;
}

DisplayTransform read_display_transform(const std::string& manifest, const nlohmann::json& j) {
  if (!j.is_object()) throw InputError(manifest, "conventions.display must be an object (docs/external_format.md)");
  DisplayTransform d;
  for (const auto& [key, value] : j.items()) {
    if (key == "operator") {
      const std::string name = value.is_string() ? value.get<std::string>() : "";
      bool found = false;
      for (const auto& [op, n] : operator_names())
        if (name == n) d.op = op, found = true;
      if (!found) throw InputError(manifest, "conventions.display.operator must be one of none|reinhard|aces");
    } else if (key == "exposure") {
      d.exposure = positive_number(manifest, j, "exposure");
    } else if (key == "gamma") {
      d.gamma = positive_number(manifest, j, "gamma");
    } else if (key == "bits") {
      if (!value.is_number_integer() || value.get<int64_t>() < 0 || value.get<int64_t>() > 16)
        throw InputError(manifest, "conventions.display.bits must be an integer in 0..16 (0 = not quantised)");
      d.bits = value.get<int>();
    } else if (key == "stages") {
      if (!value.is_array() || value.empty())
        throw InputError(manifest, "conventions.display.stages must be a non-empty list of image stage names");
      d.stages.clear();
      for (const auto& s : value) {
        if (!s.is_string() || s.get<std::string>().rfind("image.", 0) != 0)
          throw InputError(manifest, "conventions.display.stages: every entry must be an image.* stage name");
        d.stages.push_back(s.get<std::string>());
      }
    } else {
      throw InputError(manifest, "unknown key conventions.display." + key +
                                     " (known: operator, exposure, gamma, bits, stages)");
    }
  }
  return d;
}

nlohmann::json to_json(const DisplayTransform& d) {
  return {{"operator", to_string(d.op)}, {"exposure", d.exposure}, {"gamma", d.gamma}, {"bits", d.bits},
          {"stages", d.stages}};
}

}  // namespace vct::cmp
