// One-screen terminal summaries of comparison verdicts and bias (vct compare, vct validate).
#pragma once

#include <string>
#include <vector>

#include "compare/bias.h"
#include "compare/verdict.h"

namespace vct::app {

/// Mip levels are folded into one line per pyramid (worst verdict) so the summary fits a screen.
void print_verdicts(const cmp::Report& report, const std::string& title);
void print_bias(const std::vector<cmp::BiasComponent>& bias);

}  // namespace vct::app
