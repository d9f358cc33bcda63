// Voxelization (dominant-axis geometry shader, MSAA coverage on an attachment-less framebuffer),
// the per-voxel reduction and its resolve, particles added into the voxels, temporal multibounce,
// and the isotropic / anisotropic mip chains built by compute shaders.
#include <algorithm>
#include <cmath>
#include <string>

#include "gl_context.h"
#include "gl_frame.h"
#include "gl_resources.h"
#include "gl_setting_uniforms.h"
#include "core/memory_budget.h"
#include "stages/cone_sets.h"
#include "stages/multibounce.h"

namespace vct::gl {
namespace {

GLuint groups(int n) { return GLuint((n + 3) / 4); }

void bind_image(GLuint unit, GLuint tex, GLint level, GLenum access, GLenum format) {
  glBindImageTexture(unit, tex, level, GL_TRUE, 0, access, format);
}

void clear_uint(GLuint tex) {
  const GLuint zero = 0;
  glClearTexImage(tex, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void set_volume(const GlFrame& f, const Program& p) {
  p.set("u_volume_origin", f.scene.volume.origin);
  p.set("u_volume_size", f.scene.volume.size);
  set_setting_uniforms(p, f.s);
}

// std140 image of sh::ParticleEmitterBlock (seven vec4s).
struct EmitterStd140 {
  vec4 v[7];
};

EmitterStd140 emitter_block(const ParticleEmitter& e) {
  EmitterStd140 b;
  b.v[0] = vec4(e.origin, float(e.count));
  b.v[1] = vec4(e.spawn_extent, e.lifetime);
  b.v[2] = vec4(e.velocity_min, 0.0f);
  b.v[3] = vec4(e.velocity_max, 0.0f);
  b.v[4] = vec4(e.acceleration, 0.0f);
  b.v[5] = vec4(e.color_start, e.size_start);
  b.v[6] = vec4(e.color_end, e.size_end);
  return b;
}

void inject_particles(GlFrame& f) {
  for (GLuint& t : f.particle_sums) clear_uint(t);
  if (!f.s.particles || f.scene.emitters.empty()) return;
  ScopedTimer timer(f.timers, "particles_voxels");
  const Program prog = f.programs.build({"particles_voxel.comp"});
  prog.use();
  set_volume(f, prog);
  for (GLuint c = 0; c < 3; ++c) bind_image(4 + c, f.particle_sums[c], 0, GL_READ_WRITE, GL_R32UI);
  for (size_t e = 0; e < f.scene.emitters.size(); ++e) {
    const EmitterStd140 block = emitter_block(f.scene.emitters[e]);
    glNamedBufferSubData(f.emitter_ubo, 0, sizeof block, &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, f.emitter_ubo);
    prog.set("u_emitter_index", unsigned(e));
    prog.set("u_count", unsigned(f.scene.emitters[e].count));
    glDispatchCompute(GLuint((f.scene.emitters[e].count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  check_gl("particles into voxels");
}

// One voxelization frame into f.sums; bounce > 0 reads the previous frame's mips.
void voxelize(GlFrame& f, const Program& prog, int bounce, GLuint prev_radiance,
              const std::array<GLuint, 6>& prev_aniso) {
  ScopedTimer timer(f.timers, "voxelize");
  for (GLuint& t : f.sums) clear_uint(t);
  GLuint fbo = 0;
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_WIDTH, f.s.grid);
  glNamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_HEIGHT, f.s.grid);
  glNamedFramebufferParameteri(fbo, GL_FRAMEBUFFER_DEFAULT_SAMPLES, f.samples > 1 ? f.samples : 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, f.s.grid, f.s.grid);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  if (f.samples > 1) glEnable(GL_MULTISAMPLE);
  prog.use();
  if (f.conservative.mode != ConservativeRaster::Off) {
    prog.set("u_emit_quad", f.conservative.emit_quad ? 1 : 0);
    prog.set("u_clip_dilation", f.conservative.clip_dilation);
    prog.set("u_keep_outside", f.conservative.keep_outside ? 1 : 0);
  }
  set_volume(f, prog);
  f.geo.set_lights(prog, f.s, f.layer_view_proj, f.light_layer);
  glBindTextureUnit(4, f.shadow_maps);
  prog.set("u_bounce", bounce);
  prog.set("u_reduction", f.s.reduction == Reduction::CasRgba8 ? 1 : 0);
  if (bounce > 0) bind_voxels(f, prog, prev_radiance, prev_aniso);
  for (GLuint c = 0; c < 4; ++c) bind_image(c, f.sums[c], 0, GL_READ_WRITE, GL_R32UI);
  if (f.facing) {
    clear_uint(f.facing);
    bind_image(4, f.facing, 0, GL_READ_WRITE, GL_R32UI);
  }
  if (f.conservative.cap) glEnable(f.conservative.cap);
  f.geo.draw(prog);
  if (f.conservative.cap) glDisable(f.conservative.cap);
  // The resolve reads what the fragment shader's atomics wrote: GL 4.5 §7.12.2 orders the two
  // only through this barrier (the missing_barrier fault leaves it out).
  if (!f.has_fault("missing_barrier")) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  check_gl("voxelization");
}

void resolve(GlFrame& f, GLuint target) {
  ScopedTimer timer(f.timers, "resolve");
  const Program prog = f.programs.build({"voxel_resolve.comp"});
  prog.use();
  set_setting_uniforms(prog, f.s);
  prog.set("u_reduction", f.s.reduction == Reduction::CasRgba8 ? 1 : 0);
  prog.set("u_storage_format", f.voxel_format == GL_RGBA8 ? 1 : 0);
  for (GLuint c = 0; c < 4; ++c) bind_image(c, f.sums[c], 0, GL_READ_ONLY, GL_R32UI);
  for (GLuint c = 0; c < 3; ++c) bind_image(4 + c, f.particle_sums[c], 0, GL_READ_ONLY, GL_R32UI);
  bind_image(7, target, 0, GL_WRITE_ONLY, f.voxel_format);
  glDispatchCompute(groups(f.s.grid), groups(f.s.grid), groups(f.s.grid));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  check_gl("voxel resolve");
}

// Solid interior and thickening (voxel_fill.comp) on the resolved base level.
void fill(GlFrame& f, GLuint target) {
  if (!f.s.solid_voxelization && f.s.surface_thickening_voxels <= 0) return;
  ScopedTimer timer(f.timers, "voxel_fill");
  const std::string format = f.voxel_format == GL_RGBA8 ? "rgba8" : "rgba16f";
  const Program prog =
      Program::from_files({"voxel_fill.comp"}, f.programs.defines() + "#define VCT_VOXEL_FORMAT " + format + "\n");
  prog.use();
  set_setting_uniforms(prog, f.s);
  bind_image(0, f.sums[3], 0, GL_READ_ONLY, GL_R32UI);
  if (f.facing) bind_image(1, f.facing, 0, GL_READ_ONLY, GL_R32UI);
  bind_image(2, target, 0, GL_READ_WRITE, f.voxel_format);
  glDispatchCompute(groups(f.s.grid), groups(f.s.grid), groups(f.s.grid));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  check_gl("voxel fill");
}

void build_mips(GlFrame& f, GLuint radiance, const std::array<GLuint, 6>& aniso) {
  ScopedTimer timer(f.timers, "mips");
  const Program iso = f.programs.build({"mip_iso.comp"});
  iso.use();
  iso.set("u_storage_format", f.voxel_format == GL_RGBA8 ? 1 : 0);
  glBindTextureUnit(0, radiance);
  for (int l = 1, size = f.s.grid / 2; l < f.levels; ++l, size /= 2) {
    iso.set("u_src_level", l - 1);
    iso.set("u_dst_size", size);
    bind_image(0, radiance, l, GL_WRITE_ONLY, f.voxel_format);
    glDispatchCompute(groups(size), groups(size), groups(size));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  if (f.s.anisotropic) {
    const Program an = f.programs.build({"mip_aniso.comp"});
    an.use();
    an.set("u_storage_format", f.voxel_format == GL_RGBA8 ? 1 : 0);
    for (int d = 0; d < 6; ++d) {
      an.set("u_axis", d / 2);
      an.set("u_positive", d % 2 == 0 ? 1 : 0);
      for (int l = 0, size = f.s.grid / 2; l < f.levels - 1; ++l, size /= 2) {
        // Level 0 of a directional volume is built from the shared base level.
        glBindTextureUnit(0, l == 0 ? radiance : aniso[size_t(d)]);
        an.set("u_src_level", l == 0 ? 0 : l - 1);
        an.set("u_dst_size", size);
        bind_image(0, aniso[size_t(d)], l, GL_WRITE_ONLY, f.voxel_format);
        glDispatchCompute(groups(size), groups(size), groups(size));
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      }
    }
  }
  check_gl("mips");
}

// The frame's base level as stored (the energy is summed from it, and the frames before the last
// are kept for the judge: voxel.frame.<frame>, compare/bounce_frames.h).
Volume read_base_level(const GlFrame& f, GLuint radiance, int n) {
  return f.voxel_format == GL_RGBA8 ? read_volume_unorm8(radiance, 0, n) : read_volume(radiance, 0, n, 4);
}

}  // namespace

void bind_voxels(const GlFrame& f, const Program& p, GLuint radiance, const std::array<GLuint, 6>& aniso) {
  glBindTextureUnit(5, radiance);
  for (GLuint d = 0; d < 6; ++d) glBindTextureUnit(6 + d, f.s.anisotropic ? aniso[d] : radiance);
  set_setting_uniforms(p, f.s);
  // Derived from settings: texture units and radians.
  const MarchParams march = MarchParams::from_settings(f.s, f.s.grid);  // the CPU's floats
  p.set("u_cone_start", march.start_offset);
  p.set("u_cone_normal_offset", march.normal_offset);
  p.set("u_shadow_cone_start", MarchParams::shadow_from_settings(f.s, f.s.grid).start_offset);
  p.set("u_diffuse_aperture", f.s.diffuse_aperture_deg * (kPi / 180.0f));
  glBindBufferBase(GL_UNIFORM_BUFFER, 1, f.diffuse_cone_ubo);
}

void upload_diffuse_cone_block(GlFrame& f) {
  // Two vec4s: std140 and C++ layouts coincide, so the host's floats go up byte for byte.
  static_assert(sizeof(sh::DiffuseConeBlock) == 2 * sizeof(vec4), "DiffuseConeBlock must stay two vec4s");
  const sh::DiffuseConeBlock block = diffuse_cone_block(f.s);
  glCreateBuffers(1, &f.diffuse_cone_ubo);
  glNamedBufferStorage(f.diffuse_cone_ubo, sizeof block, &block, 0);
}

void voxel_passes(GlFrame& f) {
  const int n = f.s.grid;
  f.voxel_format = f.s.storage == VoxelStorage::Rgba8 ? GL_RGBA8 : GL_RGBA16F;
  f.levels = mip_count(n);
  for (GLuint& t : f.sums) t = make_texture_3d(GL_R32UI, n, 1);
  for (GLuint& t : f.particle_sums) t = make_texture_3d(GL_R32UI, n, 1);
  if (f.s.surface_thickening_voxels > 0 || f.s.solid_voxelization) f.facing = make_texture_3d(GL_R32UI, n, 1);
  glCreateBuffers(1, &f.emitter_ubo);
  glNamedBufferStorage(f.emitter_ubo, 7 * sizeof(vec4), nullptr, GL_DYNAMIC_STORAGE_BIT);
  // Two voxel textures (and directional sets): multibounce frame b reads frame b-1's.
  std::array<GLuint, 2> radiance{};
  std::array<std::array<GLuint, 6>, 2> aniso{};
  for (int i = 0; i < 2; ++i) {
    radiance[size_t(i)] = make_texture_3d(f.voxel_format, n, f.levels);
    if (f.s.anisotropic)
      for (GLuint& t : aniso[size_t(i)]) t = make_texture_3d(f.voxel_format, n / 2, f.levels - 1);
  }
  const Program prog = f.conservative.mode == ConservativeRaster::Off
                           ? f.programs.build({"voxelize.vert", "voxelize.geom", "voxelize.frag"})
                           : f.programs.build({"voxelize.vert", "voxelize_conservative.geom", "voxelize_conservative.frag"});
  inject_particles(f);
  const int frames = std::max(f.s.bounces, 1);
  // The frames before the last are read back under the reference's memory rule (core/memory_budget.h).
  const bool keep = keeps_multibounce_frames(f.s);
  size_t cur = 0;
  for (int b = 0; b < frames; ++b) {
    cur = size_t(b % 2);
    const size_t prev = 1 - cur;
    // The bounce_reads_current_frame fault traces the bounce light in the texture being written
    // (its mips hold the frame before the previous one, or nothing in frame 2).
    const size_t read = f.has_fault("bounce_reads_current_frame") ? cur : prev;
    voxelize(f, prog, b, radiance[read], aniso[read]);
    resolve(f, radiance[cur]);
    fill(f, radiance[cur]);
    build_mips(f, radiance[cur], aniso[cur]);
    Volume base = read_base_level(f, radiance[cur], n);
    f.out.multibounce_energy.push_back(total_energy(base));
    if (keep) f.out.multibounce_frames.push_back(std::move(base));
    f.bounce_input = b > 0 ? radiance[prev] : 0;
    if (multibounce_converged(f.out.multibounce_energy, f.s.convergence_tolerance)) break;
  }
  if (!f.out.multibounce_frames.empty()) f.out.multibounce_frames.pop_back();  // the last is voxel.radiance
  f.radiance = radiance[cur];
  f.aniso = aniso[cur];
}

}  // namespace vct::gl
