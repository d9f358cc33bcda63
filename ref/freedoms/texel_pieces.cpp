#include "freedoms/texel_pieces.h"

#include <vector>

#include "freedoms/lod_candidates.h"
#include "freedoms/texel_breakpoints.h"
#include "stages/raster.h"  // kVertexSnapStep

namespace vct {

namespace {

constexpr size_t kPieceCap = 512;  // points; beyond it the grid (fragment_slack.cpp's kBreakpointCap)

// The maps from window offsets to texel coordinates of every NEAREST level the material's lookups
// may read; p0, pu, pv the surface at the centre and one step along each window axis (texture
// coordinates are affine in the window over a step: the perspective's curvature across 2^-7 pixel
// is far below a texel piece's 1/64 inset).
std::vector<TexelMap> nearest_maps(const Scene& scene, const Material& m, const SurfacePoint& p0, const SurfacePoint& pu,
                                   const SurfacePoint& pv, const SurfaceLods& lods) {
  std::vector<TexelMap> maps;
  constexpr double s = kVertexSnapStep;
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    const TextureRef* ref = slot_texture(m, slot);
    if (!ref) continue;
    const glm::dvec2 uv(slot_uv(*ref, p0));
    const glm::dvec2 per_u = (glm::dvec2(slot_uv(*ref, pu)) - uv) / s, per_v = (glm::dvec2(slot_uv(*ref, pv)) - uv) / s;
    double cand[kMaxLodCandidates];
    const int count = lod_candidates(lods.range[slot], cand);
    for (int j = 0; j < count; ++j)
      append_nearest_level_maps(scene.textures[size_t(ref->texture)], slot_is_srgb(slot), cand[j], uv, per_u, per_v,
                                maps);
  }
  return maps;
}

// Whether any of the material's textures filters NEAREST within a level, minified or magnified:
// only those change texel in steps (a LINEAR lookup is continuous, its corners bound it).
bool reads_nearest(const Scene& scene, const Material& m) {
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    const TextureRef* ref = slot_texture(m, slot);
    if (!ref) continue;
    const Texture& t = scene.textures[size_t(ref->texture)];
    if (t.mag_filter == Filter::Nearest || t.min_filter == MinFilter::Nearest ||
        t.min_filter == MinFilter::NearestMipmapNearest || t.min_filter == MinFilter::NearestMipmapLinear)
      return true;
  }
  return false;
}

}  // namespace

void texel_piece_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                        const vec3& bary, const SurfaceLods& lods, std::vector<SurfacePoint>& out) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  if (!reads_nearest(scene, m)) return;
  constexpr double s = kVertexSnapStep;
  const double cx = double(x) + 0.5, cy = double(wb.height()) - double(row) - 0.5;
  glm::dvec2 bc, bu, bv;
  if (!wb.at(scene, triangle, cx, cy, bc) || !wb.at(scene, triangle, cx + s, cy, bu) ||
      !wb.at(scene, triangle, cx, cy + s, bv))
    return;
  const auto point = [&](const glm::dvec2& b) {
    return interpolate_surface(scene, triangle, bary.y + float(b.x - bc.x), bary.z + float(b.y - bc.y));
  };
  std::vector<glm::dvec2> offsets;
  for (const TexelMap& map : nearest_maps(scene, m, point(bc), point(bu), point(bv), lods)) {
    if (texel_breakpoints(map, s, kPieceCap, offsets)) continue;
    constexpr int kGrid = 16;
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; j <= kGrid; ++j) offsets.push_back({s * (2.0 * i / kGrid - 1.0), s * (2.0 * j / kGrid - 1.0)});
  }
  for (const glm::dvec2& o : offsets) {
    glm::dvec2 b;
    if (wb.at(scene, triangle, cx + o.x, cy + o.y, b)) out.push_back(point(b));
  }
}

int snap_surface_points(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                        const vec3& bary, const SurfaceLods& lods, std::vector<SurfacePoint>& out) {
  SurfacePoint shifted[kSlackShifts];
  const int n = shifted_surface_points(scene, wb, x, row, triangle, bary, shifted);
  out.assign(shifted, shifted + n);
  texel_piece_points(scene, wb, x, row, triangle, bary, lods, out);
  return n;
}

}  // namespace vct
