// Shared helpers for the GL cross-backend tests: one context for the whole test binary (creating
// contexts repeatedly is slow on llvmpipe), small settings, the Cornell box, and image metrics.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "compare/verdict.h"
#include "core/error.h"
#include "core/settings.h"
#include "gl/gl_context.h"
#include "gl/gl_pipeline.h"
#include "scene/gltf_loader.h"

namespace vct::gl::test {

/// The process's context, or nullptr when the machine has none (tests then GTEST_SKIP).
inline GlContext* shared_context() {
  static std::unique_ptr<GlContext> ctx;
  static bool tried = false;
  if (!tried) {
    tried = true;
    try {
      ctx = std::make_unique<GlContext>();
    } catch (const EnvironmentError&) {
      ctx.reset();
    }
  }
  return ctx.get();
}

#define VCT_REQUIRE_GL()                                                 \
  GlContext* ctx = ::vct::gl::test::shared_context();                    \
  if (!ctx) GTEST_SKIP() << "no OpenGL 4.5 context (EnvironmentError)"

/// Tiny sizes: llvmpipe runs every shader on the CPU.
inline Settings small_settings(int grid = 32, int size = 64) {
  Settings s;
  s.vct.width = size;
  s.vct.height = size;
  s.vct.shadow_map_size = 256;
  s.vct.grid = grid;
  s.vct.msaa_samples = 4;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.reduction = Reduction::FixedPoint;
  s.threads = 2;
  return s;
}

inline const Scene& cornell_box() {
  static const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/cornell_box.gltf");
  return scene;
}

/// Largest absolute difference over all samples (same sizes required).
template <class T>
float max_abs_diff(const T& a, const T& b) {
  EXPECT_EQ(a.data.size(), b.data.size());
  float m = 0.0f;
  for (size_t i = 0; i < std::min(a.data.size(), b.data.size()); ++i) m = std::max(m, std::abs(a.data[i] - b.data[i]));
  return m;
}

/// Number of samples differing by more than `tol`.
template <class T>
size_t count_diff(const T& a, const T& b, float tol) {
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.data.size(), b.data.size()); ++i) n += std::abs(a.data[i] - b.data[i]) > tol;
  return n;
}

/// The failing stages of a report, space-separated (for test output and assertions).
inline std::string failing_stages(const cmp::Report& rep) {
  std::string out;
  for (const auto& st : rep.stages)
    if (st.verdict == cmp::Verdict::Fail) out += st.stage + " ";
  return out;
}

}  // namespace vct::gl::test
