#include "stages/explain.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "shared/vct_shared.h"
#include "stages/cone_sets.h"
#include "stages/indirect_pass.h"
#include "stages/light_sample.h"
#include "stages/shadow_map.h"

namespace vct {

namespace {

using nlohmann::json;

json vec_json(const vec3& v) { return json::array({v.x, v.y, v.z}); }
json vec_json(const vec4& v) { return json::array({v.x, v.y, v.z, v.w}); }

struct TracedCone {
  std::string kind;  // "diffuse", "specular", "shadow"
  int index = 0;
  Cone cone;
  float weight = 1.0f;
  vec4 result{0.0f};
  std::vector<ConeSample> samples;
};

json cone_json(const TracedCone& c) {
  json j;
  j["kind"] = c.kind;
  j["index"] = c.index;
  j["origin_texture"] = vec_json(c.cone.origin);
  j["direction"] = vec_json(c.cone.direction);
  j["aperture_deg"] = c.cone.aperture * 180.0f / kPi;
  j["weight"] = c.weight;
  j["result_rgba"] = vec_json(c.result);
  json samples = json::array();
  for (const ConeSample& s : c.samples) {
    samples.push_back({{"position", vec_json(s.position)}, {"distance", s.distance}, {"diameter", s.diameter},
                       {"lod", s.lod}, {"sampled", vec_json(s.sampled)}, {"accumulated", vec_json(s.accumulated)}});
  }
  j["samples"] = std::move(samples);
  return j;
}

std::vector<TracedCone> trace_all(const Scene& scene, const FrameResult& f, const VctSettings& s, int x, int y) {
  const GBuffer& g = f.gbuffer;
  const vec3 p = g.position.rgb(x, y), n = g.normal.rgb(x, y);
  std::vector<TracedCone> cones;
  std::vector<std::vector<ConeSample>> records;
  const DiffuseConeSet set =
      trace_diffuse_cones(f.mips, scene.volume, s, p, n, diffuse_rotation_for_pixel(s, x, y), 0.0f, &records);
  for (int i = 0; i < set.count; ++i) {
    cones.push_back({"diffuse", i, set.geometry[size_t(i)], set.weights[size_t(i)], set.cones[size_t(i)],
                     std::move(records[size_t(i)])});
  }
  const MarchParams spec_params = MarchParams::specular_from_settings(s, f.mips.iso.empty() ? 1 : f.mips.iso[0].nx);
  const vec3 spec_v = view_vector(scene, specular_view_point(scene.volume, s.specular_view, spec_params.normal_offset, p, n));
  TracedCone spec{"specular", 0,
                  specular_cone(scene.volume, p, n, spec_v, g.material.at(x, y, 1), spec_params.normal_offset,
                                s.specular_aperture),
                  1.0f, vec4(0.0f), {}};
  spec.result = trace_specular_cone(f.mips, scene.volume, s, p, n, spec_v, g.material.at(x, y, 1), &spec.samples);
  cones.push_back(std::move(spec));
  for (size_t li = 0; li < scene.lights.size(); ++li) {
    TracedCone sc{"shadow", int(li), Cone{}, 1.0f, vec4(0.0f), {}};
    const ConeFrame frame(f.mips, scene.volume, s, 0.0f, false);
    const float vis = frame.shadow(p, scene.lights[li], &sc.samples);
    float max_distance = 0.0f;
    sc.cone = frame.shadow_cone(p, scene.lights[li], &max_distance);
    sc.result = vec4(vec3(0.0f), 1.0f - vis);
    cones.push_back(std::move(sc));
  }
  return cones;
}

// Each light as this pixel sees it: kind, direction, irradiance, n.l and the shadow map's PCF
// visibility (the shadow cone's is among the cones), so a dark pixel says which light and why.
json lights_json(const Scene& scene, const FrameResult& f, const VctSettings& s, const vec3& p, const vec3& n) {
  json arr = json::array();
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const LightSample ls = sample_light(light, s.light_model, p);
    const float pcf = i < f.shadow_maps.size() ? surface_visibility(f.shadow_maps[i], light, p, n, s) : 1.0f;
    arr.push_back({{"light", i},
                   {"name", light.name},
                   {"kind", light_kind_name(light.kind)},
                   {"to_light", vec_json(ls.l)},
                   {"distance", light.is_directional() ? json(nullptr) : json(ls.distance)},
                   {"irradiance", vec_json(ls.irradiance)},
                   {"n_dot_l", glm::dot(n, ls.l)},
                   {"shadow_map_visibility", pcf}});
  }
  return arr;
}

// --- The picture: one z/y/x slice of the base level through the surface point. ---

vec3 cone_colour(const TracedCone& c) {
  if (c.kind == "specular") return vec3(1.0f, 0.2f, 1.0f);
  if (c.kind == "shadow") return vec3(1.0f, 1.0f, 0.2f);
  // Normal cone green, then one colour per tilted cone in azimuth order; the first four are the
  // seed set's (blue, cyan, orange, red), so its pictures are unchanged.
  static const vec3 diffuse[kMaxDiffuseCones] = {
      vec3(0.2f, 1.0f, 0.2f), vec3(0.2f, 0.6f, 1.0f), vec3(0.2f, 1.0f, 1.0f), vec3(1.0f, 0.5f, 0.1f),
      vec3(1.0f, 0.2f, 0.2f), vec3(0.7f, 0.4f, 1.0f), vec3(1.0f, 0.9f, 0.6f), vec3(0.6f, 0.9f, 0.3f),
      vec3(1.0f, 0.6f, 0.8f), vec3(0.4f, 0.8f, 0.7f), vec3(0.9f, 0.7f, 0.3f), vec3(0.5f, 0.5f, 1.0f),
      vec3(0.8f, 0.3f, 0.5f), vec3(0.6f, 1.0f, 0.8f), vec3(1.0f, 0.4f, 0.0f), vec3(0.7f, 0.7f, 0.7f)};
  return diffuse[size_t(c.index) % size_t(kMaxDiffuseCones)];
}

struct SliceView {
  int axis = 2;      // slice normal axis
  int u = 0, v = 1;  // picture axes (v up)
  int n = 0;
  int scale = 1;     // pixels per voxel
  vec2 to_pixel(const vec3& tex) const {
    return vec2(tex[u] * float(n * scale), (1.0f - tex[v]) * float(n * scale));
  }
};

void put(Image& img, int px, int py, const vec3& c) {
  if (px >= 0 && py >= 0 && px < img.width && py < img.height) img.set_rgb(px, py, c);
}

void draw_circle(Image& img, const vec2& centre, float radius, const vec3& c) {
  const int steps = std::max(12, int(radius * 6.0f));
  for (int k = 0; k < steps; ++k) {
    const float a = 2.0f * kPi * float(k) / float(steps);
    put(img, int(std::floor(centre.x + radius * std::cos(a))), int(std::floor(centre.y + radius * std::sin(a))), c);
  }
}

void draw_line(Image& img, const vec2& a, const vec2& b, const vec3& c) {
  const int steps = std::max(1, int(glm::length(b - a)));
  for (int k = 0; k <= steps; ++k) {
    const vec2 p = glm::mix(a, b, float(k) / float(steps));
    put(img, int(std::floor(p.x)), int(std::floor(p.y)), c);
  }
}

Image draw_picture(const Volume& base, const vec3& origin_tex, const vec3& normal,
                   const std::vector<TracedCone>& cones) {
  SliceView view;
  view.n = base.nx;
  view.scale = std::max(1, 512 / std::max(view.n, 1));
  // Slice across the normal's weakest axis, so the normal (and the cones around it) lie in the
  // picture as much as possible.
  const vec3 an = glm::abs(normal);
  view.axis = an.x <= an.y && an.x <= an.z ? 0 : (an.y <= an.z ? 1 : 2);
  view.u = view.axis == 0 ? 2 : 0;
  view.v = view.axis == 1 ? 2 : 1;
  const int slice = std::clamp(int(std::floor(origin_tex[view.axis] * float(view.n))), 0, view.n - 1);
  const int size = view.n * view.scale;
  Image img(size, size, 3);
  for (int py = 0; py < size; ++py) {
    for (int px = 0; px < size; ++px) {
      ivec3 vox(0);
      vox[view.axis] = slice;
      vox[view.u] = px / view.scale;
      vox[view.v] = view.n - 1 - py / view.scale;
      const vec4 c = base.rgba(vox.x, vox.y, vox.z);
      // Radiance tone-mapped x/(1+x); empty voxels dark blue-grey so the geometry reads.
      const vec3 lit = vec3(c) / (vec3(1.0f) + vec3(c));
      img.set_rgb(px, py, c.a > 0.0f ? glm::max(lit, vec3(0.12f)) : vec3(0.03f, 0.03f, 0.06f));
    }
  }
  for (const TracedCone& cone : cones) {
    const vec3 colour = cone_colour(cone);
    // Samples after the cone is (almost) opaque change nothing visible: draw up to a >= 0.99 so
    // the picture shows where the cone effectively stopped (the JSON keeps every sample).
    float reach = 0.0f;
    for (const ConeSample& s : cone.samples) {
      draw_circle(img, view.to_pixel(s.position), 0.5f * s.diameter * float(size), colour * 0.6f);
      reach = s.distance;
      if (s.accumulated.a >= 0.99f) break;
    }
    draw_line(img, view.to_pixel(cone.cone.origin), view.to_pixel(cone.cone.origin + cone.cone.direction * reach),
              colour);
  }
  const vec2 o = view.to_pixel(origin_tex);
  draw_circle(img, o, 3.0f, vec3(1.0f));
  return img;
}

}  // namespace

PixelExplanation explain_pixel(const Scene& scene, const FrameResult& f, const VctSettings& s, int x, int y) {
  const GBuffer& g = f.gbuffer;
  if (x < 0 || y < 0 || x >= g.coverage.width || y >= g.coverage.height) {
    throw InputError("--explain", "pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                                      std::to_string(g.coverage.width) + "x" + std::to_string(g.coverage.height) +
                                      " image");
  }
  PixelExplanation out;
  json& j = out.json;
  j["pixel"] = {x, y};
  j["convention"] = "pixel row 0 = top; positions in voxel-texture space [0,1]^3; rgb premultiplied by opacity";
  j["grid"] = f.mips.iso.empty() ? 0 : f.mips.iso[0].nx;
  j["anisotropic"] = f.mips.anisotropic();
  if (g.coverage.at(x, y, 0) <= 0.0f) {
    j["covered"] = false;
    out.picture = Image(1, 1, 3);
    return out;
  }
  j["covered"] = true;
  const vec3 p = g.position.rgb(x, y), n = g.normal.rgb(x, y);
  j["position_world"] = vec_json(p);
  j["position_texture"] = vec_json(scene.volume.to_texture(p));
  j["normal"] = vec_json(n);
  j["view"] = vec_json(view_vector(scene, p));
  j["material"] = {{"albedo", vec_json(g.albedo.rgb(x, y))}, {"metallic", g.material.at(x, y, 0)},
                   {"roughness", g.material.at(x, y, 1)}, {"specular_factor", g.material.at(x, y, 2)}};
  json comps;
  const FrameImages& im = f.images;
  const std::pair<const char*, const Image*> images[] = {
      {"direct", &im.direct}, {"indirect_diffuse", &im.indirect_diffuse}, {"indirect_specular", &im.indirect_specular},
      {"diffuse_term", &im.diffuse_term}, {"specular_term", &im.specular_term}, {"emission", &im.emission},
      {"particles", &im.particles}, {"final", &im.final_image}};
  for (const auto& [name, img] : images) {
    if (!img->empty()) comps[name] = vec_json(img->rgb(x, y));
  }
  j["components"] = comps;
  j["lights"] = lights_json(scene, f, s, p, n);
  const std::vector<TracedCone> cones = trace_all(scene, f, s, x, y);
  json arr = json::array();
  for (const TracedCone& c : cones) arr.push_back(cone_json(c));
  j["cones"] = std::move(arr);
  out.picture = draw_picture(f.mips.iso[0], scene.volume.to_texture(p), n, cones);
  return out;
}

}  // namespace vct
