#include "pt/integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "pt/bsdf_sampling.h"
#include "pt/camera_ray.h"
#include "scene/alpha_mask.h"
#include "pt/ray_cone.h"
#include "scene/surface.h"
#include "shared/vct_shared.h"

namespace vct::pt {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
// Directions within rounding of a surface's plane carry no light; cutting them avoids 1/cos
// blow-ups from float noise (and a triangle never lights itself).
constexpr float kMinCos = 1e-5f;

float scene_scale(const Scene& s) {
  float m = 1.0f;
  for (const vec3& p : s.positions) m = std::max({m, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return m;
}

float power_heuristic(float a, float b) {
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

float max_component(const vec3& v) { return std::max({v.x, v.y, v.z}); }

bool finite(const PathSample& s) {
  for (const vec3& v : s.aov)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  return true;
}

/// Shading frame at a hit, as the G-buffer orients it: ng turned toward the viewer and the shading
/// normal negated with it on back faces (GL: gl_FrontFacing ? n : -n). A shading normal that
/// still faces away from the viewer (bent normals at silhouettes) makes cook_torrance 0 there, as
/// in the pipelines. Light arriving below ng's plane is rejected in eval_bsdf (no leaks).
void orient_normals(const SurfacePoint& sp, const SurfaceMaterial& m, const vec3& wo, vec3& ng, vec3& ns) {
  const bool back = glm::dot(sp.geometric_normal, wo) < 0.0f;
  ng = back ? -sp.geometric_normal : sp.geometric_normal;
  ns = back ? -m.shading_normal : m.shading_normal;
}

// ---- Which AOVs a contribution feeds: decided by where its light source sits (see
// docs/pathtracer.md). Every contribution also goes into pt_full.

/// Light that emission at vertex `depth` >= 2 sends back along the path (c = Le * MIS weight).
void credit_emission(PathSample& out, const Integrator::Throughput& tp, int depth, const vec3& c) {
  out.aov[kFull] += tp.beta * c;
  if (depth == 2) {
    out.aov[kIndirectDiffuse] += tp.lobe_d * c;
    out.aov[kIndirectSpecular] += tp.lobe_s * c;
  }
}

/// A punctual light's contribution f * E * cos at vertex `depth`: at the first hit it is VCT's
/// "direct"; lighting the second vertex it is one bounce of light.
void credit_punctual(PathSample& out, const Integrator::Throughput& tp, int depth, const vec3& c) {
  if (depth == 1) {
    out.aov[kDirect] += c;
    out.aov[kFull] += c;
  } else {
    credit_emission(out, tp, depth, c);
  }
}

/// An emitter's or particle's light f * k at vertex `depth`: lighting the first hit it is one
/// bounce (the VCT cones see emitters and particles in the voxels), split by f's lobes.
void credit_nee(PathSample& out, const Integrator::Throughput& tp, int depth, const BsdfValue& f, const vec3& k) {
  out.aov[kFull] += tp.beta * f.total() * k;
  if (depth == 1) {
    out.aov[kIndirectDiffuse] += f.diffuse * k;
    out.aov[kIndirectSpecular] += f.specular * k;
  }
}

}  // namespace

Integrator::Integrator(const Scene& scene, const EmbreeScene& rt, const EmissiveTriangles& lights,
                       const PtSettings& s, const ParticleLights* particles, const Image* particle_layer)
    : scene_(scene),
      rt_(rt),
      lights_(lights),
      particles_(particles && !particles->empty() ? particles : nullptr),
      particle_layer_(particle_layer && !particle_layer->empty() ? particle_layer : nullptr),
      settings_(s),
      light_model_(s.light_model == LightModel::Seed ? sh::LIGHT_MODEL_SEED : sh::LIGHT_MODEL_GLTF),
      eps_(1e-4f * scene_scale(scene)),
      // Every vertex lies within scene_scale of the origin on each axis: 4x clears the cube's
      // diagonal (2 sqrt(3) scene_scale) from any point inside it.
      sun_ray_length_(4.0f * scene_scale(scene)) {
  for (const Light& light : scene.lights)
    spot_cos_.push_back(vec2(std::cos(light.inner_cone_angle), std::cos(light.outer_cone_angle)));
}

void Integrator::nee_punctual(const Vertex& v, const Throughput& tp, PathSample& out, RayCounts& counts) const {
  for (size_t i = 0; i < scene_.lights.size(); ++i) {
    const Light& light = scene_.lights[i];
    vec3 l, shadow_ray;
    float dist = std::numeric_limits<float>::infinity();
    if (light.is_directional()) {
      // A delta in direction: one shadow ray against the sun's direction, long enough to leave
      // the scene (sun_ray_length_).
      l = -glm::normalize(light.direction);
      shadow_ray = l * sun_ray_length_;
    } else {
      // A delta in position (spot, point): the ray ends at the light.
      const vec3 to_light = light.position - v.pos;
      dist = glm::length(to_light);
      if (!(dist > 0.0f)) continue;
      l = to_light / dist;
      shadow_ray = light.position - v.p;
    }
    const BsdfValue f = eval_bsdf(v.bp, l);
    if (f.total() == vec3(0.0f)) continue;
    const vec3 e = sh::punctual_irradiance(light_model_, int(light.kind), light.color, light.intensity, dist,
                                           glm::dot(light.direction, -l), spot_cos_[i].x, spot_cos_[i].y, light.range);
    if (e == vec3(0.0f)) continue;
    ++counts.shadow;
    if (rt_.occluded(v.p, shadow_ray, leave_tnear(shadow_ray), 1.0f)) continue;
    credit_punctual(out, tp, v.depth, f.total() * e * glm::dot(v.bp.n, l));
  }
}

Integrator::NeeRay Integrator::emitter_ray(const Vertex& v, PathSampler& rng) const {
  NeeRay r;
  const PathSampler::EmitterDraw d = rng.emitter(v.depth);
  const EmissiveTriangles::Sample ls = d.reuse_x ? lights_.sample_reusing(d.x, d.u.y) : lights_.sample(d.u_select, d.u);
  if (ls.triangle == v.triangle) return r;  // a flat triangle never lights itself
  const EmissiveTriangles::Geometry& g = lights_.geometry(ls);
  // A cut-away point of an alpha-masked emitter emits nothing (no ray can hit it either).
  if (g.alpha_tested && surface_masked(scene_, ls.triangle, ls.b1, ls.b2)) return r;
  // An untextured emitter's radiance is its material's constant: only the point's position and
  // geometric normal are needed, from the emitter's own record (docs/performance.md).
  SurfacePoint lp;
  if (g.textured) lp = interpolate_surface(scene_, ls.triangle, ls.b1, ls.b2);
  const vec3 light_pos = g.textured ? lp.position : g.position(ls.b1, ls.b2);
  const vec3 light_n = g.textured ? lp.geometric_normal : g.normal;
  const vec3 to_light = light_pos - v.pos;
  const float dist2 = glm::dot(to_light, to_light);
  const float dist = std::sqrt(dist2);
  if (!(dist > 0.0f)) return r;
  const vec3 l = to_light / dist;
  const float cos_l = std::abs(glm::dot(light_n, l));
  if (glm::dot(v.bp.ng, l) <= kMinCos || cos_l <= kMinCos) return r;
  // emitted_radiance toward -l: one-sided emitters emit from the front face only.
  if (!g.double_sided && glm::dot(light_n, -l) <= 0.0f) return r;
  r.f = eval_bsdf(v.bp, l, r.bsdf_pdf);
  if (r.f.total() == vec3(0.0f)) return r;
  const vec3 le = g.textured ? emitted_radiance(scene_, lp, evaluate_material(scene_, lp), -l) : g.emission;
  if (le == vec3(0.0f)) return r;
  r.l = l;
  r.le = le;
  r.pdf_light = ls.pdf_area * dist2 / cos_l;
  r.ray.org = v.p;
  r.ray.dir = light_pos - v.p;
  r.ray.tnear = leave_tnear(r.ray.dir);
  r.ray.tfar = 1.0f - eps_ / dist;
  r.ray.active = true;
  return r;
}

void Integrator::nee_emitters(const Vertex& v, const Throughput& tp, PathSampler& rng, PathSample& out,
                              RayCounts& counts) const {
  const NeeRay r = emitter_ray(v, rng);
  if (!r.ray.active) return;
  ++counts.shadow;
  if (rt_.occluded(r.ray.org, r.ray.dir, r.ray.tnear, r.ray.tfar)) return;
  credit_emitter(v, tp, r, out);
}

void Integrator::credit_emitter(const Vertex& v, const Throughput& tp, const NeeRay& r, PathSample& out) const {
  const float w = power_heuristic(r.pdf_light, r.bsdf_pdf);
  credit_nee(out, tp, v.depth, r.f, r.le * (glm::dot(v.bp.n, r.l) * w / r.pdf_light));
}

void Integrator::nee_particles(const Vertex& v, const Throughput& tp, PathSampler& rng, PathSample& out,
                               RayCounts& counts) const {
  const ParticleLights::Sample ps = particles_->sample(rng.particle(v.depth));
  const vec3 to_light = ps.position - v.pos;
  const float dist2 = glm::dot(to_light, to_light);
  if (!(dist2 > 0.0f) || !(ps.pmf > 0.0f)) return;
  const vec3 l = to_light / std::sqrt(dist2);
  const BsdfValue f = eval_bsdf(v.bp, l);
  if (f.total() == vec3(0.0f)) return;
  ++counts.shadow;
  if (rt_.occluded(v.p, ps.position - v.p, leave_tnear(ps.position - v.p), 1.0f)) return;
  credit_nee(out, tp, v.depth, f, ps.intensity * (glm::dot(v.bp.n, l) / (dist2 * ps.pmf)));
}

PathSample Integrator::trace(int x, int y, uint32_t sample, RayCounts& counts) const {
  return trace(first_vertex(x, y, counts), x, y, sample, counts);
}

Integrator::FirstVertex Integrator::first_vertex(int x, int y, RayCounts& counts) const {
  FirstVertex first;
  const Ray cam = camera_ray(scene_.camera, settings_.width, settings_.height, float(x) + 0.5f, float(y) + 0.5f);
  ++counts.primary;
  const Hit hit = rt_.intersect(cam.org, cam.dir, cam.tnear, cam.tfar);
  if (particle_layer_) {
    first.out.aov[kParticles] = particle_layer_->rgb(x, y);
    first.out.aov[kFull] += first.out.aov[kParticles];
  }
  if (hit.hit) first.continues = shade(hit, cam.dir, 1, Throughput{}, 0.0f, first.out, counts, first.vertex);
  return first;
}

bool Integrator::shade(const Hit& hit, const vec3& dir, int depth, const Throughput& tp, float prev_pdf,
                       PathSample& out, RayCounts& counts, Vertex& v) const {
  const SurfacePoint sp = interpolate_surface(scene_, hit.triangle, hit.b1, hit.b2);
  // The primary hit looks textures up at the pixel's ray-cone footprint (pt/ray_cone.h), as the
  // G-buffer does at its LOD; later vertices integrate the texture by Monte Carlo at level 0.
  const SlotLods lods = depth == 1
                            ? ray_cone_lods(scene_, hit.triangle, hit.t, dir,
                                            pixel_spread_angle(scene_.camera, settings_.height))
                            : SlotLods{};
  const SurfaceMaterial mat = evaluate_material(scene_, sp, lods);
  const vec3 wo = -dir;

  // Emission seen from the previous vertex (or the camera); MIS against step 3's sampling.
  const vec3 le = emitted_radiance(scene_, sp, mat, wo);
  if (le != vec3(0.0f)) {
    if (depth == 1) {
      out.aov[kEmission] += le;
      out.aov[kFull] += le;
    } else {
      const float cos_l = std::abs(glm::dot(sp.geometric_normal, wo));
      const float pdf_light = lights_.pdf_area(hit.triangle) * hit.t * hit.t / std::max(cos_l, 1e-8f);
      credit_emission(out, tp, depth, le * power_heuristic(prev_pdf, pdf_light));
    }
  }
  if (depth > settings_.max_depth) return false;

  vec3 ng, ns;
  orient_normals(sp, mat, wo, ng, ns);
  const sh::SurfacePbr pbr =
      sh::surface_pbr(mat.albedo, mat.metallic, mat.roughness, mat.specular_factor, mat.specular_color);
  // Light geometry is evaluated at the true surface point; only rays start from the point
  // lifted off the surface (along ng, the side every accepted direction leaves on).
  v = Vertex{make_bsdf_point(pbr, ns, ng, wo), sp.position, sp.position + ng * eps_, hit.triangle, depth};
  nee_punctual(v, tp, out, counts);
  return true;
}

bool Integrator::scatter(const Vertex& v, Throughput& tp, PathSampler& rng, BsdfSample& bs) const {
  // Continue by BSDF sampling (also when depth == max_depth: the next vertex's emission
  // completes paths of max_depth bounces, the MIS partner of the emitter NEE).
  float u_lobe;
  vec2 u_dir;
  rng.bsdf(v.depth, v.bp.specular_probability > 0.0f && v.bp.specular_probability < 1.0f, u_lobe, u_dir);
  bs = sample_bsdf(v.bp, u_lobe, u_dir);
  if (!bs.valid) return false;
  const BsdfValue& f = bs.f;
  if (f.total() == vec3(0.0f)) return false;
  const float k = glm::dot(v.bp.n, bs.l) / bs.pdf;
  if (v.depth == 1) {
    tp.lobe_d = f.diffuse * k;
    tp.lobe_s = f.specular * k;
    tp.beta = tp.lobe_d + tp.lobe_s;
  } else {
    tp.beta *= f.total() * k;
  }
  if (v.depth >= settings_.rr_start_depth) {  // Russian roulette
    const float q = std::min(1.0f, max_component(tp.beta));
    if (rng.roulette() >= q) return false;
    tp.beta /= q;
    tp.lobe_d /= q;
    tp.lobe_s /= q;
  }
  return true;
}

void Integrator::continue_path(Vertex& v, Throughput& tp, PathSampler& rng, PathSample& out, RayCounts& counts) const {
  for (bool shaded = true; shaded;) {
    if (!lights_.empty()) nee_emitters(v, tp, rng, out, counts);
    if (particles_) nee_particles(v, tp, rng, out, counts);
    BsdfSample bs;
    if (!scatter(v, tp, rng, bs)) break;
    ++counts.secondary;
    const Hit hit = rt_.intersect(v.p, bs.l, leave_tnear(bs.l), kInf);
    shaded = hit.hit && shade(hit, bs.l, v.depth + 1, tp, bs.pdf, out, counts, v);
  }
}

void Integrator::drop_nonfinite(PathSample& out, RayCounts& counts) {
  if (finite(out)) return;
  ++counts.nonfinite_samples;
  out = PathSample{};
}

PathSample Integrator::trace(const FirstVertex& first, int x, int y, uint32_t sample, RayCounts& counts) const {
  PathSample out = first.out;
  PathSampler rng(settings_.sampler, uint64_t(y) * uint64_t(settings_.width) + uint64_t(x), sample, settings_.seed);
  Throughput tp;
  if (first.continues) {
    Vertex v = first.vertex;
    continue_path(v, tp, rng, out, counts);
  }
  drop_nonfinite(out, counts);
  return out;
}

void Integrator::trace_packet(const Lane* lanes, int n, PathSample* out, RayCounts& counts) const {
  if (n == 1) {  // one sample: single rays (a packet of one would cost more, the floats are the same)
    out[0] = trace(*lanes[0].first, lanes[0].x, lanes[0].y, lanes[0].sample, counts);
    return;
  }
  // Each lane runs trace()'s steps in trace()'s order — its own sampler, throughput and sums —
  // only its first vertex's two rays wait for the packet: every lane's floats are trace()'s.
  constexpr int kMax = EmbreeScene::kPacket;
  std::optional<PathSampler> rng[kMax];
  Throughput tp[kMax];
  EmbreeScene::RayQuery rays[kMax];
  BsdfSample bs[kMax];
  bool go[kMax];  // the path goes on from the lane's first vertex
  for (int i = 0; i < n; ++i) {
    const Lane& a = lanes[i];
    out[i] = a.first->out;
    go[i] = a.first->continues;
    if (go[i])
      rng[i].emplace(settings_.sampler, uint64_t(a.y) * uint64_t(settings_.width) + uint64_t(a.x), a.sample,
                     settings_.seed);
  }
  if (!lights_.empty()) {  // emitter NEE: shadow rays from the first vertices toward the lights
    NeeRay nee[kMax];
    for (int i = 0; i < n; ++i) {
      nee[i] = go[i] ? emitter_ray(lanes[i].first->vertex, *rng[i]) : NeeRay{};
      rays[i] = nee[i].ray;
      counts.shadow += nee[i].ray.active ? 1 : 0;
    }
    bool blocked[kMax];
    rt_.occluded_packet(rays, n, blocked);
    for (int i = 0; i < n; ++i)
      if (nee[i].ray.active && !blocked[i]) credit_emitter(lanes[i].first->vertex, tp[i], nee[i], out[i]);
  }
  for (int i = 0; i < n; ++i) {
    rays[i] = EmbreeScene::RayQuery{};
    if (!go[i]) continue;
    const Vertex& v = lanes[i].first->vertex;
    if (particles_) nee_particles(v, tp[i], *rng[i], out[i], counts);
    if (!scatter(v, tp[i], *rng[i], bs[i])) continue;
    ++counts.secondary;
    rays[i] = EmbreeScene::RayQuery{v.p, bs[i].l, leave_tnear(bs[i].l), kInf, true};
  }
  Hit hits[kMax];
  rt_.intersect_packet(rays, n, hits);
  Vertex next;
  for (int i = 0; i < n; ++i) {
    const int depth = lanes[i].first->vertex.depth + 1;
    if (rays[i].active && hits[i].hit && shade(hits[i], bs[i].l, depth, tp[i], bs[i].pdf, out[i], counts, next))
      continue_path(next, tp[i], *rng[i], out[i], counts);
    drop_nonfinite(out[i], counts);
  }
}

}  // namespace vct::pt
