// Textured materials and normal mapping in the G-buffer: GL's samplers (SRGB8_ALPHA8 decoded
// before filtering, the glTF min/mag filters and wrap modes, implicit LOD over the mip chain the
// CPU built) against ref/scene/texture_sample.h, on the demo room (brick base colour and normal
// maps) and on issue 13's tiled floor (a strongly minified checker and bump map), judged as
// `vct validate` judges them (docs/compare.md, "Texture LOD").
#include <cstdio>

#include "compare/isolated_stages.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "gl_test_util.h"
#include "scene/texture_sample.h"
#include "stages/gbuffer.h"
#include "freedoms/reference_frame.h"
#include "stages/uv_derivatives.h"
#include "stages/voxel_lod.h"

namespace vct::gl::test {
namespace {

const Scene& tiled_floor() {
  static const Scene scene =
      load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/tiled_floor.gltf");
  return scene;
}

const cmp::StageVerdict& verdict(const cmp::Report& r, const std::string& stage) {
  for (const auto& v : r.stages)
    if (v.stage == stage) return v;
  throw std::runtime_error("no stage " + stage);
}

// The report `vct validate` gives the GL frame (cone stages on its own inputs), with `fault`.
cmp::Report judge_tiled_floor(GlContext& ctx, const Settings& s, const FrameResult& ref,
                              const std::string& fault) {
  const FrameResult gl = render_gl_frame(ctx, tiled_floor(), s, {"", fault});
  const cmp::StageSet gl_set = cmp::stage_set_from_frame(gl, s.vct);
  cmp::Report rep = cmp::compare_stage_sets(cmp::stage_set_from_frame(ref, s.vct), gl_set);
  cmp::judge_cones_on_test_inputs(rep, tiled_floor(), gl, s.vct, gl_set);  // as validate does
  for (const char* st : {"gbuffer.normal", "gbuffer.albedo", "voxel.radiance"}) {
    const cmp::StageVerdict& v = verdict(rep, st);
    std::printf("  tiled floor%s%s: %s %s, %zu of %zu beyond the bound, worst %.3g (bound %.3g)\n",
                fault.empty() ? "" : " with ", fault.c_str(), st, to_string(v.verdict).c_str(),
                v.out_of_bound, v.checked, v.worst.empty() ? 0.0 : double(v.worst[0].error),
                v.worst.empty() ? 0.0 : double(v.worst[0].bound));
  }
  return rep;
}

}  // namespace

// The minified checker and bump map: GL's LOD (quad derivatives, its own rho) and the CPU's
// (exact derivatives) may pick different lambdas within the admissible range; the G-buffer's and
// the voxels' texture slack cover exactly that, so no stage fails. With the lookups forced to
// level 0 (the texture_level_zero fault) the G-buffer fails at once.
TEST(GlTextures, MinifiedTiledFloorAgreesWithinTheLodBoundAndLevelZeroFails) {
  VCT_REQUIRE_GL();
  const Settings s = small_settings(32, 64);
  const FrameResult ref = render_ref_frame(tiled_floor(), s);
  const cmp::Report ok = judge_tiled_floor(*ctx, s, ref, "");
  EXPECT_EQ(ok.first_failing(), "");
  for (const char* st : {"gbuffer.normal", "gbuffer.albedo", "voxel.radiance"})
    EXPECT_NE(verdict(ok, st).verdict, cmp::Verdict::Missing) << st;
  const cmp::Report bad = judge_tiled_floor(*ctx, s, ref, "texture_level_zero");
  EXPECT_EQ(bad.first_failing(), "gbuffer.normal");
  EXPECT_EQ(verdict(bad, "gbuffer.albedo").verdict, cmp::Verdict::Fail);
}

TEST(GlTextures, TexturedGBufferMatchesTheCpu) {
  VCT_REQUIRE_GL();
  const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/demo_room.gltf");
  ASSERT_FALSE(scene.textures.empty());
  const Settings s = small_settings(32, 96);
  const FrameResult g = render_gl_frame(*ctx, scene, s);
  const GBuffer r = render_gbuffer(scene, s.vct);
  size_t both = 0, coverage_mismatch = 0;
  double albedo_sum = 0.0, albedo_max = 0.0, normal_sum = 0.0, albedo_ref = 0.0;
  size_t albedo_over = 0;
  for (int y = 0; y < r.coverage.height; ++y)
    for (int x = 0; x < r.coverage.width; ++x) {
      const bool cg = g.gbuffer.coverage.at(x, y, 0) > 0.0f, cr = r.coverage.at(x, y, 0) > 0.0f;
      coverage_mismatch += cg != cr;
      if (!cg || !cr) continue;
      ++both;
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(double(g.gbuffer.albedo.at(x, y, c)) - double(r.albedo.at(x, y, c)));
        albedo_sum += d;
        albedo_ref += double(r.albedo.at(x, y, c));
        albedo_max = std::max(albedo_max, d);
        albedo_over += d > 4.0 / 255.0;
        normal_sum += std::abs(double(g.gbuffer.normal.at(x, y, c)) - double(r.normal.at(x, y, c)));
      }
    }
  std::printf("[gl vs ref] textured gbuffer: %zu pixels, coverage mismatches %zu, albedo mean %.3g max %.3g "
              "(> 4/255: %zu), normal mean %.3g\n",
              both, coverage_mismatch, albedo_sum / double(3 * both), albedo_max, albedo_over,
              normal_sum / double(3 * both));
  EXPECT_LE(coverage_mismatch, both / 200);  // silhouette ties of the statue only
  // Bilinear weights: llvmpipe filters sRGB-decoded texels with 8-bit fractional weights, the CPU
  // in float, so a texel step of contrast c differs by up to c/256; texture coordinates also differ
  // by interpolation rounding. Bound the mean tightly and the worst case loosely.
  EXPECT_LE(albedo_sum / albedo_ref, 5e-3);
  EXPECT_LE(albedo_over, both / 50);
  EXPECT_LE(normal_sum / double(3 * both), 5e-3);
}

namespace {

// A 2 m floor (y = 0) in a 2 m volume, u = S (x + 1) / 2, v = S (z + 1) / 2, an emissive texture
// of 256^2 whose mip levels are constant greys of known values (level k: 10 + 30 k), and nothing
// else emitting or lit: every voxel's radiance is the emissive lookup, a blend of two levels'
// constants, from which GL's lambda in the voxel raster can be read back exactly.
// `normal_axis` turns the plane so that its normal lies along that axis (1: the floor), which
// makes the voxel raster project it along that axis (window axes swapped for 0 and 2).
Scene level_marked_floor(float uv_scale, int normal_axis = 1) {
  Scene s;
  s.source = "test:level_marked_floor";
  const vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const auto place = [&](float a, float b) {
    if (normal_axis == 0) return vec3(0, a, b);
    if (normal_axis == 2) return vec3(a, b, 0);
    return vec3(a, 0, b);
  };
  for (const vec2& c : corners) {
    const vec3 p = place(c.x, c.y);
    s.positions.push_back(p);
    s.normals.push_back(place(0, 0) + vec3(normal_axis == 0, normal_axis == 1, normal_axis == 2));
    s.tangents.push_back(vec4(place(1, 0), 1));
    s.uv0.push_back(vec2(uv_scale * (c.x + 1.0f) / 2.0f, uv_scale * (c.y + 1.0f) / 2.0f));
    s.bounds.add(p);
  }
  s.triangles = {uvec3(0, 2, 1), uvec3(0, 3, 2)};
  s.triangle_material = {0, 0};
  Material m;
  m.base_color_factor = vec4(0, 0, 0, 1);
  m.metallic_factor = 0.0f;
  m.emissive_factor = vec3(1.0f);
  m.emissive_texture.texture = 0;
  s.materials.push_back(m);
  Texture t;
  t.width = t.height = 256;
  t.rgba8.assign(size_t(256) * 256 * 4, 10);
  for (int k = 1, size = 128; size >= 1; ++k, size /= 2)
    t.mips[1].push_back(TextureLevel{
        size, size, std::vector<uint8_t>(size_t(size) * size_t(size) * 4, uint8_t(10 + 30 * k))});
  s.textures.push_back(t);
  s.volume.origin = vec3(-1.0f);
  s.volume.size = 2.0f;
  s.volume.overridden = true;
  s.camera.position = vec3(0, 2, 2);
  s.camera.forward = glm::normalize(vec3(0, -1, -1));
  s.camera.up = glm::normalize(vec3(0, 1, -1));
  return s;
}

// The same level-marked texture on a 4 m plane facing the camera at z = -2 (u = S (x + 2) / 4):
// the G-buffer's emission is the lookup, from which GL's lambda in the camera pass reads back.
Scene level_marked_wall(float uv_scale) {
  Scene s = level_marked_floor(uv_scale);
  const vec3 corners[4] = {{-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}};
  s.bounds = Bounds3();
  for (int i = 0; i < 4; ++i) {
    s.positions[size_t(i)] = corners[i];
    s.normals[size_t(i)] = vec3(0, 0, 1);
    s.uv0[size_t(i)] =
        vec2(uv_scale * (corners[i].x + 2.0f) / 4.0f, uv_scale * (corners[i].y + 2.0f) / 4.0f);
    s.bounds.add(corners[i]);
  }
  s.triangles = {uvec3(0, 1, 2), uvec3(0, 2, 3)};
  s.volume = fit_volume(s.bounds);
  s.camera = Camera();
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  return s;
}

// What a correct GL may return for the level-marked texture at lambda in [lo, hi]: the lookups at
// both ends, with sRGB decoded per texel or after filtering (GL 4.5 §8.24), widened by one 8-bit
// blend-weight step of the two levels' difference and a binary16 half-ulp (voxel storage).
struct Admissible {
  double lo = 1e9, hi = -1e9;
};
Admissible admissible_emission(const Texture& t, const LodRange& range) {
  Admissible a;
  for (double l : {range.lo, range.hi})
    for (bool after : {false, true}) {
      const double v = sample_texture_lod(t, vec2(0.5f), true, l, after).r;
      a.lo = std::min(a.lo, v);
      a.hi = std::max(a.hi, v);
    }
  const int k = int(std::floor(range.lo));
  const double step =
      double(srgb8_to_linear(uint8_t(10 + 30 * (k + 2))) - srgb8_to_linear(uint8_t(10 + 30 * k))) /
      256.0;
  a.lo -= step + a.lo * std::ldexp(1.0, -11);
  a.hi += step + a.hi * std::ldexp(1.0, -11);
  return a;
}

// lambda = k + f read back from a value, assuming the level blend in linear light.
double lambda_if_linear(double value, int k) {
  const double c0 = srgb8_to_linear(uint8_t(10 + 30 * k)),
               c1 = srgb8_to_linear(uint8_t(10 + 30 * (k + 1)));
  return k + (value - c0) / (c1 - c0);
}

}  // namespace

// GL's lookup in the camera pass on a plane facing the camera (UV affine in the window: quad
// differences exact), read from the G-buffer's emission, against the values an admissible lambda
// and sRGB decode can give. llvmpipe decodes after filtering: blended in linear light its values
// would mean a lambda 0.025-0.036 below the exact one, beyond the LOD precision.
TEST(GlTextures, CameraLambdaOfAFacingPlane) {
  VCT_REQUIRE_GL();
  Settings s = small_settings(32, 32);
  for (float scale : {1.0f, 3.0f}) {
    const Scene scene = level_marked_wall(scale);
    const mat4 vp = scene.camera.projection(1.0f) * scene.camera.view();
    const double lambda = pixel_lods(scene, 0, ScreenBarycentrics(scene, 0, vp, 32, 32), 16, 16)
                              .exact.lambda[kSlotEmissive];
    ASSERT_NEAR(lambda, std::log2(256.0 * double(scale) * std::tan(0.5) / 32.0), 1e-5);
    const FrameResult gl = render_gl_frame(*ctx, scene, s);
    const LodRange range =
        pixel_lods(scene, 0, ScreenBarycentrics(scene, 0, vp, 32, 32), 16, 16).range[kSlotEmissive];
    const Admissible a = admissible_emission(scene.textures[0], range);
    double lo = 1e9, hi = -1e9;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        if (gl.gbuffer.coverage.at(x, y, 0) <= 0.0f) continue;
        lo = std::min(lo, double(gl.gbuffer.emission.at(x, y, 0)));
        hi = std::max(hi, double(gl.gbuffer.emission.at(x, y, 0)));
      }
    const int k = int(std::floor(lambda));
    std::printf(
        "  camera lambda %.4f: GL value %.5f..%.5f (lambda %.4f if blended in linear light), "
        "admissible %.5f..%.5f\n",
        lambda, lo, hi, lambda_if_linear(lo, k), a.lo, a.hi);
    EXPECT_GE(lo, a.lo);
    EXPECT_LE(hi, a.hi);
  }
}

// The same in the voxelization pass, against the CPU's lambda (stages/voxel_lod.h: texels per
// voxel step of the dominant-axis projection).
TEST(GlTextures, VoxelizationLambdaIsTheVoxelGridsFootprint) {
  VCT_REQUIRE_GL();
  Settings s = small_settings(32, 32);
  // 1.0826: lambda 3.114, a brick wall of scenes/atrium.gltf at grid 32; on every dominant axis.
  for (const auto& [scale, axis] : {std::pair{0.6f, 1}, {1.7f, 1}, {1.0826f, 0}, {1.0826f, 1}, {1.0826f, 2}}) {
    const Scene scene = level_marked_floor(scale, axis);
    const double lambda = voxel_lods(scene, 0, s.vct.grid).exact.lambda[kSlotEmissive];
    ASSERT_NEAR(lambda, std::log2(256.0 * double(scale) / 32.0), 1e-6);
    const FrameResult gl = render_gl_frame(*ctx, scene, s);
    const Admissible a = admissible_emission(scene.textures[0],
                                             voxel_lods(scene, 0, s.vct.grid).range[kSlotEmissive]);
    double lo = 1e9, hi = -1e9;
    const Volume& v = gl.voxels.radiance;
    for (size_t i = 0; i < v.voxel_count(); ++i) {
      if (v.data[i * 4 + 3] <= 0.0f) continue;
      lo = std::min(lo, double(v.data[i * 4]));
      hi = std::max(hi, double(v.data[i * 4]));
    }
    const int k = int(std::floor(lambda));
    std::printf(
        "  axis %d, voxel raster lambda %.4f: GL value %.5f..%.5f (lambda %.4f if blended in linear light), "
        "admissible %.5f..%.5f\n",
        axis, lambda, lo, hi, lambda_if_linear(lo, k), a.lo, a.hi);
    EXPECT_GE(lo, a.lo);
    EXPECT_LE(hi, a.hi);
  }
}

}  // namespace vct::gl::test
