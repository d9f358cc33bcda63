#include "pt/embree_scene.h"

#include <cstring>
#include <string>

#include "core/error.h"

namespace vct::pt {

namespace {

void check(RTCDevice device, const char* what) {
  const RTCError err = rtcGetDeviceError(device);
  if (err != RTC_ERROR_NONE)
    throw EnvironmentError(std::string("Embree: ") + what + " failed (error " + std::to_string(int(err)) + ")");
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
    if (!scene.triangles.empty()) {
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), scene.positions.size()));
      auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(uint32_t), scene.triangles.size()));
      check(device_, "buffer allocation");
      std::memcpy(v, scene.positions.data(), scene.positions.size() * sizeof(vec3));
      std::memcpy(idx, scene.triangles.data(), scene.triangles.size() * sizeof(uvec3));
      rtcCommitGeometry(geom);
      rtcAttachGeometryByID(scene_, geom, 0);
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
  h.triangle = rh.hit.primID;
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

}  // namespace vct::pt
