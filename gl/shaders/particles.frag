// Additive particle light: colour x the shared splat profile; written both to the particle layer
// and onto the final image (blending ONE, ONE).
in vec2 v_disc;
in vec3 v_color;
layout(location = 0) out vec4 o_particles;
layout(location = 1) out vec4 o_final;
void main() {
  float w = particle_profile(length(v_disc), 1.0f);
  if (w <= 0.0f) discard;
  o_particles = vec4(v_color * w, 0.0f);
  o_final = o_particles;
}
