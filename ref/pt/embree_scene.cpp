#include "pt/embree_scene.h"

#include <cstring>
#include <string>

#include "core/error.h"
#include "scene/alpha_mask.h"

namespace vct::pt {

namespace {

void check(RTCDevice device, const char* what) {
  const RTCError err = rtcGetDeviceError(device);
  if (err != RTC_ERROR_NONE)
    throw EnvironmentError(std::string("Embree: ") + what + " failed (error " + std::to_string(int(err)) + ")");
}

// Embree 3 filter function (intersection and occlusion alike): a hit on a cut-away point of an
// alpha-tested triangle is invalidated, so the ray continues to whatever lies behind it.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* data = static_cast<const EmbreeScene::AlphaFilterData*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
    const float b1 = RTCHitN_u(args->hit, args->N, i), b2 = RTCHitN_v(args->hit, args->N, i);
    if (surface_masked(*data->scene, data->triangle[prim], b1, b2)) args->valid[i] = 0;
  }
}

// One triangle geometry over `triangles` (scene triangle indices; all of them when empty).
RTCGeometry triangle_geometry(RTCDevice device, const Scene& scene,
                              const std::vector<uint32_t>& triangles) {
  const size_t count = triangles.empty() ? scene.triangles.size() : triangles.size();
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                        RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                        scene.positions.size()));
  auto* idx = static_cast<uvec3*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), count));
  check(device, "buffer allocation");
  std::memcpy(v, scene.positions.data(), scene.positions.size() * sizeof(vec3));
  if (triangles.empty()) {
    std::memcpy(idx, scene.triangles.data(), scene.triangles.size() * sizeof(uvec3));
  } else {
    for (size_t i = 0; i < count; ++i) idx[i] = scene.triangles[triangles[i]];
  }
  return geom;
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene) {
  device_ = rtcNewDevice("threads=1");
  if (!device_) throw EnvironmentError("Embree: cannot create a device");
  try {
    scene_ = rtcNewScene(device_);
    check(device_, "rtcNewScene");
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    if (scene_has_alpha_test(scene)) {
      masked_ = std::make_unique<AlphaFilterData>();
      masked_->scene = &scene;
      for (uint32_t t = 0; t < uint32_t(scene.triangles.size()); ++t)
        (triangle_alpha_tested(scene, t) ? masked_->triangle : opaque_triangles_).push_back(t);
    }
    if (!scene.triangles.empty() && (!masked_ || !opaque_triangles_.empty())) {
      RTCGeometry geom = triangle_geometry(device_, scene, opaque_triangles_);
      rtcCommitGeometry(geom);
      rtcAttachGeometryByID(scene_, geom, 0);
      rtcReleaseGeometry(geom);
    }
    if (masked_) {
      RTCGeometry geom = triangle_geometry(device_, scene, masked_->triangle);
      rtcSetGeometryUserData(geom, masked_.get());
      rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
      rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
      rtcCommitGeometry(geom);
      rtcAttachGeometryByID(scene_, geom, 1);
      rtcReleaseGeometry(geom);
    }
    rtcCommitScene(scene_);
    check(device_, "scene build");
  } catch (...) {
    if (scene_) rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw;
  }
}

uint32_t EmbreeScene::scene_triangle(uint32_t geom_id, uint32_t prim_id) const {
  if (geom_id == 1) return masked_->triangle[prim_id];
  return opaque_triangles_.empty() ? prim_id : opaque_triangles_[prim_id];
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

Hit EmbreeScene::intersect(const vec3& org, const vec3& dir, float tnear, float tfar) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh{};
  rh.ray.org_x = org.x;
  rh.ray.org_y = org.y;
  rh.ray.org_z = org.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &ctx, &rh);
  Hit h;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
  h.hit = true;
  h.t = rh.ray.tfar;
  h.triangle = scene_triangle(rh.hit.geomID, rh.hit.primID);
  h.b1 = rh.hit.u;
  h.b2 = rh.hit.v;
  return h;
}

bool EmbreeScene::occluded(const vec3& org, const vec3& dir, float tnear, float tfar) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r{};
  r.org_x = org.x;
  r.org_y = org.y;
  r.org_z = org.z;
  r.dir_x = dir.x;
  r.dir_y = dir.y;
  r.dir_z = dir.z;
  r.tnear = tnear;
  r.tfar = tfar;
  r.mask = 0xFFFFFFFFu;
  rtcOccluded1(scene_, &ctx, &r);
  return r.tfar < 0.0f;
}

namespace {
/// The packet's rays in Embree's SoA layout; lanes past n or inactive are invalid (valid = 0).
template <class RayN>
void fill_packet(const EmbreeScene::RayQuery* rays, int n, RayN& r, int* valid) {
  for (int i = 0; i < EmbreeScene::kPacket; ++i) {
    const bool on = i < n && rays[i].active;
    valid[i] = on ? -1 : 0;
    const EmbreeScene::RayQuery q = on ? rays[i] : EmbreeScene::RayQuery{};
    r.org_x[i] = q.org.x;
    r.org_y[i] = q.org.y;
    r.org_z[i] = q.org.z;
    r.dir_x[i] = q.dir.x;
    r.dir_y[i] = q.dir.y;
    r.dir_z[i] = q.dir.z;
    r.tnear[i] = q.tnear;
    r.tfar[i] = q.tfar;
    r.time[i] = 0.0f;
    r.mask[i] = 0xFFFFFFFFu;
    r.id[i] = 0;
    r.flags[i] = 0;
  }
}
}  // namespace

void EmbreeScene::intersect_packet(const RayQuery* rays, int n, Hit* hits) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  alignas(64) RTCRayHit16 rh;
  alignas(64) int valid[kPacket];
  fill_packet(rays, n, rh.ray, valid);
  for (int i = 0; i < kPacket; ++i) {
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect16(valid, scene_, &ctx, &rh);
  for (int i = 0; i < n; ++i) {
    Hit h;
    if (valid[i] && rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID) {
      h.hit = true;
      h.t = rh.ray.tfar[i];
      h.triangle = scene_triangle(rh.hit.geomID[i], rh.hit.primID[i]);
      h.b1 = rh.hit.u[i];
      h.b2 = rh.hit.v[i];
    }
    hits[i] = h;
  }
}

void EmbreeScene::occluded_packet(const RayQuery* rays, int n, bool* occluded) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  alignas(64) RTCRay16 r;
  alignas(64) int valid[kPacket];
  fill_packet(rays, n, r, valid);
  rtcOccluded16(valid, scene_, &ctx, &r);
  for (int i = 0; i < n; ++i) occluded[i] = valid[i] && r.tfar[i] < 0.0f;
}

}  // namespace vct::pt
