// Camera exposure as a pre-exposure of the scene's sources (docs/scenes.md, "Light units and
// exposure"): every punctual light's intensity, every material's emission and every particle colour is multiplied by
// one scale before any engine sees the scene. Light transport is linear in its sources, so each
// stage of ref, gl and pt is the unexposed stage times the scale: the GL/ref judge and the path
// tracer's bias compare like with like, and HDR formats (RGBA16F voxels, half images) hold a
// photometric export's 10^4-10^5 cd/m^2 without overflow (Filament's "pre-exposed lights").
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/settings.h"
#include "scene/scene.h"

namespace vct {

/// Incident-meter calibration constant for illuminance (ISO 2720: C = 250 lx s for a flat
/// receptor, ISO 100): EV100 = log2(E * 100 / C).
inline constexpr double kIncidentMeterC = 250.0;
/// Auto exposure keeps scale 1 while the meter's scale is within this many stops of 1 (docs/scenes.md).
inline constexpr double kAutoExposureDeadBandStops = 4.0;

/// A spot's flux as a share of an isotropic point light's of the same intensity: the solid angle of
/// its glTF cone (KHR_lights_punctual's squared ramp between the outer and inner cones) over 4 pi.
/// 20 degree hard spot: (1 - cos 20 deg) / 2 = 0.0302.
double spot_flux_share(const Light& light);

/// Illuminance (lux) a light meter at the centre of the scene's bounds reads from its sources: the sum
/// over punctual lights of the Rec. 709 luminance of colour x intensity, over d^2 for point and spot
/// lights (d at least 5 % of the bounds' diagonal; a spot as the isotropic source of its flux,
/// intensity x spot_flux_share: it lights a part of the scene, and aimed anywhere it still counts),
/// plus pi x the brightest material emission's luminance (an emitter seen over a hemisphere).
double key_illuminance(const Scene& scene);

/// Scale for a camera at `ev100` (saturation-based, Lagarde & de Rousiers 2014): 1 / (1.2 * 2^EV100).
double ev100_scale(double ev100);

/// Resolves the exposure setting for `scene` (does not change it).
ExposureApplied resolve_exposure(const Scene& scene, ExposureMode mode, float ev100);

/// run.json's "exposure": mode, key illuminance (lux), EV100, stops, scale.
nlohmann::json exposure_json(const ExposureApplied& e);

/// Multiplies the scene's sources by `e.scale` and records `e` in scene.exposure.
void pre_expose(Scene& scene, const ExposureApplied& e);

}  // namespace vct
