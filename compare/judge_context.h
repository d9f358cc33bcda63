// What the judge's passes learn about one comparison and hand to the stages judged after them:
// derived from the two sets (and, on the test's own inputs, from the isolated pass), never set by a
// user. CompareOptions (stage_compare.h) holds what a user chooses.
#pragma once

#include "compare/counted_shares.h"

namespace vct::cmp {

struct JudgeContext {
  // Direct light was cone-traced (either set's settings): image.direct is then a cone stage.
  bool soft_shadows = false;
  // Share of the reference's occupied voxels that tie (occupancy or radiance taint): cone-traced
  // images judged end to end may differ on kUpstreamFactor x this share (compare/counted_shares.h).
  double upstream_tie_fraction = 0.0;
  // Light-space depth stages: one UNORM step q = 1/(2^b - 1) of the reference's
  // shadow_depth_format (0 for float); the depth bound grows by 2q (docs/compare.md).
  double depth_quantum = 0.0;
  // The re-traced composite added the test's display-encoded image.direct decoded through the
  // declared transform: image.final's display bound grows by one step of its bit depth.
  bool direct_decoded_from_display = false;
  // voxel.radiance's share of shading ties (kShadingTieShare); 0 on the test's own shadow maps.
  double shading_tie_fraction = kShadingTieShare.fraction;
};

}  // namespace vct::cmp
