// The settings that are GLSL uniforms of the same name and value, set from the settings table's
// gl_uniform column (ref/core/settings_table.h): a new uniform setting is its table row, not one
// more `set` call per pass. Uniforms a program does not declare are skipped (GL ignores location
// -1, GL 4.5 §7.6.1); derived uniforms (radians, texture units) stay with their passes.
#pragma once

#include "core/settings.h"
#include "gl_program.h"

namespace vct::gl {

void set_setting_uniforms(const Program& p, const VctSettings& s);

}  // namespace vct::gl
