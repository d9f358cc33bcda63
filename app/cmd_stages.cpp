// vct stages: the stage registry (stages/stage_registry.h): every stage's name, kind, role, dump
// file, tolerance model and how --scene uses it. --json for scripts and the report, --markdown
// for docs/external_format.md; --rules prints the judge's admission table (compare/admission.h)
// its counted shares and the precision table (core/precision.h), as docs/compare.md holds them.
#include <cstdio>

#include "commands.h"
#include "compare/admission.h"
#include "compare/counted_shares.h"
#include "core/error.h"
#include "core/precision.h"
#include "stages/stage_registry_text.h"

namespace vct::app {

void register_stages(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("stages", "List every stage a frame produces (names of dumps and stage sets)");
  static bool json = false, markdown = false, rules = false;
  cmd->add_flag("--json", json, "Print the registry as JSON");
  cmd->add_flag("--markdown", markdown, "Print the registry as the Markdown table of docs/external_format.md");
  cmd->add_flag("--rules", rules, "Print the judge's admission rules, counted shares and precision table (docs/compare.md)");
  cmd->callback([&exit_code] {
    if (rules)
      std::fputs((cmp::admission_table_markdown() + "\n" + cmp::counted_shares_markdown() + "\n" +
                  precision_table_markdown())
                     .c_str(),
                 stdout);
    else if (json) std::printf("%s\n", stage_registry_json().dump(2).c_str());
    else std::fputs(stage_registry_markdown().c_str(), stdout);
    exit_code = kExitOk;
  });
}

}  // namespace vct::app
