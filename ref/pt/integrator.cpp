#include "pt/integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pt/bsdf_sampling.h"
#include "pt/camera_ray.h"
#include "pt/rng.h"
#include "scene/surface.h"
#include "shared/vct_shared.h"

namespace vct::pt {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

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
      eps_(1e-4f * scene_scale(scene)) {}

PathSample Integrator::trace(int x, int y, uint32_t sample, RayCounts& counts) const {
  PathSample out;
  Pcg32 rng = sample_rng(uint64_t(y) * uint64_t(settings_.width) + uint64_t(x), sample, settings_.seed);
  const Ray cam = camera_ray(scene_.camera, settings_.width, settings_.height, float(x) + 0.5f, float(y) + 0.5f);
  ++counts.primary;
  Hit hit = rt_.intersect(cam.org, cam.dir, cam.tnear, cam.tfar);
  vec3 dir = cam.dir;
  // beta: throughput from the camera to the current vertex. lobe_d / lobe_s: the parts of beta
  // that left the first vertex through its diffuse / specular lobe (used for the one-bounce AOVs).
  vec3 beta(1.0f), lobe_d(0.0f), lobe_s(0.0f);
  float prev_pdf = 0.0f;
  if (particle_layer_) {
    out.aov[kParticles] = particle_layer_->rgb(x, y);
    out.aov[kFull] += out.aov[kParticles];
  }

  for (int depth = 1; hit.hit; ++depth) {
    const SurfacePoint sp = interpolate_surface(scene_, hit.triangle, hit.b1, hit.b2);
    const SurfaceMaterial mat = evaluate_material(scene_, sp);
    const vec3 wo = -dir;

    // Emission seen from the previous vertex (or the camera).
    const vec3 le = emitted_radiance(scene_, sp, mat, wo);
    if (le != vec3(0.0f)) {
      if (depth == 1) {
        out.aov[kEmission] += le;
        out.aov[kFull] += le;
      } else {
        const float cos_l = std::abs(glm::dot(sp.geometric_normal, wo));
        const float pdf_light = lights_.pdf_area(hit.triangle) * hit.t * hit.t / std::max(cos_l, 1e-8f);
        const vec3 c = le * power_heuristic(prev_pdf, pdf_light);
        out.aov[kFull] += beta * c;
        if (depth == 2) {
          out.aov[kIndirectDiffuse] += lobe_d * c;
          out.aov[kIndirectSpecular] += lobe_s * c;
        }
      }
    }
    if (depth > settings_.max_depth) break;

    vec3 ng, ns;
    orient_normals(sp, mat, wo, ng, ns);
    const sh::SurfacePbr pbr =
        sh::surface_pbr(mat.albedo, mat.metallic, mat.roughness, mat.specular_factor, mat.specular_color);
    const BsdfPoint bp = make_bsdf_point(pbr, ns, ng, wo);
    // Light geometry is evaluated at the true surface point; only rays start from the point
    // lifted off the surface (along ng, the side every accepted direction leaves on).
    const vec3 pos = sp.position;
    const vec3 p = pos + ng * eps_;

    // Next-event estimation: spot lights (delta, exact visibility by a shadow ray).
    for (const SpotLight& light : scene_.spot_lights) {
      const vec3 to_light = light.position - pos;
      const float dist = glm::length(to_light);
      if (!(dist > 0.0f)) continue;
      const vec3 l = to_light / dist;
      const BsdfValue f = eval_bsdf(bp, l);
      if (f.total() == vec3(0.0f)) continue;
      const vec3 e = sh::spot_irradiance(light_model_, light.color, light.intensity, dist,
                                         glm::dot(light.direction, -l), std::cos(light.inner_cone_angle),
                                         std::cos(light.outer_cone_angle), light.range);
      if (e == vec3(0.0f)) continue;
      ++counts.shadow;
      if (rt_.occluded(p, light.position - p, 0.0f, 1.0f)) continue;
      const vec3 c = f.total() * e * glm::dot(ns, l);
      if (depth == 1) {
        out.aov[kDirect] += c;
        out.aov[kFull] += c;
      } else {
        out.aov[kFull] += beta * c;
        if (depth == 2) {
          out.aov[kIndirectDiffuse] += lobe_d * c;
          out.aov[kIndirectSpecular] += lobe_s * c;
        }
      }
    }

    // Next-event estimation: one point on the emissive triangles, MIS-weighted against BSDF
    // sampling (which finds the same emitters below).
    if (!lights_.empty()) {
      const float u_sel = rng.next_float();
      const EmissiveTriangles::Sample ls = lights_.sample(u_sel, rng.next_2d());
      const SurfacePoint lp = interpolate_surface(scene_, ls.triangle, ls.b1, ls.b2);
      const vec3 to_light = lp.position - pos;
      const float dist2 = glm::dot(to_light, to_light);
      const float dist = std::sqrt(dist2);
      if (dist > 0.0f) {
        const vec3 l = to_light / dist;
        const BsdfValue f = eval_bsdf(bp, l);
        const float cos_l = std::abs(glm::dot(lp.geometric_normal, l));
        // Directions within rounding of either plane carry no light (and a triangle never
        // lights itself); cutting them avoids 1/cos blow-ups from float noise.
        constexpr float kMinCos = 1e-5f;
        if (ls.triangle != hit.triangle && glm::dot(ng, l) > kMinCos && cos_l > kMinCos &&
            f.total() != vec3(0.0f)) {
          const vec3 lle = emitted_radiance(scene_, lp, evaluate_material(scene_, lp), -l);
          if (lle != vec3(0.0f)) {
            ++counts.shadow;
            if (!rt_.occluded(p, lp.position - p, 0.0f, 1.0f - eps_ / dist)) {
              const float pdf_light = ls.pdf_area * dist2 / cos_l;
              const float w = power_heuristic(pdf_light, bsdf_pdf(bp, l));
              const vec3 k = lle * (glm::dot(ns, l) * w / pdf_light);
              out.aov[kFull] += beta * f.total() * k;
              if (depth == 1) {
                out.aov[kIndirectDiffuse] += f.diffuse * k;
                out.aov[kIndirectSpecular] += f.specular * k;
              }
            }
          }
        }
      }
    }

    // Next-event estimation: one fire particle (an isotropic point light; delta, no MIS).
    if (particles_) {
      const ParticleLights::Sample ps = particles_->sample(rng.next_float());
      const vec3 to_light = ps.position - pos;
      const float dist2 = glm::dot(to_light, to_light);
      if (dist2 > 0.0f && ps.pmf > 0.0f) {
        const vec3 l = to_light / std::sqrt(dist2);
        const BsdfValue f = eval_bsdf(bp, l);
        if (f.total() != vec3(0.0f)) {
          ++counts.shadow;
          if (!rt_.occluded(p, ps.position - p, 0.0f, 1.0f)) {
            const vec3 k = ps.intensity * (glm::dot(ns, l) / (dist2 * ps.pmf));
            out.aov[kFull] += beta * f.total() * k;
            if (depth == 1) {
              out.aov[kIndirectDiffuse] += f.diffuse * k;
              out.aov[kIndirectSpecular] += f.specular * k;
            }
          }
        }
      }
    }

    // Continue by BSDF sampling (also when depth == max_depth: the next vertex's emission
    // completes paths of max_depth bounces, the MIS partner of the NEE above).
    const float u_lobe = rng.next_float();
    const BsdfSample bs = sample_bsdf(bp, u_lobe, rng.next_2d());
    if (!bs.valid) break;
    const BsdfValue f = eval_bsdf(bp, bs.l);
    if (f.total() == vec3(0.0f)) break;
    const float k = glm::dot(ns, bs.l) / bs.pdf;
    if (depth == 1) {
      lobe_d = f.diffuse * k;
      lobe_s = f.specular * k;
      beta = lobe_d + lobe_s;
    } else {
      beta *= f.total() * k;
    }
    if (depth >= settings_.rr_start_depth) {
      const float q = std::min(1.0f, max_component(beta));
      if (rng.next_float() >= q) break;
      beta /= q;
      lobe_d /= q;
      lobe_s /= q;
    }
    prev_pdf = bs.pdf;
    dir = bs.l;
    ++counts.secondary;
    hit = rt_.intersect(p, dir, 0.0f, kInf);
  }

  if (!finite(out)) {
    ++counts.nonfinite_samples;
    return PathSample{};
  }
  return out;
}

}  // namespace vct::pt
