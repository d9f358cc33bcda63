// Coverage ties of the voxel raster (freedoms/coverage_ties.h): the admissible means against brute
// force, and the fragments a snapped raster may drop or add against voxelizations of triangles
// whose window vertices really moved by one sub-pixel step.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <random>
#include <set>
#include <tuple>

#include "freedoms/coverage_ties.h"
#include "freedoms/fill_ties.h"
#include "scene/gltf_loader.h"
#include "stage_test_scene.h"
#include "stages/inject.h"
#include "stages/raster.h"
#include "stages/reduction.h"
#include "stages/shadow_map.h"
#include "stages/voxel_fill.h"
#include "stages/voxelize.h"

namespace vct {
namespace {

// {1, 1} certain, {4, 0} uncertain: the means of {1,1}, {1,1,4}, {1,1,0}, {1,1,4,0} are 1, 2,
// 2/3 and 1.5, so the range is [2/3, 2]. With nothing certain the set may be {3} or {1} alone.
TEST(CoverageTies, MeanRangeByHand) {
  const MeanRange a = admissible_mean_range({1, 1}, {1, 1}, {4, 0}, {4, 0});
  EXPECT_DOUBLE_EQ(a.lo, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(a.hi, 2.0);
  const MeanRange b = admissible_mean_range({}, {}, {3, 1}, {3, 1});
  EXPECT_DOUBLE_EQ(b.lo, 1.0);
  EXPECT_DOUBLE_EQ(b.hi, 3.0);
  // Each fragment's own slack widens its end: lo from value - slack, hi from value + slack.
  const MeanRange c = admissible_mean_range({0.9}, {1.1}, {}, {});
  EXPECT_DOUBLE_EQ(c.lo, 0.9);
  EXPECT_DOUBLE_EQ(c.hi, 1.1);
}

// Every subset of up to 6 uncertain values, added to 0-3 certain ones: the extremes of the
// enumerated means equal the range.
TEST(CoverageTies, MeanRangeEqualsTheExtremesOfEverySubset) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(0.0, 2.0);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<double> certain(size_t(trial % 4)), uncertain(size_t(1 + trial % 6));
    for (double& v : certain) v = value(rng);
    for (double& v : uncertain) v = value(rng);
    double lo = 1e300, hi = -1e300;
    for (unsigned mask = 0; mask < (1u << uncertain.size()); ++mask) {
      double sum = 0.0;
      size_t n = certain.size();
      for (double c : certain) sum += c;
      for (size_t k = 0; k < uncertain.size(); ++k)
        if (mask >> k & 1u) sum += uncertain[k], ++n;
      if (n == 0) continue;
      lo = std::min(lo, sum / double(n));
      hi = std::max(hi, sum / double(n));
    }
    const MeanRange r = admissible_mean_range(certain, certain, uncertain, uncertain);
    EXPECT_NEAR(r.lo, lo, 1e-12) << "trial " << trial;
    EXPECT_NEAR(r.hi, hi, 1e-12) << "trial " << trial;
  }
}

using FragmentKey = std::tuple<int, int, int, uint32_t>;
std::set<FragmentKey> keys(const std::vector<VoxelFragment>& fragments) {
  std::set<FragmentKey> k;
  for (const VoxelFragment& f : fragments) k.insert({f.voxel.x, f.voxel.y, f.voxel.z, f.triangle});
  return k;
}

// 150 random tilted triangles (z-dominant, unshared vertices, a few voxels to a fraction of one) in a
// 16^3 grid.
Scene tilted_triangles(std::mt19937& rng) {
  std::uniform_real_distribution<float> centre(-1.6f, 1.6f), size(0.02f, 0.6f), tilt(-0.7f, 0.7f);
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.5f));
  for (int t = 0; t < 150; ++t) {
    const vec3 c(centre(rng), centre(rng), centre(rng) * 0.5f);
    const float r = size(rng), gx = tilt(rng), gy = tilt(rng);  // depth slopes, |n_z| dominant
    const vec3 p[3] = {c + vec3(-r, -r * 0.7f, 0), c + vec3(r, -r * 0.2f, 0), c + vec3(-r * 0.1f, r, 0)};
    vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = p[i] + vec3(0, 0, gx * (p[i].x - c.x) + gy * (p[i].y - c.y));
    test::add_triangle(s, q[0], q[1], q[2], m);
  }
  s.bounds.add(vec3(-2.0f));
  s.bounds.add(vec3(2.0f));
  s.volume = fit_volume(s.bounds);
  return s;
}

// `s` with every vertex moved by -1, 0 or +1 sub-pixel step (2^-8 voxel of an n^3 grid) on each
// window axis (x, y), its depth kept, as a snapping GL may place it.
Scene snapped(const Scene& s, int n, std::mt19937& rng) {
  const float step = s.volume.size / float(n) / 256.0f;
  std::uniform_int_distribution<int> snap(-1, 1);
  Scene moved = s;
  for (vec3& p : moved.positions) p += vec3(float(snap(rng)) * step, float(snap(rng)) * step, 0.0f);
  return moved;
}

// The GPU rule's voxelization of `s` at grid n (4 samples) with its coverage ties.
Voxelization voxelization_with_ties(const Scene& s, int n) {
  Voxelization vox = voxelize_gpu_rule(s, n, 4);
  add_coverage_ties(s, vox);
  return vox;
}

// tilted_triangles, then voxelized again with the same samples after snapped(), 200 times. Every
// fragment that run loses must be one the reference marked may_drop, and every fragment it gains
// one of may_add.
TEST(CoverageTies, EverySnappedVoxelizationIsAmongTheTies) {
  std::mt19937 rng(11);
  const Scene s = tilted_triangles(rng);
  const int n = 16;
  const Voxelization vox = voxelization_with_ties(s, n);
  std::set<FragmentKey> droppable, addable = keys(vox.may_add);
  for (size_t i = 0; i < vox.fragments.size(); ++i)
    if (vox.may_drop[i]) droppable.insert({vox.fragments[i].voxel.x, vox.fragments[i].voxel.y, vox.fragments[i].voxel.z, vox.fragments[i].triangle});
  const std::set<FragmentKey> base = keys(vox.fragments);
  size_t changed = 0;
  for (int run = 0; run < 200; ++run) {
    const std::set<FragmentKey> now = keys(voxelize_gpu_rule(snapped(s, n, rng), n, 4).fragments);
    for (const FragmentKey& k : base) {
      if (now.count(k)) continue;
      ++changed;
      EXPECT_TRUE(droppable.count(k)) << "lost a fragment not marked may_drop, triangle " << std::get<3>(k);
    }
    for (const FragmentKey& k : now) {
      if (base.count(k)) continue;
      ++changed;
      EXPECT_TRUE(addable.count(k)) << "gained a fragment not in may_add, triangle " << std::get<3>(k);
    }
  }
  std::printf("%zu fragments, %zu may be dropped, %zu may be added; %zu changes over the snaps\n", base.size(),
              droppable.size(), addable.size(), changed);
  EXPECT_GT(changed, 0u);  // the snaps did change some fragment sets: the test tests something
  EXPECT_LT(droppable.size() + addable.size(), base.size() / 2);  // and the ties are not everything
}

// The same snaps, seen as occupancy: every voxel a snapped voxelization leaves empty or fills
// otherwise than the reference is one occupancy_ties() flags (voxel.occupancy_tie, the occupancy
// judge's coverage-tie rule), and the flags are a small part of the occupied voxels.
TEST(CoverageTies, EverySnappedOccupancyChangeIsAnOccupancyTie) {
  std::mt19937 rng(11);
  const Scene s = tilted_triangles(rng);
  const int n = 16;
  const Voxelization vox = voxelization_with_ties(s, n);
  const Volume ties = occupancy_ties(vox);
  size_t changed = 0, flagged = 0;
  for (float t : ties.data) flagged += t > 0.0f;
  for (int run = 0; run < 200; ++run) {
    const Volume now = voxelize_gpu_rule(snapped(s, n, rng), n, 4).occupancy;
    for (size_t i = 0; i < now.data.size(); ++i) {
      if (now.data[i] == vox.occupancy.data[i]) continue;
      ++changed;
      EXPECT_GT(ties.data[i], 0.0f) << "voxel " << i << " changed occupancy and is not an occupancy tie";
    }
  }
  std::printf("%lld occupied voxels, %zu occupancy ties; %zu changes over the snaps\n",
              static_cast<long long>(vox.covered), flagged, changed);
  EXPECT_GT(changed, 0u);
  EXPECT_LT(flagged, size_t(vox.covered) / 2);  // and the ties are not every voxel
}

// Occupancy with surface thickening by k (ref/stages/voxel_fill.h): the surface and the k voxels
// behind it along each facing direction its fragments have.
std::vector<uint8_t> thickened_occupancy(const Scene& s, const Voxelization& v, int k) {
  std::vector<uint8_t> surface(v.occupancy.data.size());
  for (size_t i = 0; i < surface.size(); ++i) surface[i] = v.occupancy.data[i] > 0.0f;
  const std::vector<uint8_t> thick = thickened_voxels(surface, facing_masks(s, v), v.n, k);
  for (size_t i = 0; i < surface.size(); ++i) surface[i] |= thick[i];
  return surface;
}

// The same snaps with surface thickening by 2 (scenes/regressions/seed-2572-small: llvmpipe moved a
// sliver's fragment one voxel along y, and the two voxels thickened behind it moved too): every
// voxel whose occupancy, surface or filled, a snapped voxelization changes is flagged by
// occupancy_ties_with_fills, which the surface's ties alone (occupancy_ties) do not all do.
TEST(CoverageTies, EverySnappedThickenedOccupancyChangeIsAFillTie) {
  std::mt19937 rng(11);
  const Scene s = tilted_triangles(rng);
  const int n = 16, k = 2;
  VctSettings settings;
  settings.surface_thickening_voxels = k;
  const Voxelization vox = voxelization_with_ties(s, n);
  const Volume ties = occupancy_ties_with_fills(s, vox, settings);
  const Volume surface_ties = occupancy_ties(vox);
  const std::vector<uint8_t> reference = thickened_occupancy(s, vox, k);
  size_t changed = 0, flagged = 0, beyond_surface_ties = 0, occupied = 0;
  for (float t : ties.data) flagged += t > 0.0f;
  for (uint8_t o : reference) occupied += o;
  for (int run = 0; run < 200; ++run) {
    const std::vector<uint8_t> now = thickened_occupancy(s, voxelize_gpu_rule(snapped(s, n, rng), n, 4), k);
    for (size_t i = 0; i < now.size(); ++i) {
      if (now[i] == reference[i]) continue;
      ++changed;
      beyond_surface_ties += surface_ties.data[i] == 0.0f;
      EXPECT_GT(ties.data[i], 0.0f) << "voxel " << i << " changed occupancy and is not a tie";
    }
  }
  std::printf("%zu occupied voxels with thickening, %zu ties; %zu changes over the snaps, %zu not surface ties\n",
              occupied, flagged, changed, beyond_surface_ties);
  EXPECT_GT(beyond_surface_ties, 0u);  // the fills' ties are needed: the surface's alone miss changes
  EXPECT_LT(flagged, occupied / 2);    // and the ties are not every voxel
  // Without thickening the fills add nothing: the surface's ties exactly.
  EXPECT_EQ(occupancy_ties_with_fills(s, vox, VctSettings{}).data, surface_ties.data);
}

// With the solid fill on (not monotone in the surface) the fills' ties stay the judge's counted
// fill-ray rule: the surface's ties, none on a voxel the reference fills (a fragment that may land
// there leaves it occupied).
TEST(CoverageTies, WithTheSolidFillAFilledVoxelIsNoSurfaceTie) {
  std::mt19937 rng(11);
  const Scene s = tilted_triangles(rng);
  const int n = 16;
  VctSettings settings;
  settings.solid_voxelization = true;
  settings.surface_thickening_voxels = 2;
  const Voxelization vox = voxelization_with_ties(s, n);
  const Volume ties = occupancy_ties_with_fills(s, vox, settings);
  const Volume surface_ties = occupancy_ties(vox);
  const std::vector<uint8_t> filled = thickened_occupancy(s, vox, 2);
  size_t cleared = 0;
  for (size_t i = 0; i < ties.data.size(); ++i) {
    EXPECT_LE(ties.data[i], surface_ties.data[i]) << i;
    const bool reference_fills = filled[i] && vox.occupancy.data[i] == 0.0f;
    if (reference_fills) EXPECT_EQ(ties.data[i], 0.0f) << i;
    cleared += ties.data[i] != surface_ties.data[i];
  }
  EXPECT_GT(cleared, 0u);  // some fragment the ties may add lands in a filled voxel
}

// The same snaps, seen as fragment counts: every snapped voxelization's count in every voxel lies
// in the reference's fragment_count_ranges (voxel.fragment_count_range), which the radiance judge
// takes as derived count ties; and the ranges are not wide everywhere.
TEST(CoverageTies, EverySnappedFragmentCountIsInsideTheCountRange) {
  std::mt19937 rng(11);
  const Scene s = tilted_triangles(rng);
  const int n = 16;
  const Voxelization vox = voxelization_with_ties(s, n);
  const Volume range = fragment_count_ranges(vox);
  ASSERT_EQ(range.channels, 2);
  const auto counts = [&](const Voxelization& v) {
    std::vector<float> c(range.voxel_count(), 0.0f);
    for (const VoxelFragment& f : v.fragments) c[size_t(voxel_linear_index(n, f.voxel))] += 1.0f;
    return c;
  };
  const std::vector<float> own = counts(vox);
  size_t changed = 0, wide = 0;
  for (size_t i = 0; i < own.size(); ++i) {
    EXPECT_TRUE(own[i] >= range.data[2 * i] && own[i] <= range.data[2 * i + 1]) << "voxel " << i;
    wide += range.data[2 * i + 1] > range.data[2 * i];
  }
  for (int run = 0; run < 200; ++run) {
    const std::vector<float> now = counts(voxelize_gpu_rule(snapped(s, n, rng), n, 4));
    for (size_t i = 0; i < now.size(); ++i) {
      changed += now[i] != own[i];
      EXPECT_TRUE(now[i] >= range.data[2 * i] && now[i] <= range.data[2 * i + 1])
          << "voxel " << i << ": " << now[i] << " outside [" << range.data[2 * i] << ", " << range.data[2 * i + 1] << "]";
    }
  }
  std::printf("%zu voxels with a count range, %zu count changes over the snaps\n", wide, changed);
  EXPECT_GT(changed, 0u);
  EXPECT_LT(wide, size_t(vox.covered));
}

// tilted_triangles glowing (emission 0.5, so every fragment carries light without shadow maps),
// voxelized at 16^3 with its ties, and the coverage ties' slack with no per-fragment slack.
struct GlowingTies {
  Scene scene;
  Voxelization vox;
  VctSettings settings;
  std::vector<vec3> values;
  Volume slack, exact;
};
GlowingTies glowing_ties() {
  GlowingTies g;
  std::mt19937 rng(11);
  g.scene = tilted_triangles(rng);
  for (Material& m : g.scene.materials) m.emissive_factor = vec3(0.5f);
  const int n = 16;
  g.vox = voxelization_with_ties(g.scene, n);
  g.settings.grid = n;
  g.values = fragment_radiance(g.scene, g.vox, {}, g.settings);
  g.slack = Volume(n, n, n, 1);
  g.exact = Volume(n, n, n, 1);
  widen_for_coverage_ties(g.scene, g.vox, g.values, std::vector<float>(g.vox.fragments.size(), 0.0f), {}, g.settings,
                          nullptr, g.slack, g.exact);
  return g;
}

// A voxel whose every fragment may land in a neighbour may be written no fragment at all: a fill
// that still occupies it leaves RGB 0 (stages/voxel_fill.h), so its slack reaches down to 0. The
// triangles glow (glowing_ties).
TEST(CoverageTies, AVoxelEveryFragmentMayLeaveAdmitsNoLight) {
  const GlowingTies g = glowing_ties();
  const Voxelization& vox = g.vox;
  const std::vector<vec3>& values = g.values;
  const Volume& slack = g.slack;
  size_t all_may_leave = 0;
  for (size_t b = 0, e = 0; b < vox.fragments.size(); b = e) {
    bool every = true;
    double mean = 0.0;
    for (e = b; e < vox.fragments.size() && vox.fragments[e].voxel == vox.fragments[b].voxel; ++e) {
      every = every && vox.may_drop[e];
      mean += double(values[e].x);
    }
    if (!every) continue;
    ++all_may_leave;
    const ivec3 v = vox.fragments[b].voxel;
    EXPECT_GE(double(*slack.voxel(v.x, v.y, v.z)), mean / double(e - b)) << "voxel " << v.x << " " << v.y << " " << v.z;
  }
  EXPECT_GT(all_may_leave, 0u);
}

// A voxel only fragments that may be added reach holds no light in the reference (RGB 0 where a
// fill occupies it); GL may write any of them, so its slack reaches up to the largest one's light.
TEST(CoverageTies, AVoxelOnlyAddedFragmentsReachAdmitsTheirLight) {
  const GlowingTies g = glowing_ties();
  const Voxelization& vox = g.vox;
  const Volume& slack = g.slack;
  const int n = g.settings.grid;
  Voxelization added;
  added.n = n;
  added.fragments = vox.may_add;
  const std::vector<vec3> added_values = fragment_radiance(g.scene, added, {}, g.settings);
  size_t only_added = 0;
  for (size_t k = 0; k < vox.may_add.size(); ++k) {
    const ivec3 v = vox.may_add[k].voxel;
    if (vox.occupancy.voxel(v.x, v.y, v.z)[0] > 0.0f) continue;
    ++only_added;
    EXPECT_GE(double(*slack.voxel(v.x, v.y, v.z)), double(added_values[k].x)) << "voxel " << v.x << " " << v.y << " " << v.z;
  }
  EXPECT_GT(only_added, 0u);
}

// scenes/regressions/seed-2-medium: an alpha-masked sliver across several depth layers; llvmpipe
// wrote two fragments to voxel (18, 15, 15), where the reference writes one. The count range there
// must reach two (before session 16 it was [1, 1]: the sliver's alpha and layer were taken as bounded).
TEST(CoverageTies, Seed2MediumSliverMayLandInAnyLayer) {
  const Scene s = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-2-medium/scene.gltf");
  const Voxelization vox = voxelization_with_ties(s, 32);
  const Volume range = fragment_count_ranges(vox);
  const float* r = range.voxel(18, 15, 15);
  EXPECT_LE(r[0], 1.0f);
  EXPECT_GE(r[1], 2.0f);
}

bool has(const std::vector<VoxelFragment>& fragments, const std::vector<uint8_t>* only, ivec3 voxel) {
  for (size_t i = 0; i < fragments.size(); ++i)
    if (fragments[i].voxel == voxel && (!only || (*only)[i])) return true;
  return false;
}

// The conservative voxelizer: boxes the triangle meets only within GL's conservative arithmetic
// (kConservativeArithmetic) of their faces. Voxel space = world here (origin 0, size n). The
// triangle (1,1)-(3,1)-(1,3) at z = 2.5: its hypotenuse x + y = 4 touches voxel (2,2,2) at its
// corner (2,2) only, which the half-open box holds: a fragment that may be dropped. Its edge y = 1
// touches voxel (1,0,2) on that box's open face: no fragment, one that may be added. Voxel
// (1,1,2) lies well inside: certain. Voxel (1,0,2) moved 1/512 away (a triangle at y >= 1 + 1/512)
// is no tie.
TEST(CoverageTies, ConservativeBoxesTouchedWithinTheArithmeticAreTies) {
  for (const float gap : {0.0f, 1.0f / 512.0f}) {
    Scene s;
    const uint32_t m = test::add_material(s, vec3(0.5f));
    test::add_triangle(s, {1, 1 + gap, 2.5f}, {3, 1 + gap, 2.5f}, {1, 3, 2.5f}, m);
    s.volume.origin = vec3(0.0f);
    s.volume.size = 8.0f;
    Voxelization vox = voxelize_conservative(s, 8);
    add_coverage_ties(s, vox);
    EXPECT_TRUE(has(vox.fragments, nullptr, {1, 1, 2}));
    EXPECT_FALSE(has(vox.fragments, &vox.may_drop, {1, 1, 2}));
    EXPECT_EQ(has(vox.may_add, nullptr, {1, 0, 2}), gap == 0.0f) << "gap " << gap;
    if (gap == 0.0f) {
      EXPECT_TRUE(has(vox.fragments, &vox.may_drop, {2, 2, 2}));
    }
  }
}


// scenes/regressions/seed-25-large: at voxel (52, 66, 74) an extrapolated fragment's COLOR_0 turns
// its green light negative, and the fixed-point reduction encodes it as 0 (stages/reduction.h
// reduction_input). GL may also write a fragment the coverage ties add there (llvmpipe did). The
// mean of the reduction's inputs with every added fragment written lies inside the slack around
// the reference's own mean of them (the raw values' mean, 0.25 lower in green, left it outside).
TEST(CoverageTies, ANegativeFragmentEntersTheMeanAsTheReductionTakesIt) {
  const Scene s = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-25-large/scene.gltf");
  VctSettings settings;
  settings.grid = 128;
  settings.shadow_map_size = 256;
  settings.reduction = Reduction::FixedPoint;  // what the GL build reduces with
  const Voxelization vox = voxelization_with_ties(s, settings.grid);
  const std::vector<ShadowMap> maps = render_shadow_maps(s, settings);
  const std::vector<vec3> values = fragment_radiance(s, vox, maps, settings);
  Voxelization extra;
  extra.n = vox.n;
  extra.fragments = vox.may_add;
  const std::vector<vec3> extra_values = fragment_radiance(s, extra, maps, settings);
  Volume slack(vox.n, vox.n, vox.n, 1), exact(vox.n, vox.n, vox.n, 1);
  widen_for_coverage_ties(s, vox, values, std::vector<float>(vox.fragments.size(), 0.0f), maps, settings, nullptr,
                          slack, exact);
  const ivec3 v(52, 66, 74);
  const auto input = [&](float x) { return double(reduction_input(x, settings.reduction)); };
  bool negative = false;
  for (int c = 0; c < 3; ++c) {
    double own = 0.0, all = 0.0;
    size_t n_own = 0, n_all = 0;
    for (size_t i = 0; i < vox.fragments.size(); ++i)
      if (vox.fragments[i].voxel == v) own += input(values[i][c]), all += input(values[i][c]), ++n_own, ++n_all;
    for (size_t i = 0; i < vox.fragments.size(); ++i) negative = negative || (vox.fragments[i].voxel == v && values[i][c] < 0.0f);
    for (size_t i = 0; i < extra.fragments.size(); ++i)
      if (extra.fragments[i].voxel == v) all += input(extra_values[i][c]), ++n_all;
    ASSERT_GT(n_own, 0u);
    ASSERT_GT(n_all, n_own);  // a fragment GL may add
    EXPECT_LE(std::abs(all / double(n_all) - own / double(n_own)), double(*slack.voxel(v.x, v.y, v.z))) << "channel " << c;
  }
  EXPECT_TRUE(negative);  // the case the reduction's clamp decides
  EXPECT_EQ(reduction_input(-0.7f, Reduction::FixedPoint), 0.0f);
  EXPECT_EQ(reduction_input(2000.0f, Reduction::FixedPoint), 1024.0f);
  EXPECT_EQ(reduction_input(1.5f, Reduction::CasRgba8), 1.0f);
  EXPECT_EQ(reduction_input(-0.7f, Reduction::ExactMean), -0.7f);
}

}  // namespace
}  // namespace vct
