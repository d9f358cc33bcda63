// Rasterized passes from the light and the camera: shadow maps, depth pre-pass and G-buffer.
#include <algorithm>
#include <cmath>

#include "gl_context.h"
#include "gl_frame.h"
#include "gl_resources.h"

namespace vct::gl {

void shadow_pass(GlFrame& f) {
  const int size = f.s.shadow_map_size;
  f.layer_view_proj = shadow_layer_view_proj(f.scene, f.s, &f.light_layer);  // at most kMaxLights (render_gl_frame)
  const int layers = int(f.layer_view_proj.size());
  f.shadow_maps = make_texture_2d_array(GL_DEPTH_COMPONENT32F, size, size, std::max(layers, 1));
  const Program prog = f.programs.build({"scene.vert", "depth_only.frag"});
  ScopedTimer timer(f.timers, "shadow_maps");
  GLuint fbo = 0;
  glCreateFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, size, size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  prog.use();
  for (int i = 0; i < layers; ++i) {
    glNamedFramebufferTextureLayer(fbo, GL_DEPTH_ATTACHMENT, f.shadow_maps, 0, i);
    glNamedFramebufferDrawBuffer(fbo, GL_NONE);
    const float one = 1.0f;
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &one);
    prog.set("u_view_proj", f.layer_view_proj[size_t(i)]);
    f.geo.draw_depth_only(prog);
  }
  check_gl("shadow pass");
}

void gbuffer_pass(GlFrame& f) {
  const int w = f.s.width, h = f.s.height;
  for (auto& t : f.gbuffer) t = make_texture_2d(GL_RGBA32F, w, h);
  f.gbuffer_depth = make_texture_2d(GL_DEPTH_COMPONENT32F, w, h);
  glCreateFramebuffers(1, &f.gbuffer_fbo);
  GLenum bufs[6];
  for (GLuint i = 0; i < 6; ++i) {
    glNamedFramebufferTexture(f.gbuffer_fbo, GL_COLOR_ATTACHMENT0 + i, f.gbuffer[i], 0);
    bufs[i] = GL_COLOR_ATTACHMENT0 + i;
  }
  glNamedFramebufferTexture(f.gbuffer_fbo, GL_DEPTH_ATTACHMENT, f.gbuffer_depth, 0);
  const mat4 view_proj = f.scene.camera.projection(float(w) / float(h)) * f.scene.camera.view();
  const Program depth_prog = f.programs.build({"scene.vert", "depth_only.frag"});
  const Program gbuf_prog = f.programs.build({"scene.vert", "gbuffer.frag"});
  glBindFramebuffer(GL_FRAMEBUFFER, f.gbuffer_fbo);
  glViewport(0, 0, w, h);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float one = 1.0f;
  for (GLint i = 0; i < 6; ++i) glClearNamedFramebufferfv(f.gbuffer_fbo, GL_COLOR, i, zero);
  glClearNamedFramebufferfv(f.gbuffer_fbo, GL_DEPTH, 0, &one);
  if (f.s.depth_prepass) {
    // Occlusion culling: depth first (no colour), then shade only the fragments whose depth
    // equals the nearest one. `invariant gl_Position` makes both passes' depths identical.
    ScopedTimer timer(f.timers, "depth_prepass");
    glNamedFramebufferDrawBuffer(f.gbuffer_fbo, GL_NONE);
    glDepthFunc(GL_LESS);
    depth_prog.use();
    depth_prog.set("u_view_proj", view_proj);
    f.geo.draw_depth_only(depth_prog);
  }
  {
    ScopedTimer timer(f.timers, "gbuffer");
    glNamedFramebufferDrawBuffers(f.gbuffer_fbo, 6, bufs);
    glDepthFunc(f.s.depth_prepass ? GL_LEQUAL : GL_LESS);
    gbuf_prog.use();
    gbuf_prog.set("u_view_proj", view_proj);
    f.geo.draw(gbuf_prog);
  }
  check_gl("gbuffer pass");
}

}  // namespace vct::gl
