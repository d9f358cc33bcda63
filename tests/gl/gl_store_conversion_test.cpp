// What this driver's imageStore does with a float between two values of the image's format, and
// that the GL backend's pinned store values land on the reference's values whatever it does.
// GL leaves the rounding of float -> unorm8 (GL 4.5 §2.3.5.1: either of the two closest values,
// nearest preferred) and float -> half (§2.3.4.2) conversions to the implementation, so
// the GL backend rounds first and stores a value either conversion maps to the same result
// (gl/shaders/half_round.glsl; docs/gl_backend.md, "Formats and conventions"). The docs once said
// llvmpipe truncates both (issue 34 item 4): this measures it, and the test fails if a driver's
// store is neither of GL's two admissible results or the pinned values ever miss.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl/gl_program.h"
#include "gl_test_util.h"
#include "stages/reduction.h"

namespace vct::gl::test {

namespace {
// Stores `in` (as read from an SSBO) into a 1-row image of `format`, raw (`pinned` false) or
// through half_round.glsl's storage_value (`pinned` true), and reads the image back as floats.
std::vector<float> store_and_read(const std::vector<float>& in, GLenum internal, const char* layout, int format,
                                  bool pinned) {
  const std::string src = std::string("#version 450\n") + embedded_files().at("half_round.glsl") +
                          "\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) readonly buffer In { float v[]; };\n"
                          "layout(" + layout + ", binding = 0) writeonly uniform image2D img;\n"
                          "uniform int u_pinned;\nuniform int u_format;\n"
                          "void main() {\n  int i = int(gl_GlobalInvocationID.x);\n  vec4 x = vec4(v[i]);\n"
                          "  imageStore(img, ivec2(i, 0), u_pinned != 0 ? storage_value(x, u_format) : x);\n}\n";
  Program p({ShaderSource{GL_COMPUTE_SHADER, "store_conversion.comp", src}});
  const GLsizei n = GLsizei(in.size());
  GLuint buf = 0, tex = 0;
  glCreateBuffers(1, &buf);
  glNamedBufferData(buf, GLsizeiptr(in.size() * sizeof(float)), in.data(), GL_STATIC_DRAW);
  glCreateTextures(GL_TEXTURE_2D, 1, &tex);
  glTextureStorage2D(tex, 1, internal, n, 1);
  p.use();
  p.set("u_pinned", pinned ? 1 : 0);
  p.set("u_format", format);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf);
  glBindImageTexture(0, tex, 0, GL_FALSE, 0, GL_WRITE_ONLY, internal);
  glDispatchCompute(GLuint(n), 1, 1);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::vector<float> out(in.size() * 4);
  if (internal == GL_RGBA8) {
    // Read as bytes: reading RGBA8 back as float gives c * (1/255), one ulp off c/255 (gl_backend.md).
    std::vector<uint8_t> bytes(in.size() * 4);
    glGetTextureImage(tex, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bytes.size()), bytes.data());
    for (size_t i = 0; i < bytes.size(); ++i) out[i] = float(bytes[i]);
  } else {
    glGetTextureImage(tex, 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
  }
  glDeleteTextures(1, &tex);
  glDeleteBuffers(1, &buf);
  std::vector<float> red(in.size());
  for (size_t i = 0; i < in.size(); ++i) red[i] = out[i * 4];
  return red;
}

// Which admissible conversion produced `got` from `in`: "nearest", "truncate" (toward zero), both
// (the input was exact), or "" (neither: not a conversion GL allows).
std::string classify(const std::vector<float>& got, const std::vector<float>& nearest,
                     const std::vector<float>& truncated) {
  bool all_nearest = true, all_truncated = true;
  for (size_t i = 0; i < got.size(); ++i) {
    all_nearest = all_nearest && got[i] == nearest[i];
    all_truncated = all_truncated && got[i] == truncated[i];
  }
  return all_nearest ? "nearest" : all_truncated ? "truncate" : "";
}

float half_toward_zero(float v) {
  int e = 0;
  std::frexp(v, &e);
  return std::ldexp(std::trunc(std::ldexp(v, 11 - e)), e - 11);  // normal range, positive v
}
}  // namespace

TEST(GlStoreConversion, Unorm8StoreIsOneOfGlsTwoAndThePinnedValueIsTheReferences) {
  VCT_REQUIRE_GL();
  // 100.3, 100.7, 200.6 and 3.9 steps: nearest and truncation differ on the last three.
  const std::vector<float> steps = {100.3f, 100.7f, 200.6f, 3.9f};
  std::vector<float> in, nearest, truncated, reference;
  for (float s : steps) {
    in.push_back(s / 255.0f);
    nearest.push_back(std::nearbyint(in.back() * 255.0f));
    truncated.push_back(std::trunc(in.back() * 255.0f));
    reference.push_back(std::nearbyint(quantize_unorm8(in.back()) * 255.0f));  // the CPU voxels' integer
  }
  const std::string kind = classify(store_and_read(in, GL_RGBA8, "rgba8", 1, false), nearest, truncated);
  std::printf("this driver's float->unorm8 imageStore: %s\n", kind.empty() ? "neither" : kind.c_str());
  RecordProperty("unorm8_store", kind);
  EXPECT_FALSE(kind.empty()) << "an RGBA8 store that neither rounds nor truncates";
  EXPECT_EQ(store_and_read(in, GL_RGBA8, "rgba8", 1, true), reference);
}

TEST(GlStoreConversion, HalfStoreIsOneOfGlsTwoAndThePinnedValueIsTheReferences) {
  VCT_REQUIRE_GL();
  // Values 0.3 and 0.7 of a half step above 1, 3 and 1000 (each binary16 step: 2^-10, 2^-9, 0.5).
  std::vector<float> in, nearest, truncated, reference;
  for (float base : {1.0f, 3.0f, 1000.0f}) {
    int e = 0;
    std::frexp(base, &e);
    const float step = std::ldexp(1.0f, e - 11);
    for (float f : {0.3f, 0.7f}) {
      in.push_back(base + f * step);
      nearest.push_back(quantize_half(in.back()));
      truncated.push_back(half_toward_zero(in.back()));
      reference.push_back(quantize_half(in.back()));
    }
  }
  const std::string kind = classify(store_and_read(in, GL_RGBA16F, "rgba16f", 0, false), nearest, truncated);
  std::printf("this driver's float->half imageStore: %s\n", kind.empty() ? "neither" : kind.c_str());
  RecordProperty("half_store", kind);
  EXPECT_FALSE(kind.empty()) << "an RGBA16F store that neither rounds nor truncates";
  EXPECT_EQ(store_and_read(in, GL_RGBA16F, "rgba16f", 0, true), reference);
}

}  // namespace vct::gl::test
