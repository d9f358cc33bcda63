// The Scene's triangles as Embree 3 triangle geometry (already flattened to world space by the
// loader), owned RAII-style. Queries are thread-safe: rtcIntersect1/rtcOccluded1 run on the
// calling thread. Triangles of alpha-tested materials (glTF alphaMode MASK / BLEND) form a second
// geometry whose intersection and occlusion filter functions reject hits that
// scene/alpha_mask.h's surface_masked() cuts away; the opaque geometry has no filter, and a scene
// without alpha tests builds exactly the one geometry it always did.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

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

  /// Up to kPacket rays at once (rtcIntersect16 / rtcOccluded16): the same answers as intersect()
  /// and occluded() ray by ray, cheaper where the rays are coherent — a path tracer's rays that
  /// leave one point (the first vertex of a pixel's samples: docs/performance.md "Issue 37,
  /// session 17"). Lanes with active[i] = false are not traced (their result is no hit / false).
  static constexpr int kPacket = 16;
  struct RayQuery {
    vec3 org{0.0f}, dir{0.0f};
    float tnear = 0.0f, tfar = 0.0f;
    bool active = false;
  };
  void intersect_packet(const RayQuery* rays, int n, Hit* hits) const;
  void occluded_packet(const RayQuery* rays, int n, bool* occluded) const;

  RTCScene handle() const { return scene_; }

  /// What the masked geometry's filter functions read (geometry user data).
  struct AlphaFilterData {
    const Scene* scene = nullptr;
    std::vector<uint32_t> triangle;  // primitive id -> scene triangle
  };

 private:
  uint32_t scene_triangle(uint32_t geom_id, uint32_t prim_id) const;

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<uint32_t>
      opaque_triangles_;  // geometry 0's primitive -> scene triangle; empty: identity
  std::unique_ptr<AlphaFilterData> masked_;  // geometry 1, or null when no triangle is alpha tested
};

}  // namespace vct::pt
