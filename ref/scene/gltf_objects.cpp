// Things a glTF node carries besides meshes: the camera, KHR_lights_punctual lights (spot, point, directional), our
// fire particle emitters (extras.vct_particles) and the voxel volume override (extras.vct_volume).
// Schemas and units: docs/scenes.md.
#include <cmath>

#include "scene/gltf_internal.h"

namespace vct::gltf {
namespace {

vec3 transform_point(const mat4& m, const vec3& p) { return vec3(m * vec4(p, 1.0f)); }

vec3 transform_dir(const mat4& m, const vec3& d) {
  const vec3 v = mat3(m) * d;
  const float len = glm::length(v);
  return len > 0.0f ? v / len : d;
}

// A small typed reader for our own extras objects, with messages naming the key.
struct ExtrasReader {
  const Context& ctx;
  const tinygltf::Value& obj;
  std::string owner;

  bool has(const char* key) const { return obj.Has(key); }
  float num(const char* key, float fallback) const {
    if (!obj.Has(key)) return fallback;
    const auto& v = obj.Get(key);
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) fail(ctx, owner + "." + key + " must be a finite number");
    return float(v.GetNumberAsDouble());
  }
  vec3 vec(const char* key, vec3 fallback) const {
    if (!obj.Has(key)) return fallback;
    const auto& v = obj.Get(key);
    bool ok = v.IsArray() && v.ArrayLen() == 3;
    for (int i = 0; ok && i < 3; ++i) ok = v.Get(i).IsNumber() && std::isfinite(v.Get(i).GetNumberAsDouble());
    if (!ok) fail(ctx, owner + "." + key + " must be an array of 3 finite numbers");
    return vec3(float(v.Get(0).GetNumberAsDouble()), float(v.Get(1).GetNumberAsDouble()),
                float(v.Get(2).GetNumberAsDouble()));
  }
  void only_keys(std::initializer_list<const char*> allowed) const {
    for (const auto& k : obj.Keys()) {
      bool known = false;
      for (const char* a : allowed) known = known || k == a;
      if (!known) fail(ctx, owner + " has unknown key '" + k + "' (schema: docs/scenes.md)");
    }
  }
};

}  // namespace

Camera make_camera(const Context& ctx, int camera, const mat4& world) {
  const auto& c = ctx.model.cameras[static_cast<size_t>(camera)];
  const std::string owner = "camera " + std::to_string(camera);
  Camera out;
  if (c.type == "orthographic") {
    // glTF 2.0 §3.10.3: xmag/ymag are half the view's width/height; zfar is required and finite.
    const auto& o = c.orthographic;
    if (!(o.ymag > 0.0) || !std::isfinite(o.ymag) || !(o.xmag > 0.0) || !std::isfinite(o.xmag) ||
        !(o.znear >= 0.0) || !std::isfinite(o.zfar) || !(o.zfar > o.znear)) {
      fail(ctx, owner + " (orthographic) needs xmag > 0, ymag > 0 (a mirrored view is not supported) and 0 <= znear < zfar, all finite");
    }
    out.orthographic = true;
    out.ymag = float(o.ymag);
    out.znear = float(o.znear);
    out.zfar = float(o.zfar);
  } else if (c.type == "perspective") {
    const auto& p = c.perspective;
    if (!(p.yfov > 0.0 && p.yfov < 3.14159265358979) || !(p.znear > 0.0) || !std::isfinite(p.zfar) ||
        (p.zfar != 0.0 && p.zfar <= p.znear)) {
      fail(ctx, owner + " has an invalid yfov/znear/zfar");
    }
    if (!(p.aspectRatio >= 0.0) || !std::isfinite(p.aspectRatio)) fail(ctx, owner + " has an invalid aspectRatio");
    out.yfov = float(p.yfov);
    out.aspect_ratio = float(p.aspectRatio);  // 0: absent (tinygltf's default)
    out.znear = float(p.znear);
    out.zfar = float(p.zfar);  // 0 (infinite) is replaced by the loader once bounds are known
  } else {
    fail(ctx, owner + " has type '" + c.type + "'; glTF defines perspective and orthographic");
  }
  out.position = transform_point(world, vec3(0.0f));
  out.forward = transform_dir(world, vec3(0.0f, 0.0f, -1.0f));
  out.up = transform_dir(world, vec3(0.0f, 1.0f, 0.0f));
  out.from_file = true;
  return out;
}

void validate_lights(const Context& ctx) {
  for (size_t i = 0; i < ctx.model.lights.size(); ++i) {
    const auto& l = ctx.model.lights[i];
    const std::string owner = "light " + std::to_string(i) + (l.name.empty() ? "" : " '" + l.name + "'");
    if (l.type != "spot" && l.type != "point" && l.type != "directional") {
      fail(ctx, owner + " has type '" + l.type + "'; KHR_lights_punctual defines spot, point and directional");
    }
    const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    // inner == outer (a hard spot, Blender's Blend 0) is accepted and rendered as a step (warn_hard_spots).
    if (l.type == "spot" && (!(outer > 0.0 && outer <= 0.5 * 3.14159265358979 + 1e-6) || !(inner >= 0.0 && inner <= outer))) {
      fail(ctx, owner + " needs 0 <= innerConeAngle <= outerConeAngle <= pi/2");
    }
    if (!(l.intensity >= 0.0) || !std::isfinite(l.intensity) || !(l.range >= 0.0) || !std::isfinite(l.range)) {
      fail(ctx, owner + " has an invalid intensity or range");
    }
    if (!l.color.empty() && l.color.size() != 3) fail(ctx, owner + " color must have 3 components");
    for (double c : l.color) {
      if (!(c >= 0.0) || !std::isfinite(c)) fail(ctx, owner + " has an invalid color");
    }
  }
}

void warn_hard_spots(const Context& ctx, std::vector<std::string>& warnings) {
  for (size_t i = 0; i < ctx.model.lights.size(); ++i) {
    const auto& l = ctx.model.lights[i];
    if (l.type != "spot" || l.spot.innerConeAngle < l.spot.outerConeAngle) continue;
    warnings.push_back("light " + std::to_string(i) + (l.name.empty() ? "" : " '" + l.name + "'") +
                       ": innerConeAngle == outerConeAngle (a hard spot; the Khronos validator flags it): rendered "
                       "as a step, lit strictly inside the outer cone, in every engine");
  }
}

Light make_light(const Context& ctx, int light, const mat4& world) {
  const auto& l = ctx.model.lights[static_cast<size_t>(light)];
  Light s;
  s.name = l.name.empty() ? "light_" + std::to_string(light) : l.name;
  s.kind = l.type == "point" ? LightKind::Point : l.type == "directional" ? LightKind::Directional : LightKind::Spot;
  s.position = transform_point(world, vec3(0.0f));
  s.direction = transform_dir(world, vec3(0.0f, 0.0f, -1.0f));  // KHR_lights_punctual: lights point along -Z
  if (l.color.size() == 3) s.color = vec3(float(l.color[0]), float(l.color[1]), float(l.color[2]));
  s.intensity = float(l.intensity);
  if (s.is_spot()) {
    s.inner_cone_angle = float(l.spot.innerConeAngle);
    s.outer_cone_angle = float(l.spot.outerConeAngle);
  }
  // KHR_lights_punctual: "range ... only for point and spot lights"; a directional light has none.
  s.range = s.is_directional() ? 0.0f : float(l.range);
  return s;
}

bool read_particles(const Context& ctx, int node, const mat4& world, ParticleEmitter& out) {
  const auto& n = ctx.model.nodes[static_cast<size_t>(node)];
  if (!n.extras.IsObject() || !n.extras.Has("vct_particles")) return false;
  const std::string owner = "node " + std::to_string(node) + " extras.vct_particles";
  const auto& obj = n.extras.Get("vct_particles");
  if (!obj.IsObject()) fail(ctx, owner + " must be an object");
  const ExtrasReader r{ctx, obj, owner};
  r.only_keys({"count", "lifetime", "spawn_extent", "velocity_min", "velocity_max", "acceleration", "color_start",
               "color_end", "size_start", "size_end"});
  ParticleEmitter e;
  e.name = n.name.empty() ? "emitter_" + std::to_string(node) : n.name;
  e.origin = transform_point(world, vec3(0.0f));
  const float count = r.num("count", float(e.count));
  if (!(count >= 1.0f && count <= 1e6f) || count != std::floor(count)) fail(ctx, owner + ".count must be an integer in 1..1000000");
  e.count = int(count);
  e.lifetime = r.num("lifetime", e.lifetime);
  if (!(e.lifetime > 0.0f)) fail(ctx, owner + ".lifetime must be > 0");
  e.spawn_extent = r.vec("spawn_extent", e.spawn_extent);
  e.velocity_min = r.vec("velocity_min", e.velocity_min);
  e.velocity_max = r.vec("velocity_max", e.velocity_max);
  e.acceleration = r.vec("acceleration", e.acceleration);
  e.color_start = r.vec("color_start", e.color_start);
  e.color_end = r.vec("color_end", e.color_end);
  e.size_start = r.num("size_start", e.size_start);
  e.size_end = r.num("size_end", e.size_end);
  if (glm::any(glm::lessThan(e.spawn_extent, vec3(0.0f))) || e.size_start < 0.0f || e.size_end < 0.0f ||
      glm::any(glm::lessThan(glm::min(e.color_start, e.color_end), vec3(0.0f)))) {
    fail(ctx, owner + ": spawn_extent, sizes and colours must be >= 0");
  }
  out = e;
  return true;
}

bool read_volume_override(const Context& ctx, VoxelVolume& volume) {
  const tinygltf::Value* found = nullptr;
  std::string owner;
  if (ctx.model.asset.extras.IsObject() && ctx.model.asset.extras.Has("vct_volume")) {
    found = &ctx.model.asset.extras.Get("vct_volume");
    owner = "asset extras.vct_volume";
  }
  const int s = ctx.model.defaultScene >= 0 ? ctx.model.defaultScene : 0;
  if (!found && static_cast<size_t>(s) < ctx.model.scenes.size()) {
    const auto& ex = ctx.model.scenes[static_cast<size_t>(s)].extras;
    if (ex.IsObject() && ex.Has("vct_volume")) {
      found = &ex.Get("vct_volume");
      owner = "scene extras.vct_volume";
    }
  }
  if (!found) return false;
  if (!found->IsObject()) fail(ctx, owner + " must be an object {\"origin\": [x,y,z], \"size\": s}");
  const ExtrasReader r{ctx, *found, owner};
  r.only_keys({"origin", "size"});
  if (!r.has("origin") || !r.has("size")) fail(ctx, owner + " needs both origin and size");
  volume.origin = r.vec("origin", vec3(0.0f));
  volume.size = r.num("size", 1.0f);
  if (!(volume.size > 0.0f)) fail(ctx, owner + ".size must be > 0");
  volume.overridden = true;
  return true;
}

}  // namespace vct::gltf
