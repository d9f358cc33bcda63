// An engine that writes its final image tone-mapped and quantised (issue 21: Reinhard, gamma 2.2,
// 8 bits, the source design's): our GL frame post-processed that way, judged against the CPU
// reference. Declared (manifest conventions.display), image.final is judged in display space and
// passes; undeclared it fails; a real fault under the declared transform (indirect light x1.3)
// still fails.
#include <cstdio>

#include "compare/stage_compare.h"
#include "gl_test_util.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {
namespace {

struct Frames {
  Settings s;
  FrameResult gl, ref;
};

const Frames* frames() {
  static std::unique_ptr<Frames> f;
  GlContext* ctx = shared_context();
  if (!ctx) return nullptr;
  if (!f) {
    f = std::make_unique<Frames>();
    f->s = small_settings(32, 64);
    f->gl = render_gl_frame(*ctx, cornell_box(), f->s);
    f->ref = render_ref_frame(cornell_box(), f->s);
  }
  return f.get();
}

cmp::DisplayTransform engine_transform() {
  cmp::DisplayTransform d;
  d.op = cmp::ToneOperator::Reinhard;
  d.gamma = 2.2;
  d.bits = 8;
  return d;
}

// GL's stage set with image.final = encode(final + (indirect_scale - 1) (diffuse + specular
// terms)), as an engine's 8-bit output would hold it.
cmp::StageSet engine_set(const Frames& f, float indirect_scale, bool declare) {
  cmp::StageSet set = cmp::stage_set_from_frame(f.gl, f.s.vct);
  const FrameImages& im = f.gl.images;
  Image out = im.final_image;
  const cmp::DisplayTransform d = engine_transform();
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < std::min(out.channels, 3); ++c) {
        const float extra = (indirect_scale - 1.0f) * (im.diffuse_term.at(x, y, c) + im.specular_term.at(x, y, c));
        out.at(x, y, c) = float(d.encode(double(out.at(x, y, c) + extra)));
      }
  set.images["image.final"] = out;
  if (declare) set.conventions.display = d;
  return set;
}

cmp::StageVerdict final_verdict(const Frames& f, const cmp::StageSet& engine) {
  const cmp::Report r = cmp::compare_stage_sets(cmp::stage_set_from_frame(f.ref, f.s.vct), engine);
  for (const cmp::StageVerdict& v : r.stages)
    if (v.stage == "image.final") {
      std::printf("[display] %s: %s, %s (max |d| %.4g)\n", v.stage.c_str(), to_string(v.verdict).c_str(),
                  v.note.c_str(), v.max_abs);
      return v;
    }
  ADD_FAILURE() << "no image.final verdict";
  return {};
}

}  // namespace

// Hand values of the transform and its bound: tests/compare/display_transform_test.cpp.
TEST(GlDisplayTransform, DeclaredToneMappedFinalPasses) {
  const Frames* f = frames();
  if (!f) GTEST_SKIP() << "no OpenGL 4.5 context";
  const cmp::StageVerdict v = final_verdict(*f, engine_set(*f, 1.0f, true));
  EXPECT_NE(v.verdict, cmp::Verdict::Fail) << v.note;
  EXPECT_TRUE(v.extra.contains("display_transform"));
}

TEST(GlDisplayTransform, UndeclaredToneMappedFinalFails) {
  const Frames* f = frames();
  if (!f) GTEST_SKIP() << "no OpenGL 4.5 context";
  EXPECT_EQ(final_verdict(*f, engine_set(*f, 1.0f, false)).verdict, cmp::Verdict::Fail);
}

TEST(GlDisplayTransform, IndirectTimesOnePointThreeUnderTheDeclaredTransformFails) {
  const Frames* f = frames();
  if (!f) GTEST_SKIP() << "no OpenGL 4.5 context";
  EXPECT_EQ(final_verdict(*f, engine_set(*f, 1.3f, true)).verdict, cmp::Verdict::Fail);
}

}  // namespace vct::gl::test
