#include "core/precision.h"

namespace vct {

namespace {

using P = Precision;

// One row per conversion, in Precision order (checked below). docs/compare.md, "Precision table",
// derives each and says which are carried where.
constexpr std::array<PrecisionRow, kPrecisionCount> kRows = {{
    {P::SubpixelSnap, "subpixel-snap", "window-space vertex positions (rasterisation)", 0x1p-8,
     "2^-8 px per axis (GL_SUBPIXEL_BITS 8: llvmpipe and current GPUs; the driver's value is read at run time)",
     "GL 4.5 §14.5, §14.6 (the spec's minimum is 4 bits); dEQP MIN_SUBPIXEL_BITS",
     "every raster stage's slope term (d32f-depth, interpolated-attribute), raster and light-space alternatives, "
     "the voxel shading slack's snap, coverage ties",
     "PrecisionRows.SubpixelSnapAdmitsTheSlopeTerm, PrecisionRows.SubpixelSnapBeyondFails (gbuffer.depth)"},
    {P::DepthInterpolation, "depth-interpolation", "window depth interpolated in float (D32F)", 0x1p-14,
     "2^-14 absolute, plus the snap times the depth's slope",
     "GL 4.5 §14.6.1, §13.8 (how z is interpolated is not fixed); 1/8 of the default shadow bias",
     "shadow_map.N, shadow_map_cube.M, gbuffer.depth (d32f-depth)",
     "PrecisionRows.DepthInterpolationAdmitsItsError, PrecisionRows.DepthInterpolationBeyondFails "
     "(gbuffer.depth, shadow_map.0)"},
    {P::DepthPlaneSetup, "depth-plane-setup", "the window-depth plane set up in single precision from a triangle's vertices",
     0x1p-24,
     "u = 2^-24 per rounding: (4u S_x + |dz/dx| 4u S_A) / |A| + u |dz/dx| on each gradient component (S: the "
     "products' magnitudes in the area A and the numerators) times the distance from the first vertex, plus three "
     "roundings of the evaluation; taken where it exceeds the barycentric form's 2^-22 (plane_setup_margin)",
     "GL 4.5 §14.6.1 eq. 14.10 (the arithmetic is not fixed); IEEE single precision (llvmpipe's set-up)",
     "every depth_tie_margin: light-space alternatives (shadow_map.N, shadow_map_cube.M), the G-buffer's depth ties",
     "PlaneSetup.FloatSetUpFromEveryVertexStaysInsideTheBound, PlaneSetup.TheClippedSliverOfSeed2463 (shadow_map.0)"},
    {P::DepthPlaneSnap, "depth-plane-snap",
     "the depth plane through window vertices a snap moved, at a centre the snapped coverage admits", 0x1p-8,
     "2^-8 (|dz/dx| + |dz/dy|) times 1 + 4 sum r_i / (A - R) (r_i each edge's reach over the vertices' box, R = P + 8 "
     "what a snap may change the area A by); any depth in [0, 1] where A <= R (a snap may close the triangle)",
     "GL 4.5 §14.6.1 eq. 14.10 (barycentrics from window vertices whose rounding is not fixed; llvmpipe "
     "interpolates through the unsnapped positions, covers through the snapped ones)",
     "every depth_tie_margin: light-space alternatives (shadow_map.N, shadow_map_cube.M), the G-buffer's depth ties",
     "PlaneSnap.EveryPlaneThroughVerticesOneStepOffStaysInsideTheMarginAtEveryCentreASnapCovers, "
     "PlaneSnap.TheSliverOfLargeSeed14HasNoPlane, scenes/regressions/seed-14-large (gbuffer.depth)"},
    {P::DepthUnorm, "depth-unorm", "window depth stored as b-bit UNORM (depth24, depth16)", 2.0,
     "2q, q = 1/(2^b - 1): the engine takes either integer neighbour, the reference the nearest",
     "GL 4.5 §2.3.5.2", "light-space depth stages under a declared shadow_depth_format (depth_quantum_of)",
     "PrecisionRows.DepthUnormAndUnorm16AdmitTwoSteps, PrecisionRows.DepthUnormOneFurtherStepFails "
     "(shadow_map.0, depth16)"},
    {P::AttributeInterpolation, "attribute-interpolation", "perspective-correct attribute interpolation in float",
     0x1p-12, "1e-4 + 2^-12 |r|, plus the snap times the attribute's slope",
     "GL 4.5 §14.6.1 eq. 14.9 (the arithmetic is not fixed)", "gbuffer.position (interpolated-attribute)",
     "PrecisionRows.AttributeInterpolationAdmitsItsRelativeError, "
     "PrecisionRows.AttributeInterpolationBeyondFails (gbuffer.position)"},
    {P::AttributeExtrapolation, "attribute-extrapolation",
     "attributes at a sample or centre outside the triangle (MSAA coverage without centroid)", 0.0,
     "the snapped point's reach 2^-8 sum|l_i| / (1 - 2^-8 G), l the barycentrics at the centre, G their gradients",
     "GL 4.5 §14.6.1, §14.9.3 (non-centroid inputs are evaluated at the pixel centre)",
     "the voxel shading slack (voxel_snap_reach), coverage ties; the camera G-buffer (single-sampled: a centre "
     "outside a triangle is covered only under the snap, within 2^-8 px of its edge): each raster alternative's "
     "plane and lookups at the four shifts (gbuffer_ties.cpp)",
     "FragmentSlack.SnapReachCoversExtrapolatedAttributes (tests/ref/fragment_slack_test.cpp), "
     "PrecisionRows.AttributeExtrapolationBeyondTheReach (voxel_snap_reach)"},
    {P::Unorm8, "unorm8", "float to 8-bit UNORM (storage, normal-map texels, display output)", 1.0 / 255.0,
     "one step 1/255: either neighbour (nearest is only recommended)", "GL 4.5 §2.3.5.1",
     "RGBA8 voxel storage (rgba8-quantised, fixed-point + 1/255, cas-rgba8-interval), RGBA8 mips, the normal-map "
     "texel precision in the slacks, a declared display transform's last step",
     "PrecisionRows.Unorm8AdmitsOneStep, PrecisionRows.Unorm8TwoStepsFail (voxel.radiance, rgba8)"},
    {P::Unorm16, "unorm16", "float to 16-bit UNORM", 1.0 / 65535.0, "one step 1/65535: either neighbour",
     "GL 4.5 §2.3.5.1", "depth16 shadow maps through depth-unorm; no colour stage stores UNORM16",
     "PrecisionRows.DepthUnormAndUnorm16AdmitTwoSteps, PrecisionRows.DepthUnormOneFurtherStepFails "
     "(shadow_map.0, depth16)"},
    {P::HalfFloat, "half-float", "float to binary16 (RGBA16F storage, the running mean)", 0x1p-11,
     "half an ulp (2^-11 relative) rounding to nearest; one ulp under any rounding mode",
     "GL 4.5 §2.3.4.2", "voxel.radiance (rgba16f-ulp: 2 half-ulps), every mip level, the running-mean interval",
     "PrecisionRows.HalfFloatAdmitsOneUlpPerSide, PrecisionRows.HalfFloatFourUlpsFail (voxel.radiance, rgba16f)"},
    {P::SrgbDecode, "srgb-decode", "8-bit sRGB texel to linear (base colour, emissive textures)", 0.5,
     "half a step of the 8-bit encoding: the decoded value encodes back to its texel (decode(c +- 1/2 / 255)); "
     "llvmpipe measured at most 0.34 of a step (issue 34)",
     "GL 4.5 §8.24 (the formula; its precision is the format's); dEQP/Vulkan CTS: + 4/255 on sRGB lookups "
     "(looser)",
     "gbuffer.albedo, gbuffer.emission (inside texture-8bit-weights' 2^-7 + 2^-7 |r|), voxel.radiance (the voxel "
     "shading slack's srgb term: base colour and emission shifted +- half a step); image.direct: not carried",
     "SrgbDecodePrecision.WithinHalfAStepPassesAndFailsWithoutTheTerm, SrgbDecodePrecision.AWholeStepOffFails "
     "(tests/compare/srgb_decode_precision_test.cpp), GlSrgbPrecision.* (tests/gl/gl_srgb_precision_test.cpp) "
     "(voxel.radiance)"},
    {P::SrgbEncode, "srgb-encode", "linear to 8-bit sRGB (an engine's display output)", 1.0,
     "one step of the bit depth after the transform (either neighbour)", "GL 4.5 §17.3.9, §2.3.5.1",
     "image stages a declared display transform names (the bound carried through the transform + one step)",
     "PrecisionRows.SrgbEncodeAdmitsOneStep, PrecisionRows.SrgbEncodeOneFurtherStepFails (image.final, gamma "
     "2.2, 8 bits)"},
    {P::FilterWeights, "filter-weights", "bilinear/trilinear weights of a texture lookup", 0x1p-8,
     "8 sub-texel bits per axis and an 8-bit mip blend: per fetch (2 + 1) 2^-9 of the texel range",
     "GL 4.5 §8.14.2 (open); D3D11 functional spec §7.18.16.1; dEQP LookupPrecision uvwBits 8",
     "texture-8bit-weights, normal-map-8bit-weights, filtered-8bit (cone stages), the slacks' texel shift, "
     "linear PCF's 2^-7 (kLinearCompareWeightStep)",
     "PrecisionRows.FilterWeightsAdmitTheTextureBound, PrecisionRows.FilterWeightsBeyondFails (gbuffer.albedo)"},
    {P::LodDerivatives, "lod-derivatives", "the texture LOD lambda from derivatives", 0x1p-4,
     "every lambda between the approximations of the scale factor rho the spec permits, +- 2^-4 for log2 itself "
     "(llvmpipe's linear-mantissa log2: up to 0.0431 low)",
     "GL 4.5 §8.14.1 (eq. 8.7 and the max-axis approximation; log2's precision is not fixed); dEQP LodPrecision "
     "lodBits 4 (accepted as QualityWarning after lodBits 6)",
     "gbuffer.texture_slack (texture LOD), the voxel shading slack (voxel_lod)",
     "PrecisionRows.LodDerivativesAdmitTheSumApproximation, "
     "PrecisionRows.LodDerivativesBeyondTheRangeIsNotACandidate (RhoBounds, lod_candidates)"},
    {P::ShadingArithmetic, "shading-arithmetic", "the shared BRDF evaluated in float", 0x1p-6,
     "2^-6 |r| + 2^-10 mean |r| on inputs that carry 2^-7",
     "GLSL 4.50 §4.7.1 (+ - x correctly rounded; exp, pow 3 + 2|x| ulp)", "image.direct, image.emission "
     "(shading-float)",
     "PrecisionRows.ShadingArithmeticAdmitsItsRelativeError, PrecisionRows.ShadingArithmeticBeyondFails "
     "(image.direct)"},
    {P::DivisionRcpRsqrt, "division-rcp-rsqrt", "x / y, 1 / x, inversesqrt", 2.5,
     "2.5 ulp for division and reciprocal, 2 ulp for inversesqrt (GLSL); 0.5 ulp in C++",
     "GLSL 4.50 §4.7.1; llvmpipe's results differ by CPU vendor (pygfx issues #1318/#1321): within these ulps",
     "PCF taps that may flip (ndc_error, freedoms/shadow_ties.h), shading-float",
     "PrecisionRows.DivisionTermIsInTheNdcMargin, PrecisionRows.DivisionTwoPointFiveUlpAtHalfIsCovered "
     "(ndc_error: 2 (2.5 + 0.5) u |ndc|, an ulp being up to 2u|x|); no case beyond the margin"},
    {P::Blending, "blending", "additive blending into a float target", 0x1p-24,
     "each add rounded to the target (float: half an ulp, 2^-24 relative)", "GL 4.5 §17.3.8, §2.3.4.1",
     "image.particles (filtered-8bit: far larger)",
     "PrecisionRows.BlendingRoundingIsAdmitted, PrecisionRows.BlendingBeyondTheFilteredBoundFails "
     "(image.particles; subsumed by filtered-8bit, so no case fails without it)"},
    {P::MsaaResolve, "msaa-resolve", "a multisampled image resolved to one value per pixel", 0.0,
     "not used: no stage resolves; the voxelization counts its samples itself at the driver's positions "
     "(facts.sample_positions)",
     "GL 4.5 §18.3.1 (the resolve's weights are implementation-defined)", "-",
     "-"},
}};

constexpr bool rows_in_order() {
  for (size_t i = 0; i < kRows.size(); ++i)
    if (size_t(kRows[i].id) != i) return false;
  return true;
}
static_assert(rows_in_order(), "precision rows must be listed in Precision order");

std::string cell(const char* s) { return *s ? s : "-"; }

}  // namespace

const std::array<PrecisionRow, kPrecisionCount>& precision_table() { return kRows; }

const PrecisionRow& precision_row(Precision p) { return kRows[size_t(p)]; }

double precision(Precision p) { return kRows[size_t(p)].value; }

std::string precision_table_markdown() {
  std::string md =
      "| conversion | what | allowed error | source | consumed by | tested by |\n"
      "| --- | --- | --- | --- | --- | --- |\n";
  for (const PrecisionRow& r : kRows)
    md += "| `" + std::string(r.name) + "` | " + r.conversion + " | " + r.allowed + " | " + cell(r.source) + " | " +
          cell(r.consumers) + " | " + cell(r.test) + " |\n";
  return md;
}

}  // namespace vct
