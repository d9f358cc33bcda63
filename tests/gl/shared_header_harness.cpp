// The element harness (shared_header_harness.h): one compute program holding every case as a
// function selected by a uniform, SSBOs of raw words in and out, and the element-wise comparison.
#include "shared_header_harness.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "gl/gl_api.h"
#include "gl/gl_context.h"
#include "gl/gl_program.h"

namespace vct::gl::test {
namespace {

const std::string& embedded_file(const std::string& name) {
  const auto it = embedded_files().find(name);
  if (it == embedded_files().end())
    throw std::runtime_error("element harness: no embedded " + name);
  return it->second;
}

std::string harness_source(const std::vector<ElementCase>& cases, const std::string& header) {
  std::string s = header;
  s += "\nlayout(local_size_x = 64) in;\n"
       "layout(std430, binding = 0) readonly buffer ElementInputs { uvec4 in_words[]; };\n"
       "layout(std430, binding = 1) writeonly buffer ElementOutputs { uvec4 out_words[]; };\n"
       "uniform uint u_points;\nuniform uint u_in_stride;\nuniform uint u_out_stride;\nuniform int "
       "u_case;\n"
       "uint g_point = 0u;  // set first thing in main()\n"
       "uvec4 uin(uint k) { return in_words[g_point * u_in_stride + k]; }\n"
       "vec4 fin(uint k) { return uintBitsToFloat(uin(k)); }\n"
       "void putu(uint k, uvec4 v) { out_words[g_point * u_out_stride + k] = v; }\n"
       "void put(uint k, vec4 v) { putu(k, floatBitsToUint(v)); }\n";
  for (size_t c = 0; c < cases.size(); ++c)
    s += "void element_case_" + std::to_string(c) + "() { // " + cases[c].function + "\n" +
         cases[c].glsl + "\n}\n";
  s += "void main() {\n  g_point = gl_GlobalInvocationID.x;\n  if (g_point >= u_points) return;\n  "
       "switch (u_case) {\n";
  for (size_t c = 0; c < cases.size(); ++c)
    s += "    case " + std::to_string(c) + ": element_case_" + std::to_string(c) + "(); break;\n";
  s += "  }\n}\n";
  return s;
}

std::string describe_input(const ElementCase& c, const glm::uvec4* in) {
  std::string out;
  char buf[160];
  for (size_t k = 0; k < c.in_kinds.size(); ++k) {
    if (c.in_kinds[k] == 'u')
      std::snprintf(buf, sizeof buf, "%s(%uu, %uu, %uu, %uu)", k ? ", " : "", in[k].x, in[k].y,
                    in[k].z, in[k].w);
    else {
      const glm::vec4 f = floats(in[k]);
      std::snprintf(buf, sizeof buf, "%s(%.9g, %.9g, %.9g, %.9g)", k ? ", " : "", double(f.x),
                    double(f.y), double(f.z), double(f.w));
    }
    out += buf;
  }
  return out;
}

// Distance in representable floats (the usual ordered-integer trick; opposite signs add up).
double ulp_distance(float a, float b) {
  auto ordered = [](float f) {
    int32_t i;
    std::memcpy(&i, &f, sizeof i);
    return i < 0 ? -int64_t(i & 0x7fffffff) : int64_t(i);
  };
  return double(std::llabs(ordered(a) - ordered(b)));
}

ElementResult compare_case(const ElementCase& c, const std::vector<glm::uvec4>& gl_out) {
  ElementResult r;
  r.function = c.function;
  r.points = c.points();
  const size_t stride = c.in_kinds.size();
  double worst_score = -1.0;  // ratio, or +inf for an exact mismatch
  std::string worst_text;
  for (size_t p = 0; p < r.points; ++p) {
    const glm::uvec4* in = &c.inputs[p * stride];
    const std::vector<ExpectedSlot> want = c.cpu(in);
    for (int k = 0; k < c.outputs; ++k) {
      const glm::uvec4 got = gl_out[p * size_t(c.outputs) + size_t(k)];
      for (int i = 0; i < 4; ++i) {
        const uint32_t g = got[i], w = want[size_t(k)].bits[i];
        const float bound = want[size_t(k)].bound[i];
        if (g == w) continue;
        const float gf = as_float(g), wf = as_float(w);
        double score;
        char buf[240];
        if (bound == 0.0f) {
          score = std::numeric_limits<double>::infinity();
          std::snprintf(buf, sizeof buf,
                        "output %d.%c: GL 0x%08x (%.9g) vs C++ 0x%08x (%.9g), exact expected", k,
                        "xyzw"[i], g, double(gf), w, double(wf));
        } else {
          const double err = std::abs(double(gf) - double(wf));
          score =
              std::isfinite(err) ? err / double(bound) : std::numeric_limits<double>::infinity();
          if (err > double(bound) + double(FLT_MIN) || !std::isfinite(err))
            score = std::max(score, 1.0 + 1e-9);
          else if (score > 1.0)
            score = 1.0;  // within the denormal-flush allowance
          r.worst_abs = std::max(r.worst_abs, err);
          r.worst_ulps = std::max(r.worst_ulps, ulp_distance(gf, wf));
          std::snprintf(
              buf, sizeof buf,
              "output %d.%c: GL %.9g vs C++ %.9g, |diff| %.3g = %.3g x bound %.3g (%.0f ulp)", k,
              "xyzw"[i], double(gf), double(wf), err, score, double(bound), ulp_distance(gf, wf));
          r.worst_ratio = std::max(r.worst_ratio, std::isfinite(score) ? score : 1e300);
        }
        if (score > 1.0) r.pass = false;
        if (score > worst_score) {
          worst_score = score;
          worst_text = std::string(buf) + " at point " + std::to_string(p) + ", input " +
                       describe_input(c, in);
        }
      }
    }
  }
  r.message = c.function + (r.pass ? ": within bound" : ": GL differs from C++ beyond its bound") +
              (worst_text.empty() ? " (bit-identical everywhere)" : "; worst " + worst_text);
  return r;
}

}  // namespace

std::string shared_header_glsl(const std::vector<std::pair<std::string, std::string>>& perturb) {
  std::string h = "#version 450\n#define VCT_GLSL 1\n" + embedded_file("vct_shared.h") + "\n" +
                  embedded_file("voxel_fixed_point.h") + "\n";
  for (const auto& [from, to] : perturb) {
    const auto at = h.find(from);
    if (at == std::string::npos)
      throw std::runtime_error("element harness: perturbation '" + from + "' not found");
    h.replace(at, from.size(), to);
  }
  return h;
}

std::vector<ElementResult> run_element_cases(const std::vector<ElementCase>& cases,
                                             const std::string& header) {
  const Program program(
      {{GL_COMPUTE_SHADER, "shared_header_element.comp", harness_source(cases, header)}});
  std::vector<ElementResult> results;
  for (size_t c = 0; c < cases.size(); ++c) {
    const ElementCase& e = cases[c];
    const size_t n = e.points();
    if (n == 0 || e.inputs.size() != n * e.in_kinds.size())
      throw std::runtime_error("element case " + e.function + ": inputs are not whole points");
    GLuint buffers[2];
    glCreateBuffers(2, buffers);
    const size_t out_words = n * size_t(e.outputs);
    glNamedBufferStorage(buffers[0], GLsizeiptr(e.inputs.size() * sizeof(glm::uvec4)),
                         e.inputs.data(), 0);
    // Filled with a pattern no case writes, so a skipped store shows as a mismatch.
    const std::vector<glm::uvec4> fill(out_words, glm::uvec4(0xDEADBEEFu));
    glNamedBufferStorage(buffers[1], GLsizeiptr(out_words * sizeof(glm::uvec4)), fill.data(), 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
    program.use();
    program.set("u_points", unsigned(n));
    program.set("u_in_stride", unsigned(e.in_kinds.size()));
    program.set("u_out_stride", unsigned(e.outputs));
    program.set("u_case", int(c));
    glDispatchCompute(GLuint((n + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::uvec4> out(out_words);
    glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(out_words * sizeof(glm::uvec4)), out.data());
    glDeleteBuffers(2, buffers);
    check_gl(("element case " + e.function).c_str());
    results.push_back(compare_case(e, out));
  }
  return results;
}

}  // namespace vct::gl::test
