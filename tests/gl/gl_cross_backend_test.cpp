// Stage by stage, the GL frame against the CPU reference on the Cornell box (32^3, 64^2, 256^2
// shadow maps, 4x MSAA, fixed-point reduction): exact where both follow the same arithmetic,
// bounded where the GL specification leaves freedom (docs/gl_backend.md, "Cross-backend tests").
#include <cstdio>

#include "gl_test_util.h"
#include "stages/mips.h"
#include "stages/reduction.h"
#include "freedoms/reference_frame.h"
#include "stages/indirect_pass.h"

namespace vct::gl::test {
namespace {

struct Frames {
  FrameResult gl, ref;
};

const Frames* frames() {
  static std::unique_ptr<Frames> f;
  GlContext* ctx = shared_context();
  if (!ctx) return nullptr;
  if (!f) {
    f = std::make_unique<Frames>();
    const Settings s = small_settings();
    f->gl = render_gl_frame(*ctx, cornell_box(), s);
    f->ref = render_ref_frame(cornell_box(), s);
  }
  return f.get();
}

#define VCT_FRAMES()                                   \
  const Frames* fr = frames();                         \
  if (!fr) GTEST_SKIP() << "no OpenGL 4.5 context"

// Pixels both backends cover (G-buffer coverage), so rasterization edge ties don't mix in.
bool both_cover(const Frames& f, int x, int y) {
  return f.gl.gbuffer.coverage.at(x, y, 0) > 0.0f && f.ref.gbuffer.coverage.at(x, y, 0) > 0.0f;
}

struct Stats {
  double max = 0.0, sum = 0.0, ref_sum = 0.0;
  size_t n = 0, over = 0;
  double mean() const { return n ? sum / double(n) : 0.0; }
  double ref_mean() const { return n ? ref_sum / double(n) : 0.0; }
};

Stats image_stats(const Frames& f, const Image& gl, const Image& ref, float tol) {
  Stats s;
  for (int y = 0; y < gl.height; ++y)
    for (int x = 0; x < gl.width; ++x) {
      if (!both_cover(f, x, y)) continue;
      for (int c = 0; c < gl.channels; ++c) {
        const double d = std::abs(double(gl.at(x, y, c)) - double(ref.at(x, y, c)));
        s.max = std::max(s.max, d);
        s.sum += d;
        s.ref_sum += std::abs(double(ref.at(x, y, c)));
        s.over += d > double(tol);
        ++s.n;
      }
    }
  return s;
}

void print(const char* what, const Stats& s) {
  std::printf("[gl vs ref] %-18s max %.3g mean %.3g (ref mean %.3g) over-tol %zu / %zu\n", what, s.max, s.mean(),
              s.ref_mean(), s.over, s.n);
}

// The Cornell box without its spot light, every wall emitting a scaled copy of its albedo: each
// fragment's value is then a material constant, bit-identical on both sides.
const Scene& emission_only_box() {
  static const Scene scene = [] {
    Scene s = cornell_box();
    s.lights.clear();
    for (Material& m : s.materials)
      if (!m.is_emissive()) m.emissive_factor = vec3(m.base_color_factor) * 0.37f;
    return s;
  }();
  return scene;
}

}  // namespace

TEST(GlCrossBackend, ShadowMapDepth) {
  VCT_FRAMES();
  ASSERT_EQ(fr->gl.shadow_maps.size(), fr->ref.shadow_maps.size());
  for (size_t i = 0; i < fr->gl.shadow_maps.size(); ++i) {
    const Image &g = fr->gl.shadow_maps[i].depth, &r = fr->ref.shadow_maps[i].depth;
    ASSERT_EQ(g.width, r.width);
    EXPECT_EQ(fr->gl.shadow_maps[i].view_proj, fr->ref.shadow_maps[i].view_proj);
    size_t covered_mismatch = 0, both = 0;
    float max_d = 0.0f;
    for (size_t k = 0; k < g.data.size(); ++k) {
      const bool cg = g.data[k] < 1.0f, cr = r.data[k] < 1.0f;
      if (cg != cr) {
        ++covered_mismatch;
        continue;
      }
      if (!cg) continue;
      ++both;
      max_d = std::max(max_d, std::abs(g.data[k] - r.data[k]));
    }
    std::printf("[gl vs ref] shadow map %zu: max depth diff %.3g over %zu texels, coverage mismatches %zu\n", i,
                double(max_d), both, covered_mismatch);
    // llvmpipe evaluates depth from a float plane equation (z0 + dzdx*x + dzdy*y) while the CPU
    // interpolates z_ndc per sample; with 256 texels of gradient terms the rounding reaches a few
    // 1e-5 (measured 1.8e-5 on Mesa 22.3). Bound: 2^-14.
    EXPECT_LE(max_d, 1.0f / 16384.0f);
    // Fill-rule ties on shared edges and the scene's silhouette: a handful of texels at most.
    EXPECT_LE(covered_mismatch, g.data.size() / 1000);
    EXPECT_GT(both, g.data.size() / 10);
  }
}

TEST(GlCrossBackend, GBuffer) {
  VCT_FRAMES();
  const GBuffer &g = fr->gl.gbuffer, &r = fr->ref.gbuffer;
  size_t coverage_mismatch = 0;
  for (size_t k = 0; k < g.coverage.data.size(); ++k) coverage_mismatch += g.coverage.data[k] != r.coverage.data[k];
  std::printf("[gl vs ref] gbuffer coverage mismatches %zu\n", coverage_mismatch);
  EXPECT_EQ(coverage_mismatch, 0u);  // the Cornell box fills the view: no silhouettes to tie on
  const Stats pos = image_stats(*fr, g.position, r.position, 1e-4f);
  const Stats nrm = image_stats(*fr, g.normal, r.normal, 1e-3f);
  const Stats alb = image_stats(*fr, g.albedo, r.albedo, 1e-5f);
  const Stats mat = image_stats(*fr, g.material, r.material, 1e-5f);
  const Stats dep = image_stats(*fr, g.depth, r.depth, 1e-5f);
  print("gbuffer position", pos);
  print("gbuffer normal", nrm);
  print("gbuffer albedo", alb);
  print("gbuffer material", mat);
  print("gbuffer depth", dep);
  // Positions: perspective-correct float interpolation on both sides with different rounding
  // (llvmpipe: plane equations of attribute/w; CPU: exact barycentrics); a few 1e-4 in a scene a
  // few units wide. Material factors without textures are constants: exact.
  EXPECT_LE(pos.max, 2e-3);
  EXPECT_LE(pos.mean(), 1e-4);
  EXPECT_LE(nrm.max, 1e-2);
  EXPECT_EQ(alb.max, 0.0);
  EXPECT_EQ(mat.max, 0.0);
  EXPECT_LE(dep.max, 1e-5);
}

TEST(GlCrossBackend, DirectLight) {
  VCT_FRAMES();
  const Stats s = image_stats(*fr, fr->gl.images.direct, fr->ref.images.direct, 1e-3f);
  print("direct", s);
  // Same shared BRDF and falloff; positions and normals differ by float rounding, and PCF taps
  // can flip where a point's depth is within that rounding of the stored depth (shadow edges).
  EXPECT_LE(s.mean(), 0.01 * s.ref_mean());
  EXPECT_LE(s.over, s.n / 50);
}

TEST(GlCrossBackend, VoxelOccupancyUnderTheSameMsaaRule) {
  VCT_FRAMES();
  // Same rule on both sides (dominant axis from world positions, standard 4x sample pattern,
  // top-left fill rule, one fragment per covered pixel, depth = floor of the voxel-space
  // coordinate interpolated at the pixel centre). Coverage matches exactly; the depth index can
  // differ where the interpolated coordinate lies within rounding of a voxel boundary (llvmpipe's
  // barycentrics are not the CPU's exact ones): such a fragment moves to the neighbouring voxel
  // along the axis, so the total is unchanged and every mismatch has a mismatched neighbour.
  const Volume &g = fr->gl.voxels.fragments, &r = fr->ref.voxels.fragments;
  ASSERT_EQ(g.data.size(), r.data.size());
  const int n = g.nx;
  double total_g = 0.0, total_r = 0.0;
  size_t occ_mismatch = 0, count_mismatch = 0, occupied = 0, lonely = 0;
  auto differs = [&](int x, int y, int z) {
    return g.contains(x, y, z) && *g.voxel(x, y, z) != *r.voxel(x, y, z);
  };
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float a = *g.voxel(x, y, z), b = *r.voxel(x, y, z);
        total_g += double(a);
        total_r += double(b);
        occupied += b > 0.0f;
        occ_mismatch += (a > 0.0f) != (b > 0.0f);
        if (a == b) continue;
        ++count_mismatch;
        if (!(differs(x - 1, y, z) || differs(x + 1, y, z) || differs(x, y - 1, z) || differs(x, y + 1, z) ||
              differs(x, y, z - 1) || differs(x, y, z + 1)))
          ++lonely;
      }
  std::printf("[gl vs ref] voxels: occupied %zu, fragments gl %.0f ref %.0f, occupancy mismatches %zu, "
              "fragment-count mismatches %zu (without a mismatched neighbour: %zu)\n",
              occupied, total_g, total_r, occ_mismatch, count_mismatch, lonely);
  EXPECT_GT(occupied, 1000u);
  EXPECT_EQ(total_g, total_r);  // coverage: exactly the same fragments
  EXPECT_EQ(lonely, 0u);        // only depth-tie moves between neighbours
  EXPECT_LE(occ_mismatch, occupied / 100);
}

TEST(GlCrossBackend, FixedPointRadianceBounded) {
  VCT_FRAMES();
  // Lit scene: per-fragment light differs by float rounding of positions and by PCF taps at
  // shadow edges, so only a bound; voxels whose fragment sets differ (depth ties) are skipped.
  const Volume &g = fr->gl.voxels.radiance, &r = fr->ref.voxels.radiance;
  size_t exact = 0, compared = 0;
  double sum_d = 0.0, sum_r = 0.0;
  for (size_t k = 0; k < g.voxel_count(); ++k) {
    if (r.data[k * 4 + 3] == 0.0f || fr->gl.voxels.fragments.data[k] != fr->ref.voxels.fragments.data[k]) continue;
    ++compared;
    bool same = true;
    for (size_t c = 0; c < 4; ++c) {
      same = same && g.data[k * 4 + c] == r.data[k * 4 + c];
      sum_d += std::abs(double(g.data[k * 4 + c]) - double(r.data[k * 4 + c]));
      sum_r += std::abs(double(r.data[k * 4 + c]));
    }
    exact += same;
  }
  std::printf("[gl vs ref] fixed-point voxels (lit): %zu of %zu bit-identical, relative L1 diff %.3g\n", exact,
              compared, sum_d / sum_r);
  EXPECT_GE(double(exact), 0.8 * double(compared));
  EXPECT_LE(sum_d / sum_r, 1e-3);
}

TEST(GlCrossBackend, FixedPointRadianceExactWhenFragmentValuesAgree) {
  GlContext* ctx = shared_context();
  if (!ctx) GTEST_SKIP() << "no OpenGL 4.5 context";
  // No spot lights: every fragment carries its material's emission, the same float on both
  // sides, so the shared fixed-point encode / integer sum / resolve must agree bit for bit
  // (including the RGBA16F store: the resolve rounds to nearest even itself, see half_round.glsl).
  const Scene& scene = emission_only_box();
  const Settings s = small_settings();
  const FrameResult g = render_gl_frame(*ctx, scene, s);
  const FrameResult r = render_ref_frame(scene, s);
  size_t compared = 0, exact = 0;
  for (size_t k = 0; k < g.voxels.radiance.voxel_count(); ++k) {
    if (g.voxels.fragments.data[k] != r.voxels.fragments.data[k] || r.voxels.fragments.data[k] == 0.0f) continue;
    ++compared;
    bool same = true;
    for (size_t c = 0; c < 4; ++c) same = same && g.voxels.radiance.data[k * 4 + c] == r.voxels.radiance.data[k * 4 + c];
    exact += same;
    if (!same && std::getenv("VCT_GL_DEBUG") && compared - exact < 6)
      std::printf("  voxel %zu frags %g: gl %.9g %.9g %.9g ref %.9g %.9g %.9g\n", k, double(r.voxels.fragments.data[k]),
                  double(g.voxels.radiance.data[k * 4]), double(g.voxels.radiance.data[k * 4 + 1]),
                  double(g.voxels.radiance.data[k * 4 + 2]), double(r.voxels.radiance.data[k * 4]),
                  double(r.voxels.radiance.data[k * 4 + 1]), double(r.voxels.radiance.data[k * 4 + 2]));
  }
  std::printf("[gl vs ref] fixed-point voxels (emission only): %zu of %zu bit-identical\n", exact, compared);
  EXPECT_GT(compared, 1000u);
  EXPECT_EQ(exact, compared);
}

// Share of voxels (same fragment set on both sides) whose GL CAS value lies inside the CPU's
// interval of all fragment orders: exactly, and with `slack`.
std::pair<double, double> cas_inside(const Scene& scene, float slack) {
  Settings s = small_settings();
  s.vct.reduction = Reduction::CasRgba8;
  s.vct.storage = VoxelStorage::Rgba8;
  const FrameResult g = render_gl_frame(*shared_context(), scene, s);
  const FrameResult r = render_ref_frame(scene, s);
  EXPECT_FALSE(r.voxels.cas_lo.data.empty());
  size_t compared = 0, inside = 0, inside_slack = 0;
  for (size_t k = 0; k < g.voxels.radiance.voxel_count(); ++k) {
    if (g.voxels.fragments.data[k] != r.voxels.fragments.data[k] || r.voxels.fragments.data[k] == 0.0f) continue;
    ++compared;
    bool in = true, in_slack = true;
    for (size_t c = 0; c < 3; ++c) {
      const float v = g.voxels.radiance.data[k * 4 + c];
      const float lo = r.voxels.cas_lo.data[k * 4 + c], hi = r.voxels.cas_hi.data[k * 4 + c];
      in = in && v >= lo - 1e-6f && v <= hi + 1e-6f;
      in_slack = in_slack && v >= lo - slack - 1e-6f && v <= hi + slack + 1e-6f;
    }
    inside += in;
    inside_slack += in_slack;
  }
  EXPECT_GT(compared, 1000u);
  std::printf("[gl vs ref] CAS RGBA8 voxels (%s): %zu of %zu inside the CPU interval, %zu within %.3g of it\n",
              scene.lights.empty() ? "emission only" : "lit", inside, compared, inside_slack, double(slack));
  return {double(inside) / double(compared), double(inside_slack) / double(compared)};
}

TEST(GlCrossBackend, CasRgba8WithinTheCpuInterval) {
  if (!shared_context()) GTEST_SKIP() << "no OpenGL 4.5 context";
  // Same fragment values (emission only): the GPU's order is one of those the interval covers.
  EXPECT_EQ(cas_inside(emission_only_box(), 0.0f).first, 1.0);
  // Lit: fragment values differ by rounding and by PCF taps at shadow edges; a voxel whose
  // fragments straddle a shadow edge can leave the interval, so only a share is asserted.
  const auto lit = cas_inside(cornell_box(), 1.0f / 255.0f);
  EXPECT_GE(lit.first, 0.99);
  EXPECT_GE(lit.second, 0.995);
}

// One reduction step at a time: the CPU's filter applied to GL's stored level l-1, rounded to
// RGBA16F like GL's store (round to nearest even, half_round.glsl), against GL's level l.
// Same summation order on both sides, so each step is bit-identical (measured on llvmpipe; a GPU
// contracting to FMA could differ by one half step).
double worst_step(const Volume& cpu_step, const Volume& gl_level) {
  double worst = 0.0;
  for (size_t k = 0; k < cpu_step.data.size(); ++k) {
    const double a = double(quantize_half(cpu_step.data[k])), b = double(gl_level.data[k]);
    worst = std::max(worst, std::abs(a - b) / std::max(1e-3, std::abs(a)));
  }
  return worst;
}

TEST(GlCrossBackend, Mips) {
  VCT_FRAMES();
  const auto& iso = fr->gl.mips.iso;
  ASSERT_EQ(iso.size(), 6u);
  for (size_t l = 1; l < iso.size(); ++l) {
    const double worst = worst_step(downsample_iso(iso[l - 1]), iso[l]);
    std::printf("[gl vs ref] iso mip %zu: worst relative diff %.3g\n", l, worst);
    EXPECT_EQ(worst, 0.0);
  }
}

TEST(GlCrossBackend, AnisotropicMips) {
  GlContext* ctx = shared_context();
  if (!ctx) GTEST_SKIP() << "no OpenGL 4.5 context";
  Settings s = small_settings();
  s.vct.anisotropic = true;
  const FrameResult g = render_gl_frame(*ctx, cornell_box(), s);
  for (int d = 0; d < 6; ++d) {
    const auto& chain = g.mips.aniso[size_t(d)];
    ASSERT_EQ(chain.size(), 5u);
    double worst = 0.0;
    for (size_t l = 0; l < chain.size(); ++l)
      worst = std::max(worst, worst_step(downsample_aniso(l == 0 ? g.mips.iso[0] : chain[l - 1], d), chain[l]));
    std::printf("[gl vs ref] aniso %s: worst relative diff %.3g\n", kAnisoDirNames[size_t(d)], worst);
    EXPECT_EQ(worst, 0.0);
  }
}

TEST(GlCrossBackend, ConeTracingOnTheSameInputs) {
  VCT_FRAMES();
  // The cone mechanism alone: the CPU's marcher (GL-spec sampler) on GL's own G-buffer and mips
  // against GL's textureLod marcher. Differences come from llvmpipe's filtering arithmetic (its
  // LOD and weights) and from the loop's float rounding.
  const IndirectImages cpu = trace_indirect(cornell_box(), fr->gl.gbuffer, fr->gl.mips, small_settings().vct);
  const Stats d = image_stats(*fr, fr->gl.images.indirect_diffuse, cpu.diffuse, 1e-3f);
  const Stats sp = image_stats(*fr, fr->gl.images.indirect_specular, cpu.specular, 1e-3f);
  print("cones diffuse", d);
  print("cones specular", sp);
  EXPECT_LE(d.mean(), 0.01 * d.ref_mean());
  EXPECT_LE(sp.mean(), 0.02 * sp.ref_mean());
}

TEST(GlCrossBackend, FinalImageBounded) {
  VCT_FRAMES();
  const FrameImages &g = fr->gl.images, &r = fr->ref.images;
  const Stats d = image_stats(*fr, g.indirect_diffuse, r.indirect_diffuse, 1e-2f);
  const Stats sp = image_stats(*fr, g.indirect_specular, r.indirect_specular, 1e-2f);
  const Stats fin = image_stats(*fr, g.final_image, r.final_image, 1e-2f);
  print("indirect diffuse", d);
  print("indirect specular", sp);
  print("final", fin);
  EXPECT_LE(d.mean(), 0.05 * d.ref_mean());
  EXPECT_LE(fin.mean(), 0.05 * fin.ref_mean());
}

}  // namespace vct::gl::test

namespace vct::gl::test {

TEST(GlCrossBackend, FixedPointRgba8StorageExact) {
  if (!shared_context()) GTEST_SKIP() << "no OpenGL 4.5 context";
  Settings s = small_settings();
  s.vct.storage = VoxelStorage::Rgba8;
  const FrameResult g = render_gl_frame(*shared_context(), emission_only_box(), s);
  const FrameResult r = render_ref_frame(emission_only_box(), s);
  size_t compared = 0, exact = 0;
  for (size_t k = 0; k < g.voxels.radiance.voxel_count(); ++k) {
    if (g.voxels.fragments.data[k] != r.voxels.fragments.data[k] || r.voxels.fragments.data[k] == 0.0f) continue;
    ++compared;
    bool same = true;
    for (size_t c = 0; c < 4; ++c) same = same && g.voxels.radiance.data[k * 4 + c] == r.voxels.radiance.data[k * 4 + c];
    exact += same;
    if (!same && std::getenv("VCT_GL_DEBUG") && compared - exact < 5)
      std::printf("  voxel %zu: gl %.9g %.9g %.9g %.9g ref %.9g %.9g %.9g %.9g\n", k, double(g.voxels.radiance.data[k * 4]),
                  double(g.voxels.radiance.data[k * 4 + 1]), double(g.voxels.radiance.data[k * 4 + 2]),
                  double(g.voxels.radiance.data[k * 4 + 3]), double(r.voxels.radiance.data[k * 4]),
                  double(r.voxels.radiance.data[k * 4 + 1]), double(r.voxels.radiance.data[k * 4 + 2]),
                  double(r.voxels.radiance.data[k * 4 + 3]));
  }
  std::printf("[gl vs ref] fixed-point RGBA8 voxels (emission only): %zu of %zu bit-identical\n", exact, compared);
  EXPECT_GT(compared, 1000u);
  EXPECT_EQ(exact, compared);
}

}  // namespace vct::gl::test

namespace vct::gl::test {

// Random cone rotation (hash of pixel column, row from the top, frame) and anisotropic voxels:
// the CPU marcher on GL's G-buffer and mips must see the same rotation per pixel.
TEST(GlCrossBackend, RotatedAnisotropicConesOnTheSameInputs) {
  if (!shared_context()) GTEST_SKIP() << "no OpenGL 4.5 context";
  Settings s = small_settings();
  s.vct.random_rotation = true;
  s.vct.frame = 7;
  s.vct.anisotropic = true;
  s.vct.light_model = LightModel::Seed;
  const FrameResult g = render_gl_frame(*shared_context(), cornell_box(), s);
  const IndirectImages cpu = trace_indirect(cornell_box(), g.gbuffer, g.mips, s.vct);
  double diff = 0.0, total = 0.0, worst = 0.0;
  for (size_t k = 0; k < cpu.diffuse.data.size(); ++k) {
    const double d = std::abs(double(g.images.indirect_diffuse.data[k]) - double(cpu.diffuse.data[k]));
    diff += d;
    worst = std::max(worst, d);
    total += double(cpu.diffuse.data[k]);
  }
  std::printf("[gl vs ref] rotated aniso diffuse cones: relative L1 %.3g, max %.3g\n", diff / total, worst);
  EXPECT_GT(total, 1.0);
  EXPECT_LE(diff / total, 1e-4);
}

}  // namespace vct::gl::test
