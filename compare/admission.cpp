#include "compare/admission.h"

#include "compare/counted_shares.h"

namespace vct::cmp {

namespace {

using F = Family;
using K = RuleKind;

// One row per rule, in Rule order (checked by admission_table()). Colours: red is Beyond alone;
// the within-bound rows are black (the mask shows the reference dimmed there, as context).
constexpr std::array<AdmissionRow, kRuleCount> kRows = {{
    {Rule::Beyond, "beyond", F::Image, K::Bound, "", "no rule admits the element: it fails", "",
     "Verdicts", {255, 0, 0}},
    {Rule::WithinBound, "within-bound", F::Image, K::Bound,
     "gbuffer.texture_slack (textured stages), the reference's shadow depth format (light-space depth), the "
     "declared display transform, the reference's slopes (rasterised attributes)",
     "the stage model's abs + rel x abs(ref) + mean and 2^-8 px slope terms, plus the texture slack, 2q of a UNORM "
     "depth format, the bound carried through a display transform",
     "", "Tolerance models and where each bound comes from", {0, 0, 0}},
    {Rule::RasterAlternative, "raster-alternative", F::Image, K::Range, "gbuffer.tie_range (lo/hi of each stage channel)",
     "a surface, facing or alpha test a 2^-8 px vertex snap (GL_SUBPIXEL_BITS) may flip, plus the bound", "",
     "Raster alternatives (issue 13, session 8)", {255, 217, 0}},
    {Rule::LightSpaceAlternative, "light-space-alternative", F::Image, K::Range,
     "shadow_map_tie_range.N / shadow_map_cube_tie_range.N (depth lo/hi)",
     "a depth a 2^-8 texel snap, an alpha-test tie or the UNORM step allows, plus the bound", "",
     "Light space: shadow maps (issue 13, session 12)", {255, 140, 0}},
    {Rule::PcfTapRange, "pcf-tap-range", F::Image, K::Range,
     "gbuffer.tie_range direct/emission groups, re-shaded on the test's own G-buffer and shadow maps",
     "PCF taps the lookup's float arithmetic may flip; a stage without its shadow maps has no range", "",
     "Shading stages on the test's own inputs", {200, 80, 255}},
    {Rule::EdgeNeighbour, "edge-neighbour", F::Image, K::Neighbour,
     "the edge map (image_edges.h: depth or the stage itself; gbuffer.texture_slack alpha_tie)",
     "within the reference's 3x3 range plus the pixel's bound", kEdgeTieShare.denominator,
     "Ties are admissible values (since session 3)", {0, 200, 255}},
    {Rule::EdgeShare, "edge-share", F::Image, K::CountedShare, "the edge map",
     "shading stages at an edge: any value (their inputs' freedom is not in their bound)",
     kEdgeTieShare.denominator, "Edges", {0, 110, 255}},
    {Rule::InteriorShare, "interior-share", F::Image, K::CountedShare, "",
     "stages whose model has an interior share: any value (shading), or an admissible neighbour value",
     kInteriorShare.denominator, "Edges", {150, 0, 255}},
    {Rule::UpstreamShare, "upstream-share", F::Image, K::CountedShare,
     "the voxel stages' ties (occupancy and radiance taint)",
     "cone-traced stages judged end to end: any value, min(5 %, 4 x the tied share of occupied voxels)",
     kUpstreamShare.denominator, "Cone stages are judged on the test's own inputs", {255, 105, 180}},
    {Rule::VolumeWithinBound, "volume-within-bound", F::Volume, K::Bound,
     "voxel.shading_slack and voxel.cas_lo/hi carried up the chain (largest over the level's 2^L cube)",
     "the base model's bound propagated per level (+ one storage rounding per level; x2 per anisotropic level)", "",
     "Tolerance models and where each bound comes from", {0, 0, 0}},
    {Rule::AboveUpstreamTie, "above-upstream-tie", F::Volume, K::Neighbour,
     "voxel.occupancy / voxel.radiance taint of the level's 2^L base cube",
     "any value above a base voxel that ties (the caps of the voxel stages bound how many)", "",
     "Tolerance models and where each bound comes from", {120, 120, 255}},
    {Rule::CoverageTie, "coverage-tie", F::Occupancy, K::Range, "voxel.occupancy_tie",
     "a voxel each fragment of which may drop, or where a fragment GL may make lands, under 2^-8 px vertex "
     "snapping (coverage ties); with surface thickening alone, a voxel those ties may thicken or leave empty",
     "", "Voxel shading slack", {0, 140, 140}},
    {Rule::FaceNeighbourTie, "face-neighbour-tie", F::Occupancy, K::Neighbour, "",
     "a missing voxel with an extra one among its 26 neighbours (a sample on a voxel face, edge or corner)",
     kOccupancyTieCap.denominator, "Tolerance models and where each bound comes from", {0, 200, 255}},
    {Rule::EdgeFragmentsTie, "edge-fragments-tie", F::Occupancy, K::Neighbour, "voxel.fragments",
     "at most 2 fragments on the side that has the voxel (samples on a triangle edge)",
     kOccupancyTieCap.denominator, "Tolerance models and where each bound comes from", {255, 217, 0}},
    {Rule::FillRay, "fill-ray", F::Occupancy, K::Neighbour, "voxel.fragments of both sides",
     "a filled voxel (opaque, no fragments) on an axis ray that crosses a surface difference", "",
     "Tolerance models and where each bound comes from", {0, 180, 90}},
    {Rule::ConservativeHole, "conservative-hole", F::Occupancy, K::Range,
     "the reference's settings (voxelizer = conservative)",
     "a voxel of the conservative set the sample rule leaves empty (a hole of the method, not a bug)", "",
     "Conservative voxelization (issue 15)", {150, 150, 150}},
    {Rule::RadianceWithinBound, "radiance-within-bound", F::Radiance, K::Bound,
     "voxel.fragments, voxel.shading_slack (snap, LOD, coverage ties), voxel.cas_lo/hi, voxel.exact",
     "the storage/reduction model's bound at the voxel's fragment count plus its shading slack; 0 at exact voxels",
     "", "Voxel shading slack", {0, 0, 0}},
    {Rule::ShadingShare, "shading-share", F::Radiance, K::CountedShare, "",
     "any value: shadow-test ties the slack does not see (hardware conservative modes only on the test's maps)",
     kShadingTieShare.denominator, "Voxel radiance on the test's own shadow maps", {255, 105, 180}},
    {Rule::EnergyWithinBound, "energy-within-bound", F::Radiance, K::Bound,
     "each frame's voxel.radiance judgement on the test's own inputs (voxel.frame.<frame>, the last frame's voxel.radiance)",
     "per frame, the sum over the voxels of each one's admitted width (its actual difference where a share or the "
     "occupancy stage admitted it) plus the double sums' rounding",
     "", "Every multibounce frame is judged", {0, 0, 0}},
    {Rule::OwnInputs, "own-inputs", F::Cones, K::Rejudge,
     "the test's G-buffer, direct light, mips, shadow maps and bounce input (with a scene)",
     "the stage's verdict on the reference re-run on the test's own inputs replaces the end-to-end one", "",
     "Cone stages are judged on the test's own inputs", {0, 0, 0}},
    {Rule::MarchEnd, "march-end", F::Cones, K::Range, "re-traces with march_end -1 and +1",
     "the closest of the three admissible march ends, per pixel value of the cone images", "",
     "The march-end tie", {0, 0, 0}},
}};

constexpr bool rows_in_order() {
  for (size_t i = 0; i < kRows.size(); ++i)
    if (size_t(kRows[i].rule) != i) return false;
  return true;
}
static_assert(rows_in_order(), "admission rows must be listed in Rule order");

}  // namespace

const std::array<AdmissionRow, kRuleCount>& admission_table() { return kRows; }

const AdmissionRow& admission_row(Rule r) { return kRows[size_t(r)]; }

bool within_bound_rule(Rule r) {
  return r == Rule::WithinBound || r == Rule::VolumeWithinBound || r == Rule::RadianceWithinBound ||
         r == Rule::EnergyWithinBound;
}

std::string to_string(Family f) {
  switch (f) {
    case Family::Image: return "image";
    case Family::Volume: return "volume";
    case Family::Occupancy: return "occupancy";
    case Family::Radiance: return "radiance";
    case Family::Cones: return "cones";
  }
  return "image";
}

std::string to_string(RuleKind k) {
  switch (k) {
    case RuleKind::Bound: return "bound";
    case RuleKind::Range: return "range";
    case RuleKind::Neighbour: return "neighbour";
    case RuleKind::CountedShare: return "counted share";
    case RuleKind::Rejudge: return "re-judge";
  }
  return "bound";
}

nlohmann::json RuleTally::json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const AdmissionRow& row : kRows)
    if (count[size_t(row.rule)] > 0) j[row.name] = count[size_t(row.rule)];
  return j;
}

std::string admission_table_markdown() {
  std::string md =
      "| rule | family | kind | reads | constant | denominator | derived in |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const AdmissionRow& r : kRows) {
    md += "| `" + std::string(r.name) + "` | " + to_string(r.family) + " | " + to_string(r.kind) + " | " +
          (*r.reads ? r.reads : "-") + " | " + r.constant + " | " + (*r.denominator ? r.denominator : "-") + " | \"" +
          r.doc + "\" |\n";
  }
  return md;
}

}  // namespace vct::cmp
