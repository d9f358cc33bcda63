// The stage registry written out: as JSON (`vct stages --json`, and stages.json in a validate
// run directory, which the report reads instead of keeping its own list of names) and as the
// Markdown table of docs/external_format.md ("Stage names"; a test keeps it current).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace vct {

/// One object per row, in pipeline order: name, family ("light", "mip_level" or null), kind,
/// role, dump_stem, tolerance_model, own_inputs, cone_input, channels, pt_aov, what, docs,
/// ref_source, gl_source, walkthrough_step.
nlohmann::json stage_registry_json();

std::string stage_registry_markdown();

}  // namespace vct
