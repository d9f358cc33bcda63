// The depth-only raster path against the visibility buffer it replaces for shadow maps: the same
// bytes on real scenes, on meshes whose pixel centres sit exactly on shared edges and vertices, on
// coplanar overlaps (depth ties) and on random clipped triangles, for 1, 2 and 8 threads.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>

#include "core/parallel.h"
#include "scene/gltf_loader.h"
#include "stages/depth_raster.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

struct Mesh {
  std::vector<vec3> positions;
  std::vector<uvec3> triangles;
  void add(vec3 a, vec3 b, vec3 c) {
    const uint32_t n = uint32_t(positions.size());
    positions.insert(positions.end(), {a, b, c});
    triangles.push_back(uvec3(n, n + 1, n + 2));
  }
};

// Asserts render_depth == render_visibility().depth bit for bit at 1, 2 and 8 threads; returns the
// number of texels some triangle wrote (so callers can check the case is not empty).
int expect_same_depth(const std::vector<vec3>& positions, const std::vector<uvec3>& triangles, const mat4& view_proj,
                      int width, int height) {
  set_thread_count(1);
  const std::vector<float> reference = render_visibility(positions, triangles, view_proj, width, height).depth;
  for (int threads : {1, 2, 8}) {
    set_thread_count(threads);
    const std::vector<float> depth = render_depth(positions, triangles, view_proj, width, height);
    EXPECT_EQ(depth.size(), reference.size());
    if (depth.size() != reference.size()) break;
    int differing = 0, first = -1;
    for (size_t i = 0; i < depth.size(); ++i)
      if (std::memcmp(&depth[i], &reference[i], sizeof(float)) != 0 && differing++ == 0) first = int(i);
    EXPECT_EQ(differing, 0) << threads << " threads; first at x " << first % width << ", row " << first / width
                            << ": " << (first >= 0 ? depth[size_t(first)] : 0.0f) << " vs "
                            << (first >= 0 ? reference[size_t(first)] : 0.0f);
  }
  set_thread_count(0);
  int written = 0;
  for (float d : reference) written += d < 1.0f;
  return written;
}

// NDC position of a window position (identity view_proj): the hand-made cases place vertices in
// window coordinates, exactly representable.
vec3 window(float x, float y, float z, int w, int h) { return vec3(x / float(w) * 2.0f - 1.0f, y / float(h) * 2.0f - 1.0f, z); }

TEST(DepthRaster, CentreRowSpanIsTheHandCountedRun) {
  // Window (1,1), (6,1), (1,6) in 8x8 (raster_test's hand-counted triangle): covered centres are
  // x + y <= 5 for x, y >= 1; the hypotenuse through centres (x + y = 6) is a right edge: excluded.
  std::vector<RasterTriangle> t;
  const vec4 clip[3] = {vec4(window(1, 1, 0, 8, 8), 1), vec4(window(6, 1, 0, 8, 8), 1), vec4(window(1, 6, 0, 8, 8), 1)};
  setup_triangle(clip, 8, 8, 0, t);
  ASSERT_EQ(t.size(), 1u);
  const EdgeSetup e = edge_setup(t[0]);
  for (int y = 0; y < 8; ++y) {
    int x0 = 0, x1 = 7;
    const bool any = centre_row_span(e, y, x0, x1);
    EXPECT_EQ(any, y >= 1 && y <= 4) << y;
    if (any) {
      EXPECT_EQ(x0, 1) << y;
      EXPECT_EQ(x1, 5 - y) << y;
    }
  }
  int x0 = 3, x1 = 3;  // the caller's range is respected
  EXPECT_TRUE(centre_row_span(e, 1, x0, x1));
  EXPECT_EQ(x0, 3);
  EXPECT_EQ(x1, 3);
}

TEST(DepthRaster, SharedEdgesAndTiesMatchTheVisibilityBuffer) {
  // raster_test's mesh with vertices on half-pixel positions (many centres exactly on edges and
  // vertices), on a slanted plane, drawn twice (second copy with the other winding: exact depth
  // ties), plus a coplanar second triangulation of the same plane (near-ties) and a nearer
  // axis-aligned rectangle whose edges run through centres.
  const int w = 32, h = 32, g = 8;
  std::vector<vec2> v;
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i) {
      float x = float(i) * 4.0f, y = float(j) * 4.0f;
      if (i > 0 && i < g) x += float((i * 7 + j * 3) % 5) * 0.5f - 1.0f + 0.5f;
      if (j > 0 && j < g) y += float((i * 5 + j * 11) % 5) * 0.5f - 1.0f + 0.5f;
      v.push_back({x, y});
    }
  const auto z = [](vec2 p) { return 0.3f + 0.01f * p.x - 0.007f * p.y; };
  const auto at = [&](int k) { return window(v[size_t(k)].x, v[size_t(k)].y, z(v[size_t(k)]), w, h); };
  Mesh m;
  for (int copy = 0; copy < 2; ++copy)
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) {
        const int a = j * (g + 1) + i, b = a + 1, c = a + g + 2, d = a + g + 1;
        if ((i + j + copy) % 2) {
          m.add(at(a), at(b), at(c));
          m.add(at(a), at(c), at(d));
        } else {
          m.add(at(a), at(d), at(b));
          m.add(at(b), at(d), at(c));
        }
      }
  const vec2 corner[4] = {{0, 0}, {32, 0}, {32, 32}, {0, 32}};
  const auto cz = [&](int k) { return window(corner[k].x, corner[k].y, z(corner[k]), w, h); };
  m.add(cz(0), cz(1), cz(3));
  m.add(cz(1), cz(2), cz(3));
  m.add(window(4.5f, 6.5f, -0.5f, w, h), window(20.5f, 6.5f, -0.5f, w, h), window(20.5f, 14.5f, -0.5f, w, h));
  m.add(window(4.5f, 6.5f, -0.5f, w, h), window(20.5f, 14.5f, -0.5f, w, h), window(4.5f, 14.5f, -0.5f, w, h));
  EXPECT_EQ(expect_same_depth(m.positions, m.triangles, mat4(1.0f), w, h), w * h);
}

TEST(DepthRaster, RandomClippedTrianglesMatchTheVisibilityBuffer) {
  // Vertices on a quarter-pixel grid (centres on edges), some far outside the viewport (guard-band
  // clipping), some behind the near or beyond the far plane, through a perspective projection
  // (perspective-divided window positions, near/far clipping). Odd sizes: bands cut off mid-way.
  std::mt19937 rng(12345);
  const auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * float(rng() % 100000u) / 100000.0f; };
  const int w = 61, h = 47;
  Mesh flat, deep;
  for (int i = 0; i < 400; ++i) {
    vec3 p[3], q[3];
    const float reach = i % 10 == 0 ? 6.0f : 1.2f;
    for (int k = 0; k < 3; ++k) {
      const float x = std::round(uniform(-reach, reach) * float(w) * 2.0f) / (float(w) * 2.0f);
      const float y = std::round(uniform(-reach, reach) * float(h) * 2.0f) / (float(h) * 2.0f);
      p[k] = vec3(x, y, uniform(-1.3f, 1.3f));
      q[k] = vec3(uniform(-3.0f, 3.0f), uniform(-3.0f, 3.0f), uniform(-12.0f, 1.0f));
    }
    flat.add(p[0], p[1], p[2]);
    deep.add(q[0], q[1], q[2]);
  }
  EXPECT_GT(expect_same_depth(flat.positions, flat.triangles, mat4(1.0f), w, h), w * h / 2);
  const mat4 proj = glm::perspective(1.3f, float(w) / float(h), 0.5f, 10.0f);
  EXPECT_GT(expect_same_depth(deep.positions, deep.triangles, proj, w, h), w * h / 2);
}

TEST(DepthRaster, CommittedScenesShadowMapsMatchTheVisibilityBuffer) {
  for (const std::string name : {"", "thin_wall.gltf", "tiny_triangles.gltf"}) {
    const Scene s = name.empty() ? load_scene("") : load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/" + name);
    ASSERT_FALSE(s.lights.empty()) << name;
    for (const Light& light : s.lights)
      for (int size : {96, 200}) {
        const mat4 vp = spot_light_view_proj(light, s.bounds);
        EXPECT_GT(expect_same_depth(s.positions, s.triangles, vp, size, size), size * size / 4) << name << " " << size;
      }
  }
}

TEST(DepthRaster, ShadowMapsUseTheDepthPath) {
  const Scene s = load_scene("");
  VctSettings st;
  st.shadow_map_size = 128;
  const std::vector<ShadowMap> maps = render_shadow_maps(s, st);
  ASSERT_EQ(maps.size(), s.lights.size());
  for (const ShadowMap& m : maps) {
    EXPECT_EQ(m.depth.width, 128);
    EXPECT_EQ(m.depth.height, 128);
    EXPECT_EQ(m.depth.channels, 1);
    const std::vector<float> vb = render_visibility(s.positions, s.triangles, m.view_proj, 128, 128).depth;
    ASSERT_EQ(m.depth.data.size(), vb.size());
    EXPECT_EQ(std::memcmp(m.depth.data.data(), vb.data(), vb.size() * sizeof(float)), 0);
  }
}

}  // namespace
}  // namespace vct
