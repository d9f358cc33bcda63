// The settings table: each field of VctSettings and PtSettings declared once (key, member, type,
// range, help, GL uniform) and read by everything that handles settings: JSON in and out
// (--config, run.json, stage-set manifests), range checks, `--set KEY=VALUE`, `--sweep`,
// `vct settings` (the list in --help and docs/settings.md) and the GL passes' uniforms.
// Adding a setting is its member in settings.h plus one row in settings_table.cpp
// (docs/CONVENTIONS.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/settings.h"

namespace vct {

enum class SettingType { Int, Float, Bool, Choice, Text };

/// Allowed values of a number: [lo, hi] with either end open, optionally powers of two only or a
/// short list (`only`).
struct SettingRange {
  double lo = 0.0, hi = 0.0;
  bool lo_open = false, hi_open = false;
  bool power_of_two = false;
  std::vector<int> only;
  bool unbounded = false;  // any value of the type (seeds, frame indices)
};

template <typename S>
struct SettingField {
  const char* key;
  SettingType type;
  SettingRange range;  // numbers only
  const char* help;
  const char* gl_uniform;            // the GLSL uniform it sets (nullptr: not a uniform)
  std::vector<std::string> choices;  // Choice only: the JSON names
  std::function<nlohmann::json(const S&)> get;
  // Type-checked assignment from JSON; throws InputError("", "setting '<scope><key>' ...").
  std::function<void(S&, const nlohmann::json&, const std::string& scope)> set;
};

const std::vector<SettingField<VctSettings>>& vct_setting_fields();
const std::vector<SettingField<PtSettings>>& pt_setting_fields();

/// "16..512, a power of two", "(0, 180)", "1, 4 or 8", "true|false", "gltf|seed".
template <typename S>
std::string allowed_text(const SettingField<S>& f);

/// Throws InputError("", "<scope><key> must be <allowed> (got <value>)") for a number out of range.
template <typename S>
void check_setting_range(const SettingField<S>& f, const S& s, const std::string& scope);

/// "KEY=VALUE" text to the JSON value the field takes: numbers and booleans parsed, choices and
/// text as strings. Throws InputError naming `what` (e.g. "--set") for malformed text.
nlohmann::json setting_value_from_text(SettingType type, const std::string& text, const std::string& what);

/// A setting's value as people write it: floats shortest ("0.0005", not 0.0005000000237),
/// choices and text unquoted.
std::string value_text(const nlohmann::json& v);

/// `s` with one field set from text: `key` is "vct.K", "pt.K" or a bare vct key K; the text is
/// parsed by the field's type. Not validated (validate_settings checks the ranges). Throws
/// InputError(what, ...) naming an unknown key or malformed text.
Settings with_setting(const Settings& s, const std::string& key, const std::string& text, const std::string& what);

/// The table as Markdown (docs/settings.md is this output; a test keeps it current).
std::string settings_markdown();

}  // namespace vct
