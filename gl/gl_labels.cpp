#include "gl_labels.h"

#include <string>
#include <utility>
#include <vector>

#include "gl_context.h"
#include "gl_frame.h"

namespace vct::gl {

void label_frame_textures(const GlFrame& f) {
  // One row per texture read_back (gl_readback.cpp) reads: label -> texture.
  const std::vector<std::pair<std::string, GLuint>> rows = {
      {"vct.shadow_maps", f.shadow_maps},         {"vct.gbuffer.position", f.gbuffer[0]},
      {"vct.gbuffer.normal", f.gbuffer[1]},       {"vct.gbuffer.albedo", f.gbuffer[2]},
      {"vct.gbuffer.material", f.gbuffer[3]},     {"vct.gbuffer.specular_color", f.gbuffer[4]},
      {"vct.gbuffer.emission", f.gbuffer[5]},     {"vct.gbuffer.depth", f.gbuffer_depth},
      {"vct.radiance", f.radiance},               {"vct.bounce_input", f.bounce_input},
      {"vct.fragments", f.sums[3]},               {"vct.aniso.posx", f.aniso[0]},
      {"vct.aniso.negx", f.aniso[1]},             {"vct.aniso.posy", f.aniso[2]},
      {"vct.aniso.negy", f.aniso[3]},             {"vct.aniso.posz", f.aniso[4]},
      {"vct.aniso.negz", f.aniso[5]},             {"vct.direct", f.direct},
      {"vct.soft_shadow", f.soft_shadow},         {"vct.indirect_diffuse", f.shading[0]},
      {"vct.indirect_specular", f.shading[1]},    {"vct.diffuse_term", f.shading[2]},
      {"vct.specular_term", f.shading[3]},        {"vct.final", f.shading[4]},
      {"vct.particles", f.particles}};
  for (const auto& [label, texture] : rows)
    if (texture != 0) glObjectLabel(GL_TEXTURE, texture, GLsizei(label.size()), label.c_str());
}

}  // namespace vct::gl
