#include "scene/exposure.h"

#include <algorithm>
#include <cmath>

#include "shared/vct_shared.h"

namespace vct {

namespace {

double luminance(const vec3& rgb) { return 0.2126 * double(rgb.r) + 0.7152 * double(rgb.g) + 0.0722 * double(rgb.b); }

// The share of a spot's axis intensity the meter counts: its cone at the meter (KHR_lights_punctual's
// attenuation toward the centre), but never less than its flux spread over the whole sphere.
double spot_meter_share(const Light& l, const vec3& centre) {
  const vec3 to_centre = centre - l.position;
  const float len = glm::length(to_centre);
  const double at_meter =
      len > 0.0f ? double(sh::spot_cone_gltf(glm::dot(to_centre / len, glm::normalize(l.direction)),
                                              std::cos(l.inner_cone_angle), std::cos(l.outer_cone_angle)))
                 : 1.0;
  return std::max(at_meter, spot_flux_share(l));
}

double light_illuminance(const Light& l, const vec3& centre, double min_distance) {
  const double flux = luminance(l.color) * double(l.intensity) * (l.is_spot() ? spot_meter_share(l, centre) : 1.0);
  if (l.is_directional()) return flux;
  const double d = std::max(double(glm::length(l.position - centre)), min_distance);
  return flux / (d * d);
}

}  // namespace

double spot_flux_share(const Light& l) {
  const double ci = std::cos(double(l.inner_cone_angle)), co = std::cos(double(l.outer_cone_angle));
  // 2 pi int f(c) dc over the cone: 1 from cos_inner to 1, the squared ramp t^2 (t linear in c) over
  // [cos_outer, cos_inner] integrates to (cos_inner - cos_outer) / 3; a hard spot has no ramp.
  const double solid_angle = 2.0 * M_PI * ((1.0 - ci) + std::max(ci - co, 0.0) / 3.0);
  return solid_angle / (4.0 * M_PI);
}

double key_illuminance(const Scene& scene) {
  const vec3 centre = 0.5f * (scene.bounds.lo + scene.bounds.hi);
  const double min_distance = 0.05 * double(glm::length(scene.bounds.hi - scene.bounds.lo));
  double e = 0.0;
  for (const Light& l : scene.lights) e += light_illuminance(l, centre, std::max(min_distance, 1e-6));
  double brightest_emission = 0.0;
  for (const Material& m : scene.materials) brightest_emission = std::max(brightest_emission, luminance(m.emission()));
  return e + M_PI * brightest_emission;
}

double ev100_scale(double ev100) { return 1.0 / (1.2 * std::exp2(ev100)); }

ExposureApplied resolve_exposure(const Scene& scene, ExposureMode mode, float ev100) {
  ExposureApplied e;
  e.mode = to_string(mode);
  e.key_illuminance = key_illuminance(scene);
  if (mode == ExposureMode::None) return e;
  if (mode == ExposureMode::Ev100) {
    e.ev100 = ev100;
    e.scale = float(ev100_scale(ev100));
    return e;
  }
  if (!(e.key_illuminance > 0.0) || !std::isfinite(e.key_illuminance)) return e;  // nothing to meter
  e.ev100 = std::log2(e.key_illuminance * 100.0 / kIncidentMeterC);
  const double stops = std::log2(ev100_scale(e.ev100));
  // Whole stops: scaling by 2^k is exact in binary floating point (and half), so pre-exposure
  // changes no rounding anywhere; inside the dead band the file's own units are kept (scale 1).
  e.stops = std::fabs(stops) <= kAutoExposureDeadBandStops ? 0 : int(std::lround(stops));
  e.scale = float(std::exp2(e.stops));
  return e;
}

void pre_expose(Scene& scene, const ExposureApplied& e) {
  for (Light& l : scene.lights) l.intensity *= e.scale;
  for (Material& m : scene.materials) m.emissive_strength *= e.scale;
  for (ParticleEmitter& p : scene.emitters) {
    p.color_start *= e.scale;
    p.color_end *= e.scale;
  }
  scene.exposure = e;
}

nlohmann::json exposure_json(const ExposureApplied& e) {
  return {{"mode", e.mode}, {"key_illuminance_lux", e.key_illuminance}, {"ev100", e.ev100}, {"stops", e.stops},
          {"scale", e.scale}};
}

}  // namespace vct
