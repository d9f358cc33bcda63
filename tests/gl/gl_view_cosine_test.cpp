// n_dot_v = abs (issue 39: the source design's |n.v|) on GL against the reference re-shaded on GL's
// own G-buffer and shadow maps (compare/isolated_stages.h): direct.frag passes the mode to the
// shared cook_torrance_nv (sh::view_cosine), so the two agree as the default does, and the
// convention must matter on the scene (smooth spheres whose interpolated normals face away from
// the camera at their silhouettes), or the test could not tell GL ignoring it.
#include <cmath>
#include <cstdio>

#include "compare/isolated_stages.h"
#include "gl_test_util.h"

namespace vct::gl::test {
namespace {

double l1(const Image& a, const Image& b) {
  double d = 0.0;
  for (size_t i = 0; i < a.data.size(); ++i) d += std::abs(double(a.data[i]) - double(b.data[i]));
  return d;
}

double total(const Image& a) {
  double t = 0.0;
  for (float v : a.data) t += std::abs(double(v));
  return t;
}

TEST(GlViewCosine, AbsMatchesTheReferenceOnGlsOwnInputs) {
  VCT_REQUIRE_GL();
  const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/material_room.gltf");
  Settings s = small_settings(32, 64);
  s.vct.n_dot_v = NdotV::Abs;
  const FrameResult g = render_gl_frame(*ctx, scene, s);
  const FrameResult ref_abs = cmp::reference_on_test_inputs(scene, g, s.vct);
  Settings zero = s;
  zero.vct.n_dot_v = NdotV::Zero;
  const FrameResult ref_zero = cmp::reference_on_test_inputs(scene, g, zero.vct);
  const double gl_vs_ref = l1(g.images.direct, ref_abs.images.direct);
  const double convention = l1(ref_zero.images.direct, ref_abs.images.direct);
  const double all = total(ref_abs.images.direct);
  std::printf("[gl vs ref] n_dot_v abs: |gl - ref| %.4g, |zero - abs| (ref) %.4g, total %.4g\n", gl_vs_ref, convention,
              all);
  ASSERT_GT(all, 0.0);
  EXPECT_GT(convention, 10.0 * gl_vs_ref) << "abs and zero differ too little here to tell GL ignoring the mode";
  EXPECT_LE(gl_vs_ref, 0.01 * all);
}

}  // namespace
}  // namespace vct::gl::test
