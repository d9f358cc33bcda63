// The scene on the GPU: one interleaved vertex buffer, indices grouped by material (one draw per
// material), textures uploaded on first use (SRGB8_ALPHA8 for colour, RGBA8 for data) with the
// glTF sampler's wrap and filter, no mipmaps (as ref/scene/surface.cpp samples them).
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "core/settings.h"
#include "gl_program.h"
#include "scene/scene.h"

namespace vct::gl {

struct DrawRange {
  uint32_t material = 0;
  GLsizei first = 0;  // first index
  GLsizei count = 0;  // index count
};

class GlScene {
 public:
  explicit GlScene(const Scene& scene);
  /// Draws every triangle (one call per material), setting material uniforms on `p` first.
  void draw(const Program& p);
  /// Draws for the depth passes (depth_only.frag): one call for everything when no material is
  /// alpha tested; otherwise one call per material with its alpha-test uniforms and base colour
  /// texture bound on `p`.
  void draw_depth_only(const Program& p);
  /// Spot-light uniforms (lights.glsl) for `p`; `view_proj` one per light.
  void set_lights(const Program& p, const VctSettings& s, const std::vector<mat4>& layer_view_proj,
                  const std::vector<int>& light_layer) const;
  const Scene& scene() const { return scene_; }

 private:
  void bind_material(const Program& p, const Material& m);
  GLuint texture(int index, bool srgb);

  const Scene& scene_;
  GLuint vao_ = 0, vbo_ = 0, ibo_ = 0;
  GLsizei index_count_ = 0;
  std::vector<DrawRange> ranges_;
  std::map<std::pair<int, bool>, GLuint> textures_;
  GLuint white_ = 0;
  bool alpha_tested_ = false;  // some material has alphaMode MASK or BLEND
};

/// Maximum lights (of any kind) the shaders take (lights.glsl's MAX_LIGHTS).
constexpr int kMaxLights = 8;

}  // namespace vct::gl
