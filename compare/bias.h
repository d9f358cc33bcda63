// Bias of VCT against the path tracer, per component (docs/compare.md §Bias). Judged against the
// path tracer's own noise: a pixel counts as biased only when |VCT - PT| > k sigma_PT, where
// sigma_PT comes from the path tracer's per-pixel variance of its mean (the _var AOVs).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/metrics.h"
#include "compare/stage_set.h"

namespace vct::cmp {

struct BiasComponent {
  std::string component, vct_stage, pt_aov;
  bool available = false;
  std::string note;
  ImageMetrics metrics;  // test = VCT, reference = PT
  bool have_variance = false;
  double k = 3.0;
  double fraction_beyond_k_sigma = 0.0;  // fraction of pixels with |VCT - PT| > k sigma
  double expected_fraction = 0.0;        // what PT noise alone would give (two-sided normal tail)
  double mean_bias_z = 0.0;              // mean luminance bias over its standard error
  bool significant = false;              // bias clearly beyond PT noise
  std::string heatmap, zmap;             // PNGs relative to the run dir
};

struct BiasOptions {
  double k = 3.0;
  std::string out_dir;     // where heat maps go ("" = none)
  std::string out_prefix;  // their names relative to the run dir
};

/// The component pairs measured (VCT stage -> PT AOV).
const std::vector<std::pair<std::string, std::string>>& bias_pairs();

/// `pt` maps AOV names ("pt_full", "pt_full_var", ...) to images.
std::vector<BiasComponent> measure_bias(const StageSet& vct, const std::map<std::string, Image>& pt,
                                        const BiasOptions& opt = {});

nlohmann::json to_json(const BiasComponent& b);

/// Reads every pt_*.exr in `dir` (the path tracer's AOVs); empty map when none.
std::map<std::string, Image> read_pt_aovs(const std::string& dir);

}  // namespace vct::cmp
