// Tolerance models per stage (docs/compare.md gives each bound with its source). A model is a
// per-element bound |test - ref| <= abs + rel * |ref| plus the rule for rasterisation ties.
#pragma once

#include <string>

#include "compare/stage_set.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

struct ImageModel {
  ToleranceModel id = ToleranceModel::Filtered;
  std::string name;     // e.g. "d32f-depth"
  double abs = 0.0;     // absolute part of the bound
  double rel = 0.0;     // relative part (times |reference|)
  double abs_of_mean = 0.0;  // extra absolute part, times mean |reference| (scale of the image)
  // Pixels beyond the bound are tolerated where rasterisation may legitimately differ (coverage
  // and shadow-test ties at edges): at most this fraction of the pixels the edge map flags
  // (image_edges.h) -> warn, more -> fail. A share of the flagged pixels, not of all pixels, so it
  // means the same at every resolution (docs/compare.md, "Edges").
  double edge_tie_fraction = 0.0;
  // Beyond-bound pixels away from edges: up to this fraction of all pixels -> warn, more -> fail.
  double interior_fraction = 0.0;
  // Rasterised attributes: vertices snap to a 2^-8 pixel grid (GL_SUBPIXEL_BITS = 8 on llvmpipe
  // and current GPUs; GL requires >= 4), so an interpolated value may move by that much times
  // its screen-space slope: bound += slope_factor * (|d/dx| + |d/dy|) from the reference.
  double slope_factor = 0.0;
  std::string source;  // the freedom the numbers stand for, and where it is specified
};

/// The bound an image model states, written from its numbers (for run.json and the report).
std::string bound_text(const ImageModel& m);

/// Cone-traced stages (they sample the voxels, so voxel ties upstream move them): the registry's
/// own-inputs stages, and image.direct when soft shadows trace it (judged_on_own_inputs).
bool is_cone_traced(const std::string& stage, bool soft_shadows);

/// The model of a tolerance id, and of a stage by its registry row (names the registry does not
/// know are judged as filtered radiance).
ImageModel image_model(ToleranceModel id);
ImageModel image_model(const std::string& stage);

/// Channel of the reference's texture slack image (GBuffer::texture_slack) that widens `stage`'s
/// bound, found by its name ("normal", "albedo", "material", "emission": EXR files store channels
/// sorted by name) or, for an unnamed image, by freedoms/texture_slack.h's order. -1 for stages
/// that are not textured or a slack image without that channel.
int texture_slack_channel(const std::string& stage, const Image& slack);

/// Channel "alpha_tie" of the reference's texture slack image (1 where the alpha test may go
/// either way, freedoms/alpha_ties.h), or -1 when the image has none.
int alpha_tie_channel(const Image& slack);

/// Per-voxel radiance bound at level 0, chosen by how the TEST side stored and reduced voxels.
enum class VoxelModelId {
  FixedPointVsExact,
  FixedPointExactShading,
  CasInterval,
  RunningMeanInterval,
  Rgba8Quantised,
  Rgba16fUlp,
  Rgba32fSum
};

struct VoxelModel {
  VoxelModelId id = VoxelModelId::Rgba32fSum;
  std::string name;  // "fixed-point-exact+shading", "cas-rgba8-interval", "rgba16f-ulp", ...
  double abs = 0.0, rel = 0.0;
  double per_fragment_rel = 0.0;  // float summation order: n * 2^-23 * |ref|
  double half_ulps = 0.0;         // binary16 storage: this many half-ulps of |ref|
  bool cas_interval = false;      // use the reference's interval [cas_lo, cas_hi] +- abs (CAS or running mean)
  std::string source;

  /// |test - ref| allowed for a voxel channel of value `ref` reduced from `fragments` fragments
  /// whose mean may move by `slack` (the reference's shading slack): the binary16 storage term is
  /// taken at |ref| + the rest, where the test's mean may lie (seed 2191: a voxel the reference
  /// leaves dark, GL's mean 0.17 rounded to half by 6e-5, when half-ulp(0) is 2^-24).
  double bound(double ref, double fragments, double slack = 0.0) const;
};

/// The bound a voxel model states, written from its numbers.
std::string bound_text(const VoxelModel& m);

/// `ref_reduction`: how the reference reduced (fixed point is exact only against fixed point).
VoxelModel voxel_model(const std::string& storage, const std::string& reduction,
                       const std::string& ref_reduction = "fixed_point");

/// Bound for mip level `level` (>= 1), propagated from the base model: the box filter is an
/// average of non-negative values, so an abs+rel bound passes through unchanged and each level
/// adds one storage rounding; anisotropic compositing can at most double the bound per level.
struct MipBound {
  double abs = 0.0, rel = 0.0;
};
MipBound mip_bound(const VoxelModel& base, const std::string& storage, int level, bool anisotropic,
                   double cas_width = 0.0);

/// Half-float spacing at |v| (ulp of IEEE binary16; subnormal spacing 2^-24 below 2^-14).
double half_ulp(double v);

}  // namespace vct::cmp
