// A fragment's light split per light, so the judge's first-order slacks can bound a change that
// crosses a light's horizon.
//
// The slacks (freedoms/fragment_slack.h) sum each freedom's change taken alone. A light's diffuse
// term is albedo E max(n.l, 0) vis / pi: flat below the horizon, so freedoms that only together turn
// a light past it would each show no change (seed 559: a normal map's LOD and its 8-bit precision
// lit a fragment whose every single freedom leaves the light behind it). Taken on the signed
// cosine each shows its share, and |max(a, 0) - max(b, 0)| <= |a - b| keeps the sum a bound; but
// only light by light: summed first, one light's signed change may cancel another's (seed 248).
#pragma once

#include <vector>

#include "core/math.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "scene/surface.h"
#include "stages/inject.h"
#include "stages/shadow_map.h"

namespace vct {

struct LightTerms {
  vec3 rest{0.0f};                // emission + bounce
  std::vector<vec3> per_light;    // albedo E (n.l) vis / pi with the signed n.l
  std::vector<float> n_dot_l;     // each light's n.l (0 where the light sends nothing)
};

/// The terms of light_leaving (stages/inject.h) for fragment `f` with material `m`.
LightTerms light_terms(const Scene& scene, const VoxelFragment& f, const SurfaceMaterial& m,
                       const std::vector<ShadowMap>& maps, const VctSettings& settings, const BounceLight* bounce);

/// A bound on |light_leaving(a) - light_leaving(b)| (largest channel) that a sum over freedoms
/// keeps to first order: the lights in front of both summed with emission and bounce, every other
/// light's signed change on its own.
float light_change(const LightTerms& a, const LightTerms& b);

}  // namespace vct
