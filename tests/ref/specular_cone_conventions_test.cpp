// The specular cone's own conventions (issue 21): specular_offset_voxels, specular_quality,
// specular_aperture (ours 2 atan(r^2), or the source design's Rosseaux polynomial) and
// specular_view. Hand values and hand-marched cones on an 8^3 volume.
#include <gtest/gtest.h>

#include <cmath>

#include "core/settings.h"
#include "stages/cone_sets.h"
#include "stages/cone_trace.h"

namespace vct {
namespace {

TEST(SpecularAperture, RosseauxPolynomialOfRoughnessSquared) {
  // Full aperture 2 (c0 + a (c1 - c2 a)), a = r^2, c0 = 0.0003474660443456835,
  // c1 = 1.3331290497744692, c2 = 0.5040552688878546 (righier/gidemo voxelcone.frag):
  // r = 1: 2 (c0 + c1 - c2) = 1.6588417 rad (95.04 degrees, above ours' 90 degree cap);
  // r = 0.5: a = 0.25, 2 (c0 + 0.25 (c1 - 0.126013817)) = 0.6042526; r = 0: 2 c0.
  EXPECT_NEAR(specular_cone_aperture_of(SpecularAperture::Rosseaux, 1.0f), 1.6588417, 1e-6);
  EXPECT_NEAR(specular_cone_aperture_of(SpecularAperture::Rosseaux, 0.5f), 0.6042526, 1e-6);
  EXPECT_NEAR(specular_cone_aperture_of(SpecularAperture::Rosseaux, 0.0f), 0.00069493, 1e-8);
  EXPECT_NEAR(specular_cone_aperture_of(SpecularAperture::Rosseaux, 1.5f), 1.6588417, 1e-6);  // r clamped to 1
  // Ours: 2 atan(r^2), capped at 90 degrees: r = 1 gives exactly pi/2, r = 0.5 2 atan(0.25).
  EXPECT_NEAR(specular_cone_aperture_of(SpecularAperture::Ggx, 1.0f), 1.5707963, 1e-6);
  EXPECT_NEAR(specular_cone_aperture_of(SpecularAperture::Ggx, 0.5f), 2.0 * std::atan(0.25), 1e-6);
}

// The source design's cones: diffuse origin 2 voxels along n, first sample 2 along the axis,
// step 0.7 d; specular origin 4 voxels along n, from t = 0, step 0.6 d.
VctSettings gidemo_like(int) {
  VctSettings s;
  s.cone_start = ConeStart::Normal;
  s.cone_offset_voxels = 2.0f;
  s.cone_axis_offset_voxels = 2.0f;
  s.cone_quality = 0.7f;
  s.specular_offset_voxels = 4.0f;
  s.specular_quality = 0.6f;
  return s;
}

TEST(SpecularMarch, OwnOffsetAndStepUnderTheNormalStart) {
  const VctSettings s = gidemo_like(64);
  const MarchParams diffuse = MarchParams::from_settings(s, 64);
  const MarchParams spec = MarchParams::specular_from_settings(s, 64);
  EXPECT_FLOAT_EQ(diffuse.normal_offset, 2.0f / 64.0f);
  EXPECT_FLOAT_EQ(diffuse.start_offset, 2.0f / 64.0f);
  EXPECT_FLOAT_EQ(diffuse.quality, 0.7f);
  EXPECT_FLOAT_EQ(spec.normal_offset, 4.0f / 64.0f);
  EXPECT_FLOAT_EQ(spec.start_offset, 0.0f);  // the diffuse cones' axis offset is not the specular's
  EXPECT_FLOAT_EQ(spec.quality, 0.6f);
}

TEST(SpecularMarch, AxisStartAndDefaultsFollowTheDiffuseCones) {
  VctSettings s;  // ours: axis start 1.5 voxels, quality 0.5
  const MarchParams d = MarchParams::from_settings(s, 32);
  MarchParams p = MarchParams::specular_from_settings(s, 32);
  EXPECT_EQ(p.start_offset, d.start_offset);
  EXPECT_EQ(p.normal_offset, d.normal_offset);
  EXPECT_EQ(p.quality, d.quality);
  s.specular_offset_voxels = 3.0f;  // under axis: the first sample 3 voxels along the cone
  p = MarchParams::specular_from_settings(s, 32);
  EXPECT_FLOAT_EQ(p.start_offset, 3.0f / 32.0f);
  EXPECT_FLOAT_EQ(p.normal_offset, 0.0f);
}

// N = 8, one emissive opaque voxel (4,4,4) of radiance 3 in level 0, upper levels empty.
VoxelMips one_voxel_level0() {
  VoxelMips m;
  for (int n = 8; n >= 1; n /= 2) m.iso.push_back(Volume(n, n, n, 4));
  m.iso[0].set_rgba(4, 4, 4, vec4(3.0f, 3.0f, 3.0f, 1.0f));
  return m;
}

// Surface point at voxel (1,4,4)'s centre, normal +y, view from -x so reflect(-v, n) = +x; the
// Rosseaux aperture at r = 0.1 (half-angle 0.013628, tan < 1/16 over the volume) keeps every
// diameter at one voxel (1/8), so each sample reads one texel centre of level 0.
struct Grazing {
  vec3 p{1.5f / 8.0f, 4.5f / 8.0f, 4.5f / 8.0f};
  vec3 n{0.0f, 1.0f, 0.0f};
  vec3 v{-1.0f, 0.0f, 0.0f};
  float roughness = 0.1f;
};

VctSettings normal_start(float specular_offset, float specular_quality) {
  VctSettings s;
  s.cone_start = ConeStart::Normal;
  s.cone_offset_voxels = 1.0f;  // the diffuse cones' offset: would lift the specular cone off row 4
  s.cone_quality = 1.0f;
  s.specular_offset_voxels = specular_offset;
  s.specular_quality = specular_quality;
  s.specular_aperture = SpecularAperture::Rosseaux;
  return s;
}

TEST(SpecularMarch, ZeroOwnOffsetMarchesAlongTheSurfaceRowAndHitsTheVoxel) {
  const VoxelMips m = one_voxel_level0();
  const Grazing g;
  std::vector<ConeSample> rec;
  const vec4 r = trace_specular_cone(m, VoxelVolume{}, normal_start(0.0f, 0.0f), g.p, g.n, g.v, g.roughness, &rec);
  // Origin (1.5, 4.5, 4.5) voxels, t = 0, steps of one voxel (cone_quality 1): x = 1.5, 2.5, 3.5,
  // 4.5 -- the fourth is the voxel, opaque, and the march ends.
  ASSERT_EQ(rec.size(), 4u);
  EXPECT_FLOAT_EQ(rec[0].distance, 0.0f);
  EXPECT_FLOAT_EQ(rec[3].position.x, 4.5f / 8.0f);
  EXPECT_FLOAT_EQ(rec[3].position.y, 4.5f / 8.0f);
  EXPECT_FLOAT_EQ(r.x, 3.0f);
  EXPECT_FLOAT_EQ(r.w, 1.0f);
  // The default (< 0) takes the diffuse cones' 1-voxel normal offset: row 5, empty.
  const vec4 lifted = trace_specular_cone(m, VoxelVolume{}, normal_start(-1.0f, 0.0f), g.p, g.n, g.v, g.roughness);
  EXPECT_EQ(lifted, vec4(0.0f));
}

TEST(SpecularMarch, OwnQualityStepsOverTheVoxel) {
  const VoxelMips m = one_voxel_level0();
  const Grazing g;
  std::vector<ConeSample> rec;
  // specular_quality 2: steps of two voxels, x = 1.5, 3.5, 5.5, 7.5 (texel centres of empty
  // voxels 1, 3, 5, 7), then 9.5 is outside: four samples, nothing seen.
  const vec4 r = trace_specular_cone(m, VoxelVolume{}, normal_start(0.0f, 2.0f), g.p, g.n, g.v, g.roughness, &rec);
  ASSERT_EQ(rec.size(), 4u);
  EXPECT_FLOAT_EQ(rec[1].position.x, 3.5f / 8.0f);
  EXPECT_FLOAT_EQ(rec[3].position.x, 7.5f / 8.0f);
  EXPECT_EQ(r, vec4(0.0f));
}

TEST(SpecularView, FromTheOriginMovesTheViewPointAlongTheNormal) {
  // gidemo's volume: world [-1, 1]^3 (size 2); 4 voxels of 64 = 0.0625 texture units = 0.125 world.
  const VoxelVolume volume{vec3(-1.0f), 2.0f};
  const vec3 p(0.0f, -1.0f, 0.0f), n(0.0f, 1.0f, 0.0f);
  const vec3 o = specular_view_point(volume, SpecularView::Origin, 4.0f / 64.0f, p, n);
  EXPECT_FLOAT_EQ(o.x, 0.0f);
  EXPECT_FLOAT_EQ(o.y, -0.875f);
  EXPECT_FLOAT_EQ(o.z, 0.0f);
  EXPECT_EQ(specular_view_point(volume, SpecularView::Surface, 4.0f / 64.0f, p, n), p);
  // Through a ConeFrame built from the settings (64^3 mips): the same point.
  VoxelMips m;
  for (int k = 64; k >= 1; k /= 2) m.iso.push_back(Volume(k, k, k, 4));
  VctSettings s = gidemo_like(64);
  s.specular_view = SpecularView::Origin;
  const ConeFrame frame(m, volume, s, 0.0f, false);
  EXPECT_FLOAT_EQ(frame.specular_view_point(p, n).y, -0.875f);
}

}  // namespace
}  // namespace vct
