#include "gl_setting_uniforms.h"

#include "core/settings_table.h"

namespace vct::gl {

void set_setting_uniforms(const Program& p, const VctSettings& s) {
  for (const auto& f : vct_setting_fields()) {
    if (!f.gl_uniform || p.location(f.gl_uniform) < 0) continue;
    const nlohmann::json v = f.get(s);
    switch (f.type) {
      case SettingType::Bool: p.set(f.gl_uniform, v.get<bool>() ? 1 : 0); break;  // GLSL int flags
      case SettingType::Int: p.set(f.gl_uniform, v.get<int>()); break;
      case SettingType::Float: p.set(f.gl_uniform, v.get<float>()); break;
      case SettingType::Choice:
      case SettingType::Text: break;  // no table row maps these to a uniform
    }
  }
}

}  // namespace vct::gl
