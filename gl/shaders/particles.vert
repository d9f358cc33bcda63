// Fire particles as discs facing the eye (plane normal = eye -> centre, -to_eye, as ref/stages/particles.cpp), one instance per particle; the state is the shared
// stateless function of (emitter, id, time).
layout(std140, binding = 0) uniform EmitterBlock { ParticleEmitterBlock u_emitter; };
uniform uint u_emitter_index;
uniform float u_time;
uniform mat4 u_view_proj;
#include "camera.glsl"
out vec2 v_disc;   // position in the disc, in radii
out vec3 v_color;

void main() {
  ParticleState p = particle_state(u_emitter, u_emitter_index, uint(gl_InstanceID), u_time);
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0f - 1.0f;
  float r = p.position_radius.w;
  vec3 centre = p.position_radius.xyz;
  vec3 normal = -to_eye(centre);
  vec3 helper = abs(normal.y) < 0.99f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
  vec3 right = normalize(cross(helper, normal));
  vec3 up = cross(normal, right);
  // The quad encloses the disc; v_disc interpolates (perspective-correct) to the hit point's
  // coordinates in the disc plane, in radii.
  vec3 world = centre + (right * corner.x + up * corner.y) * r;
  v_disc = corner;
  v_color = p.color_age.rgb;
  gl_Position = u_view_proj * vec4(world, 1.0f);
}
