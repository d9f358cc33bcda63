// Screen-space passes over the G-buffer: direct light, indirect light + final composition, and
// the additive particle layer.
#include <algorithm>

#include "gl_context.h"
#include "gl_frame.h"
#include "gl_resources.h"
#include "gl_setting_uniforms.h"

namespace vct::gl {
namespace {

// A framebuffer over `colour` (+ depth); `clear` zeroes the colour attachments first.
GLuint framebuffer(const std::vector<GLuint>& colour, GLuint depth, bool clear = true) {
  GLuint fbo = 0;
  glCreateFramebuffers(1, &fbo);
  std::vector<GLenum> bufs;
  for (size_t i = 0; i < colour.size(); ++i) {
    glNamedFramebufferTexture(fbo, GLenum(GL_COLOR_ATTACHMENT0 + i), colour[i], 0);
    bufs.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  }
  if (depth) glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth, 0);
  glNamedFramebufferDrawBuffers(fbo, GLsizei(bufs.size()), bufs.data());
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  if (clear)
    for (GLint i = 0; i < GLint(colour.size()); ++i) glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  return fbo;
}

// gl/shaders/camera.glsl's uniforms.
void set_camera_uniforms(const Camera& c, const Program& p) {
  p.set("u_camera_position", c.position);
  p.set("u_camera_forward", glm::normalize(c.forward));
  p.set("u_camera_orthographic", c.orthographic ? 1 : 0);
}

void bind_gbuffer(const GlFrame& f, const Program& p) {
  for (GLuint i = 0; i < 6; ++i) glBindTextureUnit(12 + i, f.gbuffer[i]);
  set_camera_uniforms(f.scene.camera, p);
  p.set("u_volume_origin", f.scene.volume.origin);
  p.set("u_volume_size", f.scene.volume.size);
}

void fullscreen(const GlFrame& f) {
  glViewport(0, 0, f.s.width, f.s.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(f.empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace

void direct_pass(GlFrame& f) {
  f.direct = make_texture_2d(GL_RGBA32F, f.s.width, f.s.height);
  f.soft_shadow = make_texture_2d(GL_RGBA32F, f.s.width, f.s.height);
  const Program prog = f.programs.build({"fullscreen.vert", "direct.frag"});
  ScopedTimer timer(f.timers, "direct");
  framebuffer({f.direct, f.soft_shadow}, 0);
  prog.use();
  f.geo.set_lights(prog, f.s, f.layer_view_proj, f.light_layer);
  glBindTextureUnit(4, f.shadow_maps);
  bind_voxels(f, prog, f.radiance, f.aniso);
  bind_gbuffer(f, prog);
  set_setting_uniforms(prog, f.s);
  prog.set("u_shadow_aperture", f.s.soft_shadow_aperture_deg * (kPi / 180.0f));
  prog.set("u_nv_mode", nv_mode(f.s.n_dot_v));  // the reference's stages/direct.cpp takes the same
  fullscreen(f);
  check_gl("direct pass");
}

void indirect_pass(GlFrame& f) {
  for (GLuint& t : f.shading) t = make_texture_2d(GL_RGBA32F, f.s.width, f.s.height);
  const Program prog = f.programs.build({"fullscreen.vert", "indirect.frag"});
  ScopedTimer timer(f.timers, "indirect_cones");
  framebuffer(std::vector<GLuint>(f.shading.begin(), f.shading.end()), 0);
  prog.use();
  bind_voxels(f, prog, f.radiance, f.aniso);
  bind_gbuffer(f, prog);
  glBindTextureUnit(18, f.direct);
  set_setting_uniforms(prog, f.s);
  prog.set("u_frame", unsigned(f.s.frame));  // unsigned in GLSL: the hash's input
  fullscreen(f);
  check_gl("indirect pass");
}

void particle_pass(GlFrame& f) {
  f.particles = make_texture_2d(GL_RGBA32F, f.s.width, f.s.height);
  if (!f.s.particles || f.scene.emitters.empty()) return;
  const Program prog = f.programs.build({"particles.vert", "particles.frag"});
  ScopedTimer timer(f.timers, "particles");
  // Depth-tested against the opaque surfaces, never writing depth, blended additively.
  framebuffer({f.particles, f.shading[4]}, f.gbuffer_depth, false);  // keep the final image: add onto it
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(f.particles, 0, GL_RGBA, GL_FLOAT, zero);
  glViewport(0, 0, f.s.width, f.s.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  prog.use();
  const mat4 view = f.scene.camera.view();
  prog.set("u_view_proj", f.scene.camera.projection(float(f.s.width) / float(f.s.height)) * view);
  set_camera_uniforms(f.scene.camera, prog);
  set_setting_uniforms(prog, f.s);
  glBindVertexArray(f.empty_vao);
  for (size_t e = 0; e < f.scene.emitters.size(); ++e) {
    const ParticleEmitter& em = f.scene.emitters[e];
    const vec4 block[7] = {vec4(em.origin, float(em.count)), vec4(em.spawn_extent, em.lifetime),
                           vec4(em.velocity_min, 0.0f), vec4(em.velocity_max, 0.0f), vec4(em.acceleration, 0.0f),
                           vec4(em.color_start, em.size_start), vec4(em.color_end, em.size_end)};
    glNamedBufferSubData(f.emitter_ubo, 0, sizeof block, block);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, f.emitter_ubo);
    prog.set("u_emitter_index", unsigned(e));
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, em.count);
  }
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  check_gl("particle pass");
}

}  // namespace vct::gl
