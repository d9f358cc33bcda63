#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace vct {

vec2 TextureTransform::apply(const vec2& uv) const {
  // glTF KHR_texture_transform: translation * rotation * scale, rotation counter-clockwise in UV
  // space as the extension's matrix defines it.
  const float c = std::cos(rotation), s = std::sin(rotation);
  const vec2 scaled = uv * scale;
  return vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y) + offset;
}

const char* light_kind_name(LightKind kind) {
  switch (kind) {
    case LightKind::Point: return "point";
    case LightKind::Directional: return "directional";
    case LightKind::Spot:
    default: return "spot";
  }
}

mat4 Camera::view() const { return glm::lookAt(position, position + forward, up); }

mat4 Camera::projection(float aspect) const {
  if (orthographic) return glm::ortho(-ymag * aspect, ymag * aspect, -ymag, ymag, znear, zfar);
  return glm::perspective(yfov, aspect, znear, zfar);
}

vec3 Camera::to_eye(const vec3& p) const {
  return orthographic ? -glm::normalize(forward) : glm::normalize(position - p);
}

VoxelVolume fit_volume(const Bounds3& bounds) {
  VoxelVolume v;
  if (bounds.empty()) return v;
  const vec3 e = bounds.extent();
  const float largest = std::max({e.x, e.y, e.z, 1e-6f});
  // 2 % margin so surfaces on the bounds do not sit exactly on the volume's faces, plus one
  // voxel of a 16^3 grid so they stay inside even at the coarsest grid.
  v.size = largest * 1.02f + largest / 16.0f;
  v.origin = bounds.center() - vec3(v.size * 0.5f);
  return v;
}

Camera default_camera(const Bounds3& bounds) {
  Camera c;
  const vec3 center = bounds.empty() ? vec3(0.0f) : bounds.center();
  const float radius = bounds.empty() ? 1.0f : std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
  c.yfov = 0.8f;
  const float dist = radius / std::sin(0.5f * c.yfov);
  c.position = center + vec3(0.0f, 0.0f, dist);
  c.forward = vec3(0.0f, 0.0f, -1.0f);
  c.up = vec3(0.0f, 1.0f, 0.0f);
  c.znear = std::max(dist - radius, 1e-3f) * 0.5f;
  c.zfar = (dist + radius) * 1.5f;
  return c;
}

}  // namespace vct
