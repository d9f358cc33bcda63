// Internal: the GPU state of one frame, handed from pass to pass (gl_pass_*.cpp). Every GL object
// belongs to the frame's context and dies with it, so passes create freely and never delete.
#pragma once

#include <array>
#include <vector>

#include "core/settings.h"
#include "gl_conservative.h"
#include "gl_program.h"
#include "gl_scene.h"
#include "gl_timer.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::gl {

struct GlFrame {
  GlFrame(const Scene& sc, const VctSettings& st, FrameResult& r, const std::string& fault_name)
      : scene(sc), s(st), geo(sc), out(r), fault(fault_name), programs(fault_name) {}

  const Scene& scene;
  VctSettings s;
  GlScene geo;
  FrameResult& out;
  GpuTimers timers;
  std::string fault;        // "" or a kGlFaults name (gl_faults.h)
  ProgramBuilder programs;  // every program of the frame: carries the fault's #define
  bool has_fault(const char* name) const { return fault == name; }
  int samples = 1;  // MSAA samples actually used for voxelization
  ConservativeSetup conservative;  // settings.conservative_raster as this driver runs it

  // One layer per spot or directional light, six per point light (cube faces in GL's order).
  std::vector<mat4> layer_view_proj;
  std::vector<int> light_layer;   // light i's first layer
  GLuint shadow_maps = 0;         // DEPTH_COMPONENT32F 2D array of those layers
  std::array<GLuint, 6> gbuffer{};  // position(+coverage), normal, albedo, material, specular, emission
  GLuint gbuffer_depth = 0;
  GLuint gbuffer_fbo = 0;

  GLenum voxel_format = GL_RGBA16F;
  int levels = 1;
  GLuint radiance = 0;                // voxel radiance with its mip chain
  GLuint bounce_input = 0;            // the frame before the last's radiance (multibounce), else 0
  std::array<GLuint, 6> aniso{};      // directional volumes, level 0 = mip 1
  std::array<GLuint, 4> sums{};       // r, g, b (or packed CAS), count
  std::array<GLuint, 3> particle_sums{};
  GLuint facing = 0;  // R32UI facing masks (solid voxelization and thickening only)
  GLuint emitter_ubo = 0;
  GLuint diffuse_cone_ubo = 0;  // sh::DiffuseConeBlock of the settings (binding 1, cone.glsl)

  GLuint direct = 0, soft_shadow = 0;
  std::array<GLuint, 5> shading{};  // indirect diffuse, indirect specular, diffuse term, specular term, final
  GLuint particles = 0;
  GLuint empty_vao = 0;
};

// The passes, in frame order.
/// The shadow layers' world -> clip matrices, light by light (the CPU's definitions, shared by
/// call: both backends render from the same matrices), and each light's first layer.
std::vector<mat4> shadow_layer_view_proj(const Scene& scene, const VctSettings& settings, std::vector<int>* light_layer);
void shadow_pass(GlFrame& f);
void gbuffer_pass(GlFrame& f);
void upload_diffuse_cone_block(GlFrame& f);  // the cone set's shared block, before any cone pass
void voxel_passes(GlFrame& f);   // voxelization (+ multibounce frames), particles into voxels, mips
void direct_pass(GlFrame& f);
void indirect_pass(GlFrame& f);
void particle_pass(GlFrame& f);
void read_back(GlFrame& f);

/// Binds the voxel mips (units 5..11) and the diffuse cone block (uniform buffer 1) and sets the
/// cone uniforms (cone.glsl) on `p`.
void bind_voxels(const GlFrame& f, const Program& p, GLuint radiance, const std::array<GLuint, 6>& aniso);

}  // namespace vct::gl
