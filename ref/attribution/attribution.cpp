#include "attribution/attribution.h"

#include <algorithm>

#include "attribution/diffuse_ladder.h"
#include "attribution/direct_ladder.h"
#include "attribution/ladder_context.h"
#include "attribution/specular_ladder.h"
#include "core/error.h"
#include "freedoms/reference_frame.h"

namespace vct::attr {

const std::vector<std::string>& component_names() {
  static const std::vector<std::string> names = {"indirect_diffuse", "indirect_specular", "direct"};
  return names;
}

bool Attribution::sums_to_totals() const {
  return std::all_of(components.begin(), components.end(), [](const ComponentBudget& b) { return b.sums_to_total(); });
}

void check_components(const std::vector<std::string>& names, const std::string& flag) {
  const auto& known = component_names();
  for (const std::string& n : names)
    if (std::find(known.begin(), known.end(), n) == known.end())
      throw InputError(flag, "unknown component '" + n + "' (known: indirect_diffuse, indirect_specular, direct)");
}

void check_attributable(const VctSettings& vs) {
  if (!vs.diffuse_cone_set.empty() || vs.cone_tangent_frame != ConeTangentFrame::Branchless)
    throw InputError("settings", "vct attribute splits the diffuse_cone_count/tilt set; diffuse_cone_set and "
                                 "cone_tangent_frame are for vct render and vct compare");
  if (vs.indirect_diffuse_gain != 1.0f || vs.indirect_fresnel != IndirectFresnel::Schlick)
    throw InputError("settings", "vct attribute splits the oracle's own composite; indirect_diffuse_gain and "
                                 "indirect_fresnel are for vct render and vct compare");
  if (vs.specular_offset_voxels >= 0.0f || vs.specular_quality > 0.0f || vs.specular_aperture != SpecularAperture::Ggx ||
      vs.specular_view != SpecularView::Surface)
    throw InputError("settings", "vct attribute splits the oracle's specular cone; specular_offset_voxels, "
                                 "specular_quality, specular_aperture and specular_view are for vct render and vct "
                                 "compare");
}

Attribution attribute_frame(const Scene& scene, const Settings& settings, const FrameResult& frame,
                            const AttributionOptions& opt) {
  check_components(opt.components, "--components");
  check_attributable(settings.vct);
  const LadderContext ctx(scene, settings, frame, opt.rays_per_pixel, opt.pt_cache);
  Attribution a;
  for (const std::string& name : component_names()) {
    if (!opt.components.empty() &&
        std::find(opt.components.begin(), opt.components.end(), name) == opt.components.end())
      continue;
    if (name == "indirect_diffuse")
      a.components.push_back(run_ladder(name, diffuse_rungs(ctx), diffuse_term_names(), ctx.mask()));
    else if (name == "indirect_specular")
      a.components.push_back(run_ladder(name, specular_rungs(ctx), specular_term_names(), ctx.mask()));
    else
      a.components.push_back(run_ladder(name, direct_rungs(ctx), direct_term_names(), ctx.mask()));
  }
  return a;
}

Attribution attribute(const Scene& scene, const Settings& settings, const AttributionOptions& opt) {
  check_components(opt.components, "--components");
  const FrameResult frame = render_ref_frame(scene, settings);
  return attribute_frame(scene, settings, frame, opt);
}

namespace {
nlohmann::json mean_se(const MeanSe& m) { return {{"mean", m.mean}, {"se", m.se}}; }
}  // namespace

nlohmann::json to_json(const ComponentBudget& b) {
  nlohmann::json j;
  j["component"] = b.component;
  j["pixels"] = b.total.value.pixels;
  nlohmann::json rungs = nlohmann::json::array();
  for (size_t k = 0; k < b.rungs.size(); ++k) {
    nlohmann::json r = mean_se(b.rungs[k]);
    r["name"] = b.rung_names[k];
    r["what"] = b.rung_whats[k];
    rungs.push_back(r);
  }
  j["rungs"] = rungs;
  nlohmann::json terms = nlohmann::json::array();
  for (const Term& t : b.terms) {
    nlohmann::json r = mean_se(t.value);
    r["name"] = t.name;
    r["share_of_total"] = b.total.value.mean != 0.0 ? t.value.mean / b.total.value.mean : 0.0;
    terms.push_back(r);
  }
  j["terms"] = terms;
  j["total"] = mean_se(b.total.value);
  j["sum_of_terms"] = {{"mean", b.sum_of_terms}, {"se", b.sum_se}};
  j["sum_check"] = {{"discrepancy", b.discrepancy},
                    {"se", b.discrepancy_se},
                    {"rounding", b.rounding},
                    {"sigmas", kSumCheckSigmas},
                    {"pass", b.sums_to_total()}};
  return j;
}

nlohmann::json to_json(const Attribution& a) {
  nlohmann::json j = nlohmann::json::array();
  for (const ComponentBudget& b : a.components) j.push_back(to_json(b));
  return j;
}

}  // namespace vct::attr
