// What `vct attribute` and `vct validate --attribute` write and print of a budget
// (docs/attribution.md): the table on stdout, and per component a waterfall PNG and per term a
// heat map (EXR of the RGB difference, PNG of its signed luminance) under <run>/attribution/.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "attribution/attribution.h"
#include "io/run_dir.h"

namespace vct::app {

/// One line per rung, per term (mean, SE, share of the total) and the total with the sum check.
void print_budget(const attr::ComponentBudget& b, const std::string& prefix);

/// Writes the pictures of every component; returns attr::to_json(a) with each component's
/// "files" (paths relative to the run directory). `mask`: the G-buffer's coverage.
nlohmann::json write_attribution(const RunDir& run, const attr::Attribution& a, const Image& mask);

}  // namespace vct::app
