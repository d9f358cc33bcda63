// Scenes built in code for the path tracer's analytic tests (independent of the glTF loader):
// flat-shaded triangles, quads, icospheres, simple materials.
#pragma once

#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"

namespace vct::pt::test {

/// Metallic 0, roughness 1, specular_factor 0: exactly albedo/pi (F = 0, kd = 1).
Material lambertian(const vec3& albedo, const vec3& emission = vec3(0.0f), bool double_sided = false);
/// A glTF metallic-roughness material with KHR_materials_specular factor 1.
Material pbr(const vec3& albedo, float metallic, float roughness);

uint32_t add_material(Scene& s, const Material& m);
/// One triangle with flat normals: front face (winding normal) = cross(b-a, c-a).
void add_triangle(Scene& s, const vec3& a, const vec3& b, const vec3& c, uint32_t material);
/// Parallelogram corner, corner+eu, corner+eu+ev, corner+ev; front = cross(eu, ev).
void add_quad(Scene& s, const vec3& corner, const vec3& eu, const vec3& ev, uint32_t material);
/// Closed icosphere (20 * 4^subdiv flat triangles); inward = front faces point to the centre.
void add_icosphere(Scene& s, const vec3& centre, float radius, int subdiv, bool inward, uint32_t material);
/// Axis-aligned closed box, front faces inward (a room).
void add_room(Scene& s, const vec3& lo, const vec3& hi, uint32_t material);

Camera look_at(const vec3& eye, const vec3& target, const vec3& up, float yfov);
/// Bounds and voxel volume from the positions.
void finish(Scene& s);

}  // namespace vct::pt::test

namespace vct::pt::test {
/// A small closed room exercising every feature of the estimator: a one-sided emissive ceiling
/// panel, a spot light, a rough metal block, a glossy dielectric sphere and coloured walls.
Scene demo_room();
}  // namespace vct::pt::test
