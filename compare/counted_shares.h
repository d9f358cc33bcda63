// The counted allowances, in one place: the only rules that admit elements by how many they are
// rather than by their value. Each says what it is a share of and why it is a count at all (a
// freedom the reference cannot yet turn into a per-element range); the admission table
// (compare/admission.h) names them in its denominator column and docs/compare.md, "Counted shares",
// derives each.
#pragma once

#include <string>

namespace vct::cmp {

struct CountedShare {
  const char* name;
  double fraction;          // the cap: at most this share of the denominator -> warn, more -> fail
  const char* denominator;  // what the share is of
  const char* why_a_count;  // the freedom it stands for, and why no per-element range replaces it yet
};

// Edge ties: measured legitimate ties reach 1.2 % of the pixels the edge map flags; a one-pixel
// shift puts >= 15 % of them beyond the bound (docs/compare.md, "Edges"). A share of the flagged
// pixels, not of all pixels, so it means the same at every resolution.
inline constexpr CountedShare kEdgeTieShare{
    "edge ties", 0.025, "pixels the edge map flags (2.5 %)",
    "stages without raster alternatives (external references, bare images, shading and cone stages end to end)"};

// Interior pixels beyond the bound, for the models that have an interior share (image_model()).
inline constexpr CountedShare kInteriorShare{
    "interior", 0.001, "all checked pixels (0.1 %)",
    "shading and cone stages end to end: their inputs' ties are not in their bound"};

// Cone-traced stages judged end to end: a voxel that ties upstream moves every cone through it,
// anywhere in the image. The share is kUpstreamFactor x the tied share of occupied voxels, at most
// kUpstreamShare.fraction (docs/compare.md, "Cone stages are judged on the test's own inputs").
inline constexpr CountedShare kUpstreamShare{
    "upstream voxel ties", 0.05, "all checked pixels, and as many edge pixels (min(5 %, 4 x tied voxel share))",
    "end to end only: with a scene the stage is re-judged on the test's own voxels, where no voxel ties"};
inline constexpr double kUpstreamFactor = 4.0;

// voxel.occupancy: ties beyond 1 % of the occupied voxels are a shifted grid, not ties.
inline constexpr CountedShare kOccupancyTieCap{
    "occupancy ties", 0.01, "occupied voxels of the reference (1 %)",
    "a cap on elements each admitted by a value rule (face neighbour, edge fragments): a shift admits every one"};

// voxel.radiance: fragment-count ties (coverage ties) beyond 2 % of the checked voxels are no ties.
inline constexpr CountedShare kFragmentCountTieCap{
    "fragment-count ties", 0.02, "checked voxels of voxel.radiance (2 %)",
    "a cap on voxels whose fragment sets differ; each is still judged within its slack"};

// voxel.radiance: shadow-test ties the shading slack does not see, end to end (the reference's own
// shadow maps) and with a hardware conservative raster; 0 on the test's own maps otherwise.
inline constexpr CountedShare kShadingTieShare{
    "shading ties", 0.005, "checked voxels of voxel.radiance (0.5 %; 0 on the test's own shadow maps)",
    "a texel that ties on GL's own shadow map moves every fragment that samples it; re-injected on the test's maps "
    "there is no such tie"};

inline constexpr const CountedShare* kCountedShares[] = {&kEdgeTieShare,    &kInteriorShare,       &kUpstreamShare,
                                                         &kOccupancyTieCap, &kFragmentCountTieCap, &kShadingTieShare};

/// docs/compare.md's "Counted shares" table (Markdown), written from kCountedShares.
std::string counted_shares_markdown();

}  // namespace vct::cmp
