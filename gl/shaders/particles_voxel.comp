// Particle light added into the voxels (not averaged): each particle adds the shared
// particle_voxel_radiance to the voxel holding its centre, as fixed-point integer sums so the
// result does not depend on the order particles run in.
#include "voxel_fixed.glsl"
layout(local_size_x = 64) in;
layout(std140, binding = 0) uniform EmitterBlock { ParticleEmitterBlock u_emitter; };
layout(binding = 4, r32ui) uniform coherent uimage3D u_particle_r;
layout(binding = 5, r32ui) uniform coherent uimage3D u_particle_g;
layout(binding = 6, r32ui) uniform coherent uimage3D u_particle_b;
uniform uint u_emitter_index;
uniform uint u_count;
uniform float u_time;
uniform int u_grid;
uniform vec3 u_volume_origin;
uniform float u_volume_size;

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= u_count) return;
  ParticleState p = particle_state(u_emitter, u_emitter_index, id, u_time);
  vec3 tex = (p.position_radius.xyz - u_volume_origin) / u_volume_size;
  ivec3 c = ivec3(floor(tex * float(u_grid)));
  if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(u_grid)))) return;
  uvec3 q = uvec3(floor(particle_voxel_radiance(p, u_volume_size / float(u_grid)) * FIXED_POINT_SCALE + 0.5f));
  imageAtomicAdd(u_particle_r, c, q.r);
  imageAtomicAdd(u_particle_g, c, q.g);
  imageAtomicAdd(u_particle_b, c, q.b);
}
