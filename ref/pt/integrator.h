// One path sample of one pixel: next-event estimation to the punctual lights (spot and point: a
// delta in position; directional: a delta in direction; no MIS) and
// to emissive triangles (area sampling, power-heuristic MIS with BSDF sampling), BSDF importance
// sampling, Russian roulette. Returns the contribution split into the AOVs that mirror the VCT
// components (docs/pathtracer.md defines each one).
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/settings.h"
#include "pt/bsdf_sampling.h"
#include "pt/emissive_lights.h"
#include "pt/embree_scene.h"
#include "pt/particle_lights.h"
#include "pt/path_sampler.h"
#include "scene/scene.h"

namespace vct::pt {

/// AOVs in accumulator order.
enum Aov : int { kFull = 0, kDirect, kEmission, kIndirectDiffuse, kIndirectSpecular, kParticles, kAovCount };
constexpr const char* kAovNames[kAovCount] = {"pt_full",           "pt_direct",
                                              "pt_emission",       "pt_indirect_diffuse",
                                              "pt_indirect_specular", "pt_particles"};

struct PathSample {
  vec3 aov[kAovCount] = {vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f), vec3(0.0f)};
};

/// Ray counts (primary = camera rays, secondary = BSDF continuation rays, shadow = NEE rays).
struct RayCounts {
  uint64_t primary = 0, secondary = 0, shadow = 0;
  uint64_t nonfinite_samples = 0;  // samples dropped because a value was NaN/inf (should stay 0)
  void add(const RayCounts& o) {
    primary += o.primary;
    secondary += o.secondary;
    shadow += o.shadow;
    nonfinite_samples += o.nonfinite_samples;
  }
  uint64_t total() const { return primary + secondary + shadow; }
};

class Integrator {
 public:
  /// particles / particle_layer may be null (no fire). particle_layer: the camera's additive
  /// particle image (ParticleLights::camera_layer), added to every sample of its pixel.
  Integrator(const Scene& scene, const EmbreeScene& rt, const EmissiveTriangles& lights, const PtSettings& s,
             const ParticleLights* particles = nullptr, const Image* particle_layer = nullptr);

  /// Sample `sample` of pixel (x, y); deterministic in (x, y, sample, settings.seed).
  PathSample trace(int x, int y, uint32_t sample, RayCounts& counts) const;

  /// Throughput from the camera to the current vertex, and the parts of it that left the first
  /// vertex through its diffuse / specular lobe (for the one-bounce AOVs).
  struct Throughput {
    vec3 beta{1.0f}, lobe_d{0.0f}, lobe_s{0.0f};
  };

  /// A shading point: BSDF (bp.n is the oriented shading normal), true position, lifted ray
  /// origin, depth.
  struct Vertex {
    BsdfPoint bp;
    vec3 pos;  // on the surface: light geometry is evaluated here
    vec3 p;    // lifted along ng: rays start here
    uint32_t triangle;
    int depth;
  };

  /// What every sample of a pixel shares (issue 16): camera rays go through the pixel centre, so
  /// the primary hit, its shading, its emission and its punctual-light NEE use no random number
  /// and are the same for every sample. trace(first_vertex(x, y), x, y, s) gives the same floats
  /// as trace(x, y, s); a renderer computes first_vertex once per pixel and reuses it.
  struct FirstVertex {
    PathSample out;        // the particle layer, the first hit's emission and punctual light
    bool continues = false;  // a hit within max_depth: the path goes on from `vertex`
    Vertex vertex{};
  };
  /// Traces the camera ray of pixel (x, y) and shades its hit (counted in `counts`).
  FirstVertex first_vertex(int x, int y, RayCounts& counts) const;
  /// Sample `sample` of pixel (x, y) from its first vertex.
  PathSample trace(const FirstVertex& first, int x, int y, uint32_t sample, RayCounts& counts) const;
  /// One sample of a pixel from its first vertex (FirstVertex::continues may be false).
  struct Lane {
    const FirstVertex* first = nullptr;
    int x = 0, y = 0;
    uint32_t sample = 0;
  };
  /// n <= EmbreeScene::kPacket samples, of one pixel or of several, into out[0 … n−1]: the same
  /// floats as n calls of trace(), but the first vertices' emitter shadow rays and BSDF rays —
  /// from one point, or from neighbouring pixels' points — go to Embree as one packet each
  /// (docs/performance.md "Issue 37, session 17").
  void trace_packet(const Lane* lanes, int n, PathSample* out, RayCounts& counts) const;

 private:
  /// Shades the vertex at `hit` reached along `dir`: its emission (MIS-weighted past the first
  /// vertex) and punctual NEE into `out`. False when the path ends there (depth > max_depth).
  bool shade(const Hit& hit, const vec3& dir, int depth, const Throughput& tp, float prev_pdf, PathSample& out,
             RayCounts& counts, Vertex& v) const;
  void nee_punctual(const Vertex& v, const Throughput& tp, PathSample& out, RayCounts& counts) const;
  void nee_emitters(const Vertex& v, const Throughput& tp, PathSampler& rng, PathSample& out, RayCounts& counts) const;
  /// The emitter NEE up to its shadow ray: the ray (inactive when the sample contributes nothing)
  /// and what credit_emitter needs if the ray is unoccluded.
  struct NeeRay {
    EmbreeScene::RayQuery ray;
    BsdfValue f;
    vec3 l{0.0f}, le{0.0f};
    float pdf_light = 0.0f, bsdf_pdf = 0.0f;
  };
  NeeRay emitter_ray(const Vertex& v, PathSampler& rng) const;
  /// An unoccluded emitter sample's light, MIS-weighted against BSDF sampling.
  void credit_emitter(const Vertex& v, const Throughput& tp, const NeeRay& r, PathSample& out) const;
  /// The BSDF sample at v, the throughput through it and Russian roulette: false when the path
  /// ends there.
  bool scatter(const Vertex& v, Throughput& tp, PathSampler& rng, BsdfSample& bs) const;
  /// The path from vertex v on (its NEE, then bounce after bounce), adding into out; v is
  /// overwritten by each vertex reached.
  void continue_path(Vertex& v, Throughput& tp, PathSampler& rng, PathSample& out, RayCounts& counts) const;
  /// Sets out to 0 when a value is NaN/inf (counted).
  static void drop_nonfinite(PathSample& out, RayCounts& counts);
  void nee_particles(const Vertex& v, const Throughput& tp, PathSampler& rng, PathSample& out, RayCounts& counts) const;

  const Scene& scene_;
  const EmbreeScene& rt_;
  const EmissiveTriangles& lights_;
  const ParticleLights* particles_;
  const Image* particle_layer_;
  PtSettings settings_;
  int light_model_;
  float eps_;  // ray offset, scaled to the scene's size
  /// tnear of a ray that leaves a vertex from its lifted origin (Vertex::p) along `ray` (any
  /// length): the first eps_ of its length is skipped. The lift alone does not clear a surface
  /// that meets this one at a concave edge: a vertex exactly on the floor–wall corner of a box,
  /// lifted along the floor's normal, starts *on* the wall, and a ray with tnear = 0 reports the
  /// wall at t = 0 (Embree's hits are t >= tnear) — every such vertex came out in shadow. Camera
  /// rays through pixel centres land on such edges exactly in symmetric views (the Cornell box's
  /// floor corners lie on the image diagonals): docs/pathtracer.md "Leaving a surface".
  float leave_tnear(const vec3& ray) const { return eps_ / glm::length(ray); }
  float sun_ray_length_;  // a directional light's shadow ray: leaves the scene from any vertex
  std::vector<vec2> spot_cos_;  // per light: cos(inner), cos(outer), computed once
};

}  // namespace vct::pt
