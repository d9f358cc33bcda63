// vct info [SCENE] [--json]: everything the loader made of a glTF file (no SCENE = the built-in
// Cornell box): geometry counts, what was dropped or skipped and why, bounds and the voxel
// volume, materials, textures, camera, lights and particle emitters.
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "core/error.h"
#include "core/settings.h"
#include "options.h"
#include "scene/exposure.h"
#include "scene/gltf_loader.h"
#include "stages/backend_facts.h"

#ifdef VCT_HAVE_GL
#include "gl/gl_device_list.h"
#define VCT_INFO_GL 1
#endif

namespace vct::app {
namespace {

using nlohmann::json;

json vec_json(const vec2& v) { return json::array({v.x, v.y}); }
json vec_json(const vec3& v) { return json::array({v.x, v.y, v.z}); }
json vec_json(const vec4& v) { return json::array({v.x, v.y, v.z, v.w}); }

json texture_ref_json(const TextureRef& r) {
  if (!r.present()) return nullptr;
  json j = {{"texture", r.texture}, {"texcoord", r.texcoord}};
  if (!r.transform.is_identity()) {
    j["transform"] = {{"offset", vec_json(r.transform.offset)},
                      {"rotation", r.transform.rotation},
                      {"scale", vec_json(r.transform.scale)}};
  }
  return j;
}

const char* wrap_name(Wrap w) {
  return w == Wrap::Repeat ? "repeat" : (w == Wrap::ClampToEdge ? "clamp_to_edge" : "mirrored_repeat");
}

// glTF / GL spelling of a min filter, lower case.
const char* min_filter_name(MinFilter f) {
  switch (f) {
    case MinFilter::Nearest:
      return "nearest";
    case MinFilter::Linear:
      return "linear";
    case MinFilter::NearestMipmapNearest:
      return "nearest_mipmap_nearest";
    case MinFilter::LinearMipmapNearest:
      return "linear_mipmap_nearest";
    case MinFilter::NearestMipmapLinear:
      return "nearest_mipmap_linear";
    case MinFilter::LinearMipmapLinear:
    default:
      return "linear_mipmap_linear";
  }
}

// The one description of a scene; the text output prints the same facts.
json summary(const Scene& s) {
  const int grid = VctSettings{}.grid;
  json j;
  j["source"] = s.source;
  j["triangles"] = s.triangle_count();
  j["vertices"] = s.positions.size();
  j["has_uv1"] = !s.uv1.empty();
  j["degenerate_triangles_dropped"] = s.stats.degenerate_triangles_dropped;
  j["non_triangle_primitives_skipped"] = s.stats.non_triangle_primitives_skipped;
  j["warnings"] = s.stats.warnings;
  j["bounds"] = {{"min", vec_json(s.bounds.lo)}, {"max", vec_json(s.bounds.hi)}, {"extent", vec_json(s.bounds.extent())}};
  j["volume"] = {{"origin", vec_json(s.volume.origin)},
                 {"size", s.volume.size},
                 {"overridden", s.volume.overridden},
                 {"default_grid", grid},
                 {"voxel_size_at_default_grid", s.volume.size / float(grid)}};
  for (const Material& m : s.materials) {
    j["materials"].push_back({{"name", m.name},
                              {"base_color_factor", vec_json(m.base_color_factor)},
                              {"base_color_texture", texture_ref_json(m.base_color_texture)},
                              {"metallic", m.metallic_factor},
                              {"roughness", m.roughness_factor},
                              {"metallic_roughness_texture", texture_ref_json(m.metallic_roughness_texture)},
                              {"normal_texture", texture_ref_json(m.normal_texture)},
                              {"normal_scale", m.normal_scale},
                              {"normal_two_channel", m.normal_two_channel},
                              {"emissive_factor", vec_json(m.emissive_factor)},
                              {"emissive_strength", m.emissive_strength},
                              {"emissive_texture", texture_ref_json(m.emissive_texture)},
                              {"specular_factor", m.specular_factor},
                              {"specular_color_factor", vec_json(m.specular_color_factor)},
                              {"double_sided", m.double_sided}});
  }
  j["textures"] = json::array();
  for (const Texture& t : s.textures) {
    j["textures"].push_back({{"name", t.name},
                             {"width", t.width},
                             {"height", t.height},
                             {"wrap_s", wrap_name(t.wrap_s)},
                             {"wrap_t", wrap_name(t.wrap_t)},
                             {"mag_filter", t.mag_filter == Filter::Nearest ? "nearest" : "linear"},
                             {"min_filter", min_filter_name(t.min_filter)}});
  }
  const Camera& c = s.camera;
  j["camera"] = {{"from_file", c.from_file}, {"position", vec_json(c.position)}, {"forward", vec_json(c.forward)},
                 {"up", vec_json(c.up)},     {"znear", c.znear},                {"zfar", c.zfar},
                 {"type", c.orthographic ? "orthographic" : "perspective"}};
  if (c.orthographic) j["camera"]["ymag"] = c.ymag;
  else j["camera"]["yfov"] = c.yfov;
  if (c.aspect_ratio > 0.0f) j["camera"]["aspect_ratio"] = c.aspect_ratio;
  j["exposure_auto"] = exposure_json(resolve_exposure(s, ExposureMode::Auto, 0.0f));
  j["lights"] = json::array();
  for (const Light& l : s.lights) {
    json lj = {{"name", l.name},
               {"kind", light_kind_name(l.kind)},
               {"position", vec_json(l.position)},
               {"direction", vec_json(l.direction)},
               {"color", vec_json(l.color)},
               {l.is_directional() ? "intensity_lux" : "intensity_cd", l.intensity}};
    if (l.is_spot()) {
      lj["inner_cone_angle"] = l.inner_cone_angle;
      lj["outer_cone_angle"] = l.outer_cone_angle;
    }
    if (!l.is_directional()) lj["range"] = l.range;
    j["lights"].push_back(lj);
  }
  j["particle_emitters"] = json::array();
  for (const ParticleEmitter& e : s.emitters) {
    j["particle_emitters"].push_back({{"name", e.name},
                                      {"origin", vec_json(e.origin)},
                                      {"count", e.count},
                                      {"lifetime", e.lifetime},
                                      {"spawn_extent", vec_json(e.spawn_extent)},
                                      {"velocity_min", vec_json(e.velocity_min)},
                                      {"velocity_max", vec_json(e.velocity_max)},
                                      {"acceleration", vec_json(e.acceleration)},
                                      {"color_start", vec_json(e.color_start)},
                                      {"color_end", vec_json(e.color_end)},
                                      {"size_start", e.size_start},
                                      {"size_end", e.size_end}});
  }
  return j;
}

std::string v3(const vec3& v) { return fmt::format("({:.4g}, {:.4g}, {:.4g})", v.x, v.y, v.z); }

std::string tex(const Scene& s, const TextureRef& r) {
  if (!r.present()) return "";
  std::string out = fmt::format(" [texture {} '{}', uv{}", r.texture, s.textures[size_t(r.texture)].name, r.texcoord);
  if (!r.transform.is_identity()) {
    out += fmt::format(", transform offset ({:.4g}, {:.4g}) rotation {:.4g} scale ({:.4g}, {:.4g})", r.transform.offset.x,
                       r.transform.offset.y, r.transform.rotation, r.transform.scale.x, r.transform.scale.y);
  }
  return out + "]";
}

float deg(float radians) { return radians * 180.0f / kPi; }

// One line per light: what each kind's glTF parameters mean (lux for a sun, candela otherwise).
std::string light_line(const Light& l) {
  const std::string range = l.range > 0.0f ? fmt::format(", range {:.4g}", l.range) : "";
  switch (l.kind) {
    case LightKind::Directional:
      return fmt::format("'{}' directional: direction {} colour {} intensity {:.4g} lux", l.name, v3(l.direction),
                         v3(l.color), l.intensity);
    case LightKind::Point:
      return fmt::format("'{}' point: position {} colour {} intensity {:.4g} cd{}", l.name, v3(l.position), v3(l.color),
                         l.intensity, range);
    case LightKind::Spot:
    default:
      return fmt::format("'{}' spot: position {} direction {} colour {} intensity {:.4g} cd, cone inner {:.4g} outer "
                         "{:.4g} deg{}",
                         l.name, v3(l.position), v3(l.direction), v3(l.color), l.intensity, deg(l.inner_cone_angle),
                         deg(l.outer_cone_angle), range);
  }
}

void print_text(const Scene& s) {
  const int grid = VctSettings{}.grid;
  fmt::print("scene: {}\n", s.source);
  fmt::print("triangles: {}\nvertices: {}{}\n", s.triangle_count(), s.positions.size(), s.uv1.empty() ? "" : " (with TEXCOORD_1)");
  fmt::print("degenerate triangles dropped: {}\nnon-triangle primitives skipped: {}\n",
             s.stats.degenerate_triangles_dropped, s.stats.non_triangle_primitives_skipped);
  fmt::print("warnings: {}\n", s.stats.warnings.size());
  for (const auto& w : s.stats.warnings) fmt::print("  - {}\n", w);
  fmt::print("bounds: min {} max {} extent {}\n", v3(s.bounds.lo), v3(s.bounds.hi), v3(s.bounds.extent()));
  fmt::print("voxel volume: origin {} size {:.4g}{}; voxel {:.4g} at the default grid {}^3\n", v3(s.volume.origin),
             s.volume.size, s.volume.overridden ? " (from the file's vct_volume)" : " (fit to bounds)",
             s.volume.size / float(grid), grid);
  fmt::print("materials: {}\n", s.materials.size());
  for (size_t i = 0; i < s.materials.size(); ++i) {
    const Material& m = s.materials[i];
    const vec4& b = m.base_color_factor;
    fmt::print("  {} '{}': base colour ({:.3g}, {:.3g}, {:.3g}, {:.3g}){}\n", i, m.name, b.x, b.y, b.z, b.w,
               tex(s, m.base_color_texture));
    fmt::print("      metallic {:.3g} roughness {:.3g}{}; specular {:.3g} colour {}{}{}\n", m.metallic_factor,
               m.roughness_factor, tex(s, m.metallic_roughness_texture), m.specular_factor, v3(m.specular_color_factor),
               m.specular_factor == 0.0f && m.metallic_factor == 0.0f ? " (Lambertian)" : "",
               m.double_sided ? "; double sided" : "");
    if (m.normal_texture.present()) {
      fmt::print("      normal map{} scale {:.3g}{}\n", tex(s, m.normal_texture), m.normal_scale,
                 m.normal_two_channel ? " (two-channel RG, z reconstructed)" : "");
    }
    if (m.is_emissive() || m.emissive_texture.present()) {
      fmt::print("      emission {} = factor {} x strength {:.4g}{}\n", v3(m.emission()), v3(m.emissive_factor),
                 m.emissive_strength, tex(s, m.emissive_texture));
    }
  }
  fmt::print("textures: {}\n", s.textures.size());
  for (size_t i = 0; i < s.textures.size(); ++i) {
    const Texture& t = s.textures[i];
    fmt::print("  {} '{}': {}x{} RGBA8, wrap {}/{}, mag {}, min {}\n", i, t.name, t.width, t.height,
               wrap_name(t.wrap_s), wrap_name(t.wrap_t),
               t.mag_filter == Filter::Nearest ? "nearest" : "linear",
               min_filter_name(t.min_filter));
  }
  const Camera& c = s.camera;
  const std::string lens = c.orthographic ? fmt::format("orthographic ymag {:.4g}", c.ymag)
                                         : fmt::format("yfov {:.4g} deg", deg(c.yfov)) +
                                               (c.aspect_ratio > 0.0f ? fmt::format(" aspect {:.4g}", c.aspect_ratio) : "");
  fmt::print("camera ({}): position {} forward {} up {} {} near {:.4g} far {:.4g}\n",
             c.from_file ? "from file" : "default framing", v3(c.position), v3(c.forward), v3(c.up), lens, c.znear,
             c.zfar);
  fmt::print("lights: {}\n", s.lights.size());
  for (const Light& l : s.lights) fmt::print("  {}\n", light_line(l));
  const ExposureApplied auto_exposure = resolve_exposure(s, ExposureMode::Auto, 0.0f);  // docs/scenes.md
  fmt::print("exposure (auto): meter at the scene's centre {:.4g} lux, {} (scale {:.6g})\n",
             auto_exposure.key_illuminance,
             auto_exposure.stops == 0 ? std::string("kept at 1") : fmt::format("{:+d} stops", auto_exposure.stops),
             auto_exposure.scale);
  fmt::print("particle emitters: {}\n", s.emitters.size());
  for (const ParticleEmitter& e : s.emitters) {
    fmt::print("  '{}': origin {} count {} lifetime {:.3g} s, spawn half-extent {}, velocity {}..{}, "
               "acceleration {}, colour {} -> {}, size {:.3g} -> {:.3g}\n",
               e.name, v3(e.origin), e.count, e.lifetime, v3(e.spawn_extent), v3(e.velocity_min), v3(e.velocity_max),
               v3(e.acceleration), v3(e.color_start), v3(e.color_end), e.size_start, e.size_end);
  }
}

}  // namespace

// `vct info --gl`: the machine's GL devices (gl/gl_device_list.h), as text or JSON.
int print_gl_devices(bool json) {
#ifdef VCT_INFO_GL
  const nlohmann::json list = gl::list_gl_devices();
  if (json) {
    std::printf("%s\n", list.dump(2).c_str());
  } else {
    for (const auto& d : list["devices"]) {
      fmt::print("--gl-device {:<12} {:<11} {}\n", d["spec"].get<std::string>(), d["kind"].get<std::string>(),
                 d["status"].get<std::string>());
      if (d.contains("egl")) fmt::print("    egl: {} {}\n", d["egl"]["extensions"].get<std::string>(), d["egl"]["render_node"].get<std::string>());
      if (!d.contains("facts")) continue;
      const BackendFacts f = d["facts"].get<BackendFacts>();
      fmt::print("    {} | {} | {}\n", f.vendor, f.renderer, f.version);
      std::string pos;
      for (const vec2& p : f.sample_positions) pos += fmt::format(" ({:.4g},{:.4g})", p.x, p.y);
      fmt::print("    max samples {}, GL_SUBPIXEL_BITS {}, sample positions at {}:{}\n", f.max_samples, f.subpixel_bits,
                 f.msaa_samples, pos);
      fmt::print("    conservative raster: {}\n", f.conservative_raster.empty() ? "none" : fmt::format("{}", fmt::join(f.conservative_raster, " ")));
      for (const std::string& u : f.unreported) fmt::print("    not reported: {}\n", u);
    }
    const std::string def = list["default"].get<std::string>();
    fmt::print("default (no --gl-device): {}\n", def.empty() ? "none: no GL 4.5 context on this machine" : def);
  }
  return kExitOk;
#else
  (void)json;
  throw EnvironmentError("GL backend not built");
#endif
}

void register_info(CLI::App& app, int& exit_code) {
  struct Args {
    std::string scene;
    bool json = false;
    SceneLoadOptions scene_load;
    bool gl = false;
  };
  static Args storage;  // lives as long as the process (CLI11 binds by reference); static, not
  auto* args = &storage;  // new, so LeakSanitizer sees no leak
  CLI::App* cmd = app.add_subcommand("info", "Print a summary of a glTF scene (no SCENE = built-in default)");
  cmd->add_option("scene", args->scene, "glTF 2.0 file (.gltf or .glb)");
  cmd->add_flag("--json", args->json, "Print the summary as JSON");
  add_scene_access_flag(cmd, args->scene_load);
  cmd->add_flag("--gl", args->gl, "List the GL devices (EGL devices, Mesa surfaceless) and what each offers, not a scene");
  cmd->callback([args, &exit_code]() {
    if (args->gl) {
      exit_code = print_gl_devices(args->json);
      return;
    }
    const Scene scene = load_scene(args->scene, args->scene_load);
    if (args->json) {
      std::printf("%s\n", summary(scene).dump(2).c_str());
    } else {
      print_text(scene);
    }
    exit_code = kExitOk;
  });
}

}  // namespace vct::app
