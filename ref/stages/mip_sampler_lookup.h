// The lookups of MipSampler (stages/mip_sampler.h), inline so that the cone march
// (cone_trace.cpp) compiles them into its loop; included at the end of mip_sampler.h only.
#pragma once

#include <algorithm>
#include <cmath>
// VCT_SCALAR_LOOKUPS forces the scalar path (for checking it where SSE2 exists).
#if defined(__SSE2__) && !defined(VCT_SCALAR_LOOKUPS)
#define VCT_SSE2_LOOKUPS 1
#include <emmintrin.h>
#endif

namespace vct {
namespace mip_lookup {

using Level = MipSampler::Level;

// Where a lookup lands in one level: GL §8.14.2 as sample_level_trilinear computes it. The
// weights are filled in only for an occupied cell (an empty one needs none).
//
// With SSE2 (every x86-64) the cell, its weights and the eight-texel sum are formed four lanes
// at a time: each lane does the scalar reference's IEEE operation on the same operands in the
// same order (u = uvw * size - 1/2, f = u - floor(u), w = (wi * wj) * wk, result += w * texel
// starting from +0), and the build has no FMA contraction (no -march, -ffp-contract is moot
// without FMA), so the bits are the reference's; tests/ref/mip_sampler_test.cpp compares them.
// A texel's four channels are one 16-byte load.
#if defined(VCT_SSE2_LOOKUPS)
struct Cell {
  int i0 = 0, j0 = 0, k0 = 0;
  bool interior = false;  // all eight texels inside
  bool located = false;   // i0..k0 in [-1, n-1]: the occupancy byte exists
  ptrdiff_t cell = 0;
  __m128 f = _mm_setzero_ps();    // fractional parts (x, y, z, -)
  bool have_weights = false;
  __m128 w_lo = _mm_setzero_ps();  // weights (di, dj) = (0,0) (1,0) (0,1) (1,1) at dk = 0
  __m128 w_hi = _mm_setzero_ps();  // the same at dk = 1
};

inline __m128 load_uvw(const vec3& uvw) { return _mm_setr_ps(uvw.x, uvw.y, uvw.z, 0.0f); }

[[gnu::always_inline]] inline Cell locate(const Level& L, __m128 uvw) {
  Cell c;
  const __m128 u = _mm_sub_ps(_mm_mul_ps(uvw, _mm_loadu_ps(L.size4.data())), _mm_set1_ps(0.5f));
  // floor by truncate-and-correct, as floor_to_int below: truncation went up where u < float(i).
  __m128i i = _mm_cvttps_epi32(u);
  i = _mm_add_epi32(i, _mm_castps_si128(_mm_cmplt_ps(u, _mm_cvtepi32_ps(i))));
  c.f = _mm_sub_ps(u, _mm_cvtepi32_ps(i));
  c.i0 = _mm_cvtsi128_si32(i);
  c.j0 = _mm_cvtsi128_si32(_mm_shuffle_epi32(i, _MM_SHUFFLE(1, 1, 1, 1)));
  c.k0 = _mm_cvtsi128_si32(_mm_shuffle_epi32(i, _MM_SHUFFLE(2, 2, 2, 2)));
  // Interior: 0 <= i0 and i0 + 1 < n on x, y and z, i.e. -1 < i0 < n - 1, as one lane test.
  const __m128i above = _mm_cmpgt_epi32(i, _mm_set1_epi32(-1));
  const __m128i below = _mm_cmpgt_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(L.last4.data())), i);
  c.interior = (_mm_movemask_ps(_mm_castsi128_ps(_mm_and_si128(above, below))) & 7) == 7;
  c.located = c.interior || (c.i0 >= -1 && c.j0 >= -1 && c.k0 >= -1 && c.i0 < L.nx && c.j0 < L.ny && c.k0 < L.nz);
  c.cell = L.cell_origin + ptrdiff_t(c.k0) * L.cell_sz + ptrdiff_t(c.j0) * L.cell_sy + c.i0;
  return c;
}

// The reference's weights wi * wj * wk, lane by lane: (1 - f) and f per axis, the x-y products,
// then times the z factor.
[[gnu::always_inline]] inline void cell_weights(Cell& c) {
  const __m128 g = _mm_sub_ps(_mm_set1_ps(1.0f), c.f);  // 1 - f
  const __m128 gf = _mm_unpacklo_ps(g, c.f);             // (1-fx, fx, 1-fy, fy)
  const __m128 wi = _mm_movelh_ps(gf, gf);               // (1-fx, fx, 1-fx, fx)
  const __m128 wj = _mm_shuffle_ps(gf, gf, _MM_SHUFFLE(3, 3, 2, 2));  // (1-fy, 1-fy, fy, fy)
  const __m128 wij = _mm_mul_ps(wi, wj);
  c.w_lo = _mm_mul_ps(wij, _mm_shuffle_ps(g, g, _MM_SHUFFLE(2, 2, 2, 2)));
  c.w_hi = _mm_mul_ps(wij, _mm_shuffle_ps(c.f, c.f, _MM_SHUFFLE(2, 2, 2, 2)));
  c.have_weights = true;
}

template <int lane>
inline __m128 broadcast(__m128 v) {
  return _mm_shuffle_ps(v, v, _MM_SHUFFLE(lane, lane, lane, lane));
}

// result + w * texel for the four texels of one (dk) slice of the cell, in the reference's order.
inline __m128 add_slice(__m128 result, __m128 w, __m128 t00, __m128 t10, __m128 t01, __m128 t11) {
  result = _mm_add_ps(result, _mm_mul_ps(broadcast<0>(w), t00));
  result = _mm_add_ps(result, _mm_mul_ps(broadcast<1>(w), t10));
  result = _mm_add_ps(result, _mm_mul_ps(broadcast<2>(w), t01));
  return _mm_add_ps(result, _mm_mul_ps(broadcast<3>(w), t11));
}

inline __m128 texel_or_border(const Level& L, int i, int j, int k) {
  if (i < 0 || j < 0 || k < 0 || i >= L.nx || j >= L.ny || k >= L.nz) return _mm_setzero_ps();
  return _mm_loadu_ps(L.data + size_t(k) * L.sz + size_t(j) * L.sy + size_t(i) * 4);
}

// The eight texels of `c` in `L` (same dimensions as the level `c` was located in), summed in
// the reference's order. The weights are made on first need and reused (the anisotropic path
// reads three volumes through one cell).
// The border case (cells on the volume's faces; one lookup in ten on a closed room) out of line.
[[gnu::noinline]] inline __m128 sum_border(const Level& L, Cell c) {
  if (!c.have_weights) cell_weights(c);
  const int i = c.i0, j = c.j0, k = c.k0;
  const __m128 result = add_slice(_mm_setzero_ps(), c.w_lo, texel_or_border(L, i, j, k), texel_or_border(L, i + 1, j, k),
                                  texel_or_border(L, i, j + 1, k), texel_or_border(L, i + 1, j + 1, k));
  return add_slice(result, c.w_hi, texel_or_border(L, i, j, k + 1), texel_or_border(L, i + 1, j, k + 1),
                   texel_or_border(L, i, j + 1, k + 1), texel_or_border(L, i + 1, j + 1, k + 1));
}

[[gnu::always_inline]] inline __m128 gather(const Level& L, Cell& c) {
  if (c.located && !L.occupied[c.cell]) return _mm_setzero_ps();  // eight zero texels: exactly +0
  if (!c.interior) return sum_border(L, c);
  if (!c.have_weights) cell_weights(c);
  const float* p0 = L.data + ptrdiff_t(c.k0) * ptrdiff_t(L.sz) + ptrdiff_t(c.j0) * ptrdiff_t(L.sy) + c.i0 * 4;
  const float* p1 = p0 + L.sz;
  const __m128 result = add_slice(_mm_setzero_ps(), c.w_lo, _mm_loadu_ps(p0), _mm_loadu_ps(p0 + 4),
                                  _mm_loadu_ps(p0 + L.sy), _mm_loadu_ps(p0 + L.sy + 4));
  return add_slice(result, c.w_hi, _mm_loadu_ps(p1), _mm_loadu_ps(p1 + 4), _mm_loadu_ps(p1 + L.sy),
                   _mm_loadu_ps(p1 + L.sy + 4));
}

using Texel = __m128;
using Uvw = __m128;
inline Texel zero_texel() { return _mm_setzero_ps(); }
inline vec4 to_vec4(__m128 v) {
  vec4 r;
  _mm_storeu_ps(&r.x, v);
  return r;
}
inline __m128 add_scaled(__m128 result, float w, __m128 t) { return _mm_add_ps(result, _mm_mul_ps(_mm_set1_ps(w), t)); }

// (1 - f) * t1 + f * t2, each channel as the reference's vec4 expression forms it.
inline __m128 blend(float f, __m128 t1, __m128 t2) {
  return _mm_add_ps(_mm_mul_ps(_mm_set1_ps(1.0f - f), t1), _mm_mul_ps(_mm_set1_ps(f), t2));
}
#else
// Where a lookup lands in one level: GL §8.14.2 as sample_level_trilinear computes it. The
// weights are filled in only for an occupied cell (an empty one needs none).
struct Cell {
  int i0 = 0, j0 = 0, k0 = 0;
  bool interior = false;  // all eight texels inside
  bool located = false;   // i0..k0 in [-1, n-1]: the occupancy byte exists
  size_t cell = 0;
  vec3 f{0.0f};           // fractional parts
  bool have_weights = false;
  float w[8];             // filled on first need (an empty cell needs none)
};

// floor(u) as an int, exactly std::floor for |u| < 2^31 (uvw in [0,1]^3 gives u in [-0.5, n)):
// truncate, then step down where truncation went up (negative non-integers). The float of the
// result is the float std::floor returns, so f = u - floor(u) keeps its bits.
inline int floor_to_int(float u) {
  const int i = int(u);
  return i - (u < float(i) ? 1 : 0);
}

inline Cell locate(const Level& L, const vec3& uvw) {
  Cell c;
  const vec3 u = uvw * L.size - vec3(0.5f);
  c.i0 = floor_to_int(u.x), c.j0 = floor_to_int(u.y), c.k0 = floor_to_int(u.z);
  c.f = u - vec3(float(c.i0), float(c.j0), float(c.k0));
  c.interior = c.i0 >= 0 && c.j0 >= 0 && c.k0 >= 0 && c.i0 + 1 < L.nx && c.j0 + 1 < L.ny && c.k0 + 1 < L.nz;
  c.located = c.i0 >= -1 && c.j0 >= -1 && c.k0 >= -1 && c.i0 < L.nx && c.j0 < L.ny && c.k0 < L.nz;
  if (c.located)
    c.cell = (size_t(c.k0 + 1) * size_t(L.ny + 1) + size_t(c.j0 + 1)) * size_t(L.nx + 1) + size_t(c.i0 + 1);
  return c;
}

// Weights in the order (dk, dj, di) of the reference loop, each formed as it forms them.
inline void cell_weights(const vec3& f, float w[8]) {
  int o = 0;
  for (int dk = 0; dk < 2; ++dk) {
    const float wk = dk ? f.z : 1.0f - f.z;
    for (int dj = 0; dj < 2; ++dj) {
      const float wj = dj ? f.y : 1.0f - f.y;
      for (int di = 0; di < 2; ++di) {
        const float wi = di ? f.x : 1.0f - f.x;
        w[o++] = wi * wj * wk;
      }
    }
  }
}

inline vec4 texel_or_border(const Level& L, int i, int j, int k) {
  if (i < 0 || j < 0 || k < 0 || i >= L.nx || j >= L.ny || k >= L.nz) return vec4(0.0f);
  const float* t = L.data + size_t(k) * L.sz + size_t(j) * L.sy + size_t(i) * 4;
  return vec4(t[0], t[1], t[2], t[3]);
}

// The eight texels of `c` in `L` (same dimensions as the level `c` was located in), summed in
// the reference's order. The weights are made on first need and reused (the anisotropic path
// reads three volumes through one cell).
inline vec4 gather(const Level& L, Cell& c) {
  if (c.located && !L.occupied[c.cell]) return vec4(0.0f);  // eight zero texels: exactly +0
  if (!c.have_weights) {
    cell_weights(c.f, c.w);
    c.have_weights = true;
  }
  const float* w = c.w;
  vec4 result(0.0f);
  if (c.interior) {
    const float* p0 = L.data + size_t(c.k0) * L.sz + size_t(c.j0) * L.sy + size_t(c.i0) * 4;
    int o = 0;
    for (int dk = 0; dk < 2; ++dk)
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
          const float* t = p0 + size_t(dk) * L.sz + size_t(dj) * L.sy + size_t(di) * 4;
          result += w[o++] * vec4(t[0], t[1], t[2], t[3]);
        }
    return result;
  }
  int o = 0;
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di) result += w[o++] * texel_or_border(L, c.i0 + di, c.j0 + dj, c.k0 + dk);
  return result;
}

using Texel = vec4;
using Uvw = vec3;
inline Texel zero_texel() { return vec4(0.0f); }
inline vec3 load_uvw(const vec3& uvw) { return uvw; }
inline vec4 to_vec4(const vec4& v) { return v; }
inline vec4 add_scaled(const vec4& result, float w, const vec4& t) { return result + w * t; }
inline vec4 blend(float f, const vec4& t1, const vec4& t2) { return (1.0f - f) * t1 + f * t2; }
#endif

[[gnu::always_inline]] inline Texel trilinear(const Level& L, Uvw uvw) {
  Cell c = locate(L, uvw);
  return gather(L, c);
}

// GL §8.14.3 level selection, as sample_chain does it: lambda clamped to [0, q]; at or above q
// level q alone, else floor(lambda) and the next blended by fract(lambda) (one level when 0).
struct LevelPick {
  int d1 = 0;
  float f = 0.0f;
  bool two = false;
};
inline LevelPick pick_levels(int level_count, float lod) {
  const int q = level_count - 1;
  const float lambda = std::min(std::max(lod, 0.0f), float(q));
  LevelPick p;
  if (lambda >= float(q)) {
    p.d1 = q;
    return p;
  }
  p.d1 = int(lambda);  // = floor(lambda): lambda is in [0, q) here
  p.f = lambda - float(p.d1);
  p.two = p.f != 0.0f;
  return p;
}

// The anisotropic lookup from its located cells, as voxel_sampler.cpp's sample_anisotropic
// combines its three chains (same terms, same order).
inline vec4 combine_anisotropic(const std::array<std::vector<Level>, 6>& aniso_, const LevelPick& p, Cell& c1, Cell& c2,
                                const vec3& dir) {
  const vec3 w = dir * dir;
  const int axis_dir[3] = {dir.x >= 0.0f ? kPosX : kNegX, dir.y >= 0.0f ? kPosY : kNegY,
                           dir.z >= 0.0f ? kPosZ : kNegZ};
  const bool base1 = p.d1 == 0;
  const Texel shared1 = base1 ? gather(aniso_[0][0], c1) : zero_texel();
  Texel result = zero_texel();
  for (int a = 0; a < 3; ++a) {
    if (w[a] == 0.0f) continue;  // as voxel_sampler.cpp: the axis does not contribute
    const std::vector<Level>& chain = aniso_[size_t(axis_dir[a])];
    const Texel t1 = base1 ? shared1 : gather(chain[size_t(p.d1)], c1);
    if (!p.two) {
      result = add_scaled(result, w[a], t1);  // result += w[a] * t1
      continue;
    }
    const Texel t2 = gather(chain[size_t(p.d1) + 1], c2);
    result = add_scaled(result, w[a], blend(p.f, t1, t2));  // result += w[a] * ((1 - f) t1 + f t2)
  }
  return to_vec4(result);
}

}  // namespace mip_lookup

[[gnu::always_inline]] inline vec4 MipSampler::sample(const vec3& uvw, float lod, const vec3& dir) const {
  return anisotropic_ ? sample_anisotropic(uvw, lod, dir) : sample_isotropic(uvw, lod);
}

[[gnu::always_inline]] inline vec4 MipSampler::sample_isotropic(const vec3& uvw, float lod) const {
  using namespace mip_lookup;
  const LevelPick p = pick_levels(iso_count_, lod);
  const Uvw at = load_uvw(uvw);
  const Texel t1 = trilinear(iso_[size_t(p.d1)], at);
  if (!p.two) return to_vec4(t1);
  return to_vec4(blend(p.f, t1, trilinear(iso_[size_t(p.d1) + 1], at)));
}

[[gnu::noinline]] inline vec4 MipSampler::sample_anisotropic(const vec3& uvw, float lod, const vec3& dir) const {
  using namespace mip_lookup;
  const LevelPick p = pick_levels(int(aniso_[0].size()), lod);
  // The six directional chains share each level's size (and level 0 itself): one cell per level.
  const Uvw at = load_uvw(uvw);
  Cell c1 = locate(aniso_[0][size_t(p.d1)], at);
  Cell c2;
  if (p.two) c2 = locate(aniso_[0][size_t(p.d1) + 1], at);
  return combine_anisotropic(aniso_, p, c1, c2, dir);
}

}  // namespace vct
