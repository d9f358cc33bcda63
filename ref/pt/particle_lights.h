// Fire particles in the path tracer, as the same emitters the VCT pipelines use
// (sh::particle_state via particles_at, at the VCT settings' time):
//  * seen by the camera: the identical additive layer (a disc facing the eye, radiance
//    colour * particle_profile, depth-tested against the first surface) -> AOV pt_particles;
//  * lighting the scene: each particle is an isotropic point light of intensity
//    colour * pi r^2 / 2 (the disc's power per solid angle seen face-on: mean profile 1/2 times
//    its area), the same power the voxel injection gives it. Translucent: never occludes.
// See docs/pathtracer.md for what this approximation leaves out.
#pragma once

#include <vector>

#include "core/image.h"
#include "core/math.h"
#include "pt/alias_table.h"
#include "pt/embree_scene.h"
#include "scene/scene.h"
#include "shared/vct_shared.h"

namespace vct::pt {

struct ParticleOptions {
  bool enabled = true;  // VctSettings::particles
  float time = 1.0f;    // VctSettings::time
};

class ParticleLights {
 public:
  ParticleLights(const Scene& scene, const ParticleOptions& opt);

  bool empty() const { return particles_.empty(); }
  size_t size() const { return particles_.size(); }

  struct Sample {
    vec3 position{0.0f};
    vec3 intensity{0.0f};  // radiance x area: irradiance at distance d is intensity * cos / d^2
    float pmf = 0.0f;      // probability of having picked this particle
  };
  Sample sample(float u) const;

  /// The camera's additive particle layer for pixel-centre rays (3 channels, row 0 = top).
  Image camera_layer(const Scene& scene, const EmbreeScene& rt, int width, int height) const;

 private:
  std::vector<sh::ParticleState> particles_;
  AliasTable pick_;  // by luminance of the intensity
};

}  // namespace vct::pt
