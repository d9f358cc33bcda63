// The path tracer as a whole: Embree scene + emitter list + integrator, rendering whole passes
// (one sample per pixel each) over 16x16 tiles with parallel_for.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "core/settings.h"
#include "pt/accumulator.h"
#include "pt/embree_scene.h"
#include "pt/emissive_lights.h"
#include "pt/integrator.h"
#include "pt/particle_lights.h"
#include "scene/scene.h"

namespace vct::pt {

class PathTracer {
 public:
  /// Keeps a reference to `scene`; it must outlive the tracer.
  PathTracer(const Scene& scene, const PtSettings& settings, const ParticleOptions& particles = {});

  /// Called after each batch of passes (one parallel loop: several passes per tile on small
  /// images, docs/pathtracer.md "Passes in batches") with the accumulators and the rays traced so
  /// far by this call; returning false stops the render there (acc stays a whole number of passes).
  using AfterPass = std::function<bool(const Accumulator&, const RayCounts&)>;

  /// Adds passes acc.samples() .. target_spp-1 to acc.
  RayCounts render(Accumulator& acc, uint32_t target_spp, const AfterPass& after_pass = nullptr) const;

  const PtSettings& settings() const { return settings_; }
  const EmissiveTriangles& emitters() const { return lights_; }
  const ParticleLights& particles() const { return particles_; }
  const EmbreeScene& embree() const { return rt_; }

 private:
  const Scene& scene_;
  PtSettings settings_;
  EmbreeScene rt_;
  EmissiveTriangles lights_;
  ParticleLights particles_;
  Image particle_layer_;
  Integrator integrator_;
};

}  // namespace vct::pt
