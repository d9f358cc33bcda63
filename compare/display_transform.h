// An engine's display transform of its image outputs (issue 21; manifest "conventions.display",
// docs/external_format.md): exposure, a tone operator, gamma encoding and quantisation to a bit
// depth. When an engine declares it, the comparison maps the reference's linear image through the
// same continuous transform and carries each pixel's linear bound into display space
// (docs/compare.md, "Display transform"), so a tone-mapped 8-bit final is judged in its own space.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vct::cmp {

enum class ToneOperator { None, Reinhard, Aces };

struct DisplayTransform {
  ToneOperator op = ToneOperator::None;
  double exposure = 1.0;  // linear multiplier before the operator
  double gamma = 1.0;     // display value = toned^(1 / gamma)
  int bits = 0;           // 0 = not quantised; else unorm of this many bits (clamped to [0, 1])
  std::vector<std::string> stages{"image.final"};  // the image stages the engine wrote this way

  bool declared() const { return op != ToneOperator::None || exposure != 1.0 || gamma != 1.0 || bits != 0; }
  bool applies_to(const std::string& stage) const;
  /// The continuous transform of one linear colour channel (no quantisation): monotone
  /// non-decreasing in `linear`.
  double apply(double linear) const;
  /// The engine's stored value: apply() rounded to the nearest of 2^bits - 1 steps.
  double encode(double linear) const;
  /// A linear bound b around reference value r carried into display space: the transform's
  /// change over [r - b, r + b] (its secant slope times b, exact for a monotone transform, finite
  /// where gamma's derivative is not) plus the quantisation allowance.
  double carry_bound(double r, double b) const;
  /// What storing to `bits` may add: one step 1/(2^bits - 1), because GL 4.5 §2.3.5.1 lets the
  /// conversion return either of the two nearest values (it only recommends rounding to nearest,
  /// which would need half a step); 0 when not quantised.
  double quantisation_allowance() const;
  /// Whether the transform is concave in the linear value (operator none or reinhard, gamma >= 1,
  /// any exposure and clamp): then |D(a + r) - D(b + r)| <= |D(a) - D(b)| for every r >= 0, so a
  /// display-encoded input decoded within one step of its display value keeps a sum built on it
  /// within one step too (docs/compare.md, "Display transform"). ACES' toe is convex.
  bool decodable() const;
  /// A linear value whose continuous transform is the stored value `stored` (the inverse of
  /// apply()); a saturated stored 1 decodes to the value half a step below 1 where the operator
  /// never reaches 1 (reinhard). Only for decodable() transforms.
  double decode(double stored) const;
};

/// Reads conventions.display; InputError naming `manifest` and the key on anything wrong.
DisplayTransform read_display_transform(const std::string& manifest, const nlohmann::json& j);
nlohmann::json to_json(const DisplayTransform& d);
std::string to_string(ToneOperator op);

}  // namespace vct::cmp
