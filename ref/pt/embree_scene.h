// The Scene's triangles as one Embree 3 triangle geometry (already flattened to world space by the
// loader), owned RAII-style. Queries are thread-safe: rtcIntersect1/rtcOccluded1 run on the
// calling thread.
#pragma once

#include <cstdint>
#include <memory>

#include <embree3/rtcore.h>

#include "core/math.h"
#include "scene/scene.h"

namespace vct::pt {

struct Hit {
  bool hit = false;
  float t = 0.0f;
  uint32_t triangle = 0;
  float b1 = 0.0f, b2 = 0.0f;  // barycentrics of vertices 1 and 2 (Embree's u, v)
};

class EmbreeScene {
 public:
  /// Builds the BVH. The build runs on one Embree thread so the BVH (and thus which of two
  /// coincident triangles a ray reports) cannot depend on the machine's core count.
  explicit EmbreeScene(const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Closest hit on (tnear, tfar); dir need not be unit (t is in units of |dir|).
  Hit intersect(const vec3& org, const vec3& dir, float tnear, float tfar) const;
  /// True if anything lies on (tnear, tfar).
  bool occluded(const vec3& org, const vec3& dir, float tnear, float tfar) const;

  RTCScene handle() const { return scene_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace vct::pt
