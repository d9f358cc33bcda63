// Every stage's GPU result read back into the reference's types (stage_types.h conventions:
// images row 0 = top, volumes x fastest, G-buffer channels as documented there).
#include <algorithm>
#include <cstdint>
#include <string>

#include "gl_context.h"
#include "gl_frame.h"
#include "gl_resources.h"

namespace vct::gl {
namespace {

Image channel(const Image& src, int c, const char* name) {
  Image out(src.width, src.height, 1);
  for (size_t i = 0; i < size_t(src.width) * size_t(src.height); ++i) out.data[i] = src.data[i * size_t(src.channels) + size_t(c)];
  out.channel_names = {name};
  return out;
}

Image rgb(GLuint tex, int w, int h) {
  Image img = read_image(tex, w, h, 3);
  img.channel_names = {"R", "G", "B"};
  return img;
}

}  // namespace

static Volume read_voxels(const GlFrame& f, GLuint tex, int level, int n) {
  return f.voxel_format == GL_RGBA8 ? read_volume_unorm8(tex, level, n) : read_volume(tex, level, n, 4);
}

void read_back(GlFrame& f) {
  FrameResult& r = f.out;
  const int w = f.s.width, h = f.s.height, n = f.s.grid;
  const int map_size = f.s.shadow_map_size;
  for (size_t i = 0; i < f.light_layer.size(); ++i) {
    ShadowMap sm;
    const int layer = f.light_layer[i];
    if (f.scene.lights[i].is_point()) {
      for (int face = 0; face < 6; ++face) {
        sm.cube[size_t(face)] = read_depth(f.shadow_maps, map_size, map_size, layer + face);
        sm.cube_view_proj[size_t(face)] = f.layer_view_proj[size_t(layer + face)];
      }
    } else {
      sm.depth = read_depth(f.shadow_maps, map_size, map_size, layer);
      sm.view_proj = f.layer_view_proj[size_t(layer)];
    }
    r.shadow_maps.push_back(std::move(sm));
  }
  GBuffer& g = r.gbuffer;
  const Image pos4 = read_image(f.gbuffer[0], w, h, 4);
  g.position = rgb(f.gbuffer[0], w, h);
  g.coverage = channel(pos4, 3, "Y");
  g.normal = rgb(f.gbuffer[1], w, h);
  g.albedo = rgb(f.gbuffer[2], w, h);
  g.material = read_image(f.gbuffer[3], w, h, 4);
  g.material.channel_names = {"R", "G", "B", "A"};
  g.specular_color = rgb(f.gbuffer[4], w, h);
  g.emission = rgb(f.gbuffer[5], w, h);
  g.depth = read_depth(f.gbuffer_depth, w, h);

  r.voxels.n = n;
  r.voxels.radiance = read_voxels(f, f.radiance, 0, n);
  if (f.bounce_input) r.bounce_input = read_voxels(f, f.bounce_input, 0, n);
  r.voxels.fragments = read_volume_uint(f.sums[3], n);
  r.voxels.fragments.channel_names = {"fragments"};
  double fragments = 0.0;
  int64_t covered = 0;
  for (float c : r.voxels.fragments.data) {
    fragments += double(c);
    covered += c > 0.0f;
  }
  r.info["fragments"] = std::to_string(int64_t(fragments));
  r.info["covered_voxels"] = std::to_string(covered);
  for (int l = 0, size = n; l < f.levels; ++l, size /= 2) r.mips.iso.push_back(read_voxels(f, f.radiance, l, size));
  if (f.s.anisotropic)
    for (size_t d = 0; d < 6; ++d)
      for (int l = 0, size = n / 2; l < f.levels - 1; ++l, size /= 2)
        r.mips.aniso[d].push_back(read_voxels(f, f.aniso[d], l, size));

  FrameImages& im = r.images;
  im.direct = rgb(f.direct, w, h);
  if (f.s.soft_shadows) im.soft_shadow = channel(read_image(f.soft_shadow, w, h, 1), 0, "Y");
  im.indirect_diffuse = rgb(f.shading[0], w, h);
  im.indirect_specular = rgb(f.shading[1], w, h);
  im.diffuse_term = rgb(f.shading[2], w, h);
  im.specular_term = rgb(f.shading[3], w, h);
  im.final_image = rgb(f.shading[4], w, h);
  im.emission = g.emission;
  im.particles = rgb(f.particles, w, h);
  check_gl("readback");
}

}  // namespace vct::gl
