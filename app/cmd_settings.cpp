// vct settings: every setting with its default, allowed values and meaning, from the settings
// table (core/settings_table.h). --markdown prints docs/settings.md.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "core/error.h"
#include "core/settings_table.h"

namespace vct::app {

namespace {
template <typename S>
void print_fields(const std::vector<SettingField<S>>& fields, const S& defaults, const char* scope) {
  for (const auto& f : fields)
    std::printf("  %-30s %-14s %-28s %s\n", (std::string(scope) + f.key).c_str(), value_text(f.get(defaults)).c_str(),
                allowed_text(f).c_str(), f.help);
}
}  // namespace

void register_settings(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("settings", "List every setting (--config keys, --set KEY=VALUE, --sweep KEY=...)");
  static bool markdown = false;
  cmd->add_flag("--markdown", markdown, "Print the table as Markdown (docs/settings.md)");
  cmd->callback([&exit_code] {
    if (markdown) {
      std::fputs(settings_markdown().c_str(), stdout);
    } else {
      std::printf("  %-30s %-14s %-28s %s\n", "key", "default", "allowed", "meaning");
      print_fields(vct_setting_fields(), VctSettings(), "vct.");
      print_fields(pt_setting_fields(), PtSettings(), "pt.");
    }
    exit_code = kExitOk;
  });
}

}  // namespace vct::app
