// EGL device selection (gl/gl_device.h, --gl-device) and the driver's facts (gl/gl_facts.h) on
// Mesa: its EGL exposes one software device through EGL_EXT_platform_device, the same path that
// opens an NVIDIA, AMD or Intel device elsewhere, so CI runs it.
#include <gtest/gtest.h>

#include "core/error.h"
#include "gl/gl_device.h"
#include "gl/gl_device_list.h"
#include "gl/gl_facts.h"
#include "gl_test_util.h"
#include "stages/raster.h"

namespace vct::gl::test {
namespace {

bool is_llvmpipe(const std::string& renderer) { return renderer.find("llvmpipe") != std::string::npos; }

// Index of Mesa's software device, or -1 (then the device tests skip: not a Mesa EGL).
int software_device() {
  for (const EglDevice& d : list_egl_devices())
    if (d.software) return d.index;
  return -1;
}

}  // namespace

TEST(GlDevice, SpecsParse) {
  EXPECT_EQ(parse_device_spec("").kind, DeviceSpec::Kind::Automatic);
  EXPECT_EQ(parse_device_spec("auto").kind, DeviceSpec::Kind::Automatic);
  EXPECT_EQ(parse_device_spec("surfaceless").kind, DeviceSpec::Kind::Surfaceless);
  const DeviceSpec two = parse_device_spec("2");
  EXPECT_EQ(two.kind, DeviceSpec::Kind::Index);
  EXPECT_EQ(two.index, 2);
  const DeviceSpec name = parse_device_spec("NVIDIA");
  EXPECT_EQ(name.kind, DeviceSpec::Kind::Name);
  EXPECT_EQ(name.name, "NVIDIA");
  EXPECT_THROW(parse_device_spec("-1"), InputError);
  EXPECT_THROW(parse_device_spec("123456"), InputError);
  EXPECT_TRUE(contains_ignoring_case("llvmpipe (LLVM 15.0.6, 256 bits)", "LLVMpipe"));
  EXPECT_FALSE(contains_ignoring_case("llvmpipe", "radeon"));
}

TEST(GlDevice, MesaSoftwareDeviceOpensByIndexAndByName) {
  VCT_REQUIRE_GL();
  const int soft = software_device();
  if (soft < 0) GTEST_SKIP() << "no EGL_MESA_device_software device (not Mesa's EGL)";
  {
    GlContext by_index(std::to_string(soft));
    EXPECT_EQ(by_index.device().rfind("egl device " + std::to_string(soft), 0), 0u) << by_index.device();
    EXPECT_TRUE(is_llvmpipe(by_index.renderer())) << by_index.renderer();
    EXPECT_GE(by_index.max_framebuffer_samples(), 4);
  }
  {
    // A name only GL_RENDERER carries: the device is opened to read it.
    GlContext by_name("LLVMPIPE");
    EXPECT_EQ(by_name.device().rfind("egl device", 0), 0u) << by_name.device();
  }
  {
    GlContext by_extension("MESA_device_software");
    EXPECT_EQ(by_extension.device().rfind("egl device " + std::to_string(soft), 0), 0u);
  }
  // The shared context is current again after the probes (GlContext restores the previous one).
  EXPECT_NO_THROW(check_gl("after the device contexts"));
  EXPECT_EQ(render_gl_frame(*ctx, cornell_box(), small_settings(16, 16)).backend, "gl");
}

TEST(GlDevice, MissingDevicesAreBadInput) {
  EXPECT_THROW(GlContext("99"), InputError);
  EXPECT_THROW(GlContext("no-such-gpu-vendor"), InputError);
}

TEST(GlDevice, AutomaticPrefersHardwareThenSurfaceless) {
  VCT_REQUIRE_GL();
  bool hardware = false;
  for (const EglDevice& d : list_egl_devices()) hardware = hardware || !d.software;
  GlContext automatic;
  if (hardware) {
    EXPECT_EQ(automatic.device().rfind("egl device", 0), 0u) << automatic.device();
  } else {
    EXPECT_EQ(automatic.device(), "mesa surfaceless");
  }
}

// Same driver through the device platform and through surfaceless: the same frame, bit for bit.
TEST(GlDevice, DevicePlatformRendersTheSameFrameAsSurfaceless) {
  VCT_REQUIRE_GL();
  const int soft = software_device();
  if (soft < 0) GTEST_SKIP() << "no EGL_MESA_device_software device";
  const Settings s = small_settings();
  const FrameResult a = render_gl_frame(cornell_box(), s, {std::to_string(soft), ""});
  const FrameResult b = render_gl_frame(cornell_box(), s, {"surfaceless", ""});
  EXPECT_EQ(a.facts.device.rfind("egl device", 0), 0u);
  EXPECT_EQ(b.facts.device, "mesa surfaceless");
  EXPECT_EQ(max_abs_diff(a.voxels.radiance, b.voxels.radiance), 0.0f);
  EXPECT_EQ(max_abs_diff(a.images.final_image, b.images.final_image), 0.0f);
}

// The facts the CPU mirrors. llvmpipe's 4x pattern is the standard one the CPU assumed before
// positions were read (stages/raster.cpp), so mirroring changes nothing there.
TEST(GlFacts, SamplePositionsSubpixelBitsAndClamping) {
  VCT_REQUIRE_GL();
  const BackendFacts four = read_driver_facts(*ctx, 4);
  ASSERT_EQ(four.msaa_samples, 4);
  ASSERT_EQ(four.sample_positions.size(), 4u);
  for (const vec2& p : four.sample_positions) {
    EXPECT_GE(p.x, 0.0f);
    EXPECT_LT(p.x, 1.0f);
    EXPECT_GE(p.y, 0.0f);
    EXPECT_LT(p.y, 1.0f);
  }
  EXPECT_GT(four.subpixel_bits, 0);
  EXPECT_EQ(four.renderer, ctx->renderer());
  EXPECT_FALSE(four.unreported.empty());  // texture filtering precision has no query
  const BackendFacts one = read_driver_facts(*ctx, 1);
  EXPECT_EQ(one.sample_positions, std::vector<vec2>{vec2(0.5f, 0.5f)});
  const BackendFacts many = read_driver_facts(*ctx, 64);
  EXPECT_EQ(many.msaa_samples_requested, 64);
  EXPECT_LE(many.msaa_samples, std::max(ctx->max_framebuffer_samples(), 1) * 2);
  if (is_llvmpipe(ctx->renderer())) {
    EXPECT_EQ(four.sample_positions, standard_sample_positions(4));
    EXPECT_EQ(four.subpixel_bits, kSubpixelBits);
    EXPECT_EQ(many.msaa_samples, 4);  // GL_MAX_FRAMEBUFFER_SAMPLES = 4
    EXPECT_TRUE(four.conservative_raster.empty());
  }
}

TEST(GlFacts, FrameRecordsWhatRan) {
  VCT_REQUIRE_GL();
  Settings s = small_settings(16, 16);
  s.vct.msaa_samples = 8;
  s.vct.reduction = Reduction::ExactMean;
  const FrameResult r = render_gl_frame(*ctx, cornell_box(), s, {"", "wrong_mip"});
  EXPECT_EQ(r.facts.msaa_samples_requested, 8);
  EXPECT_EQ(r.facts.msaa_samples, std::min(8, ctx->max_framebuffer_samples()));
  EXPECT_EQ(r.facts.sample_positions.size(), size_t(r.facts.msaa_samples));
  EXPECT_EQ(r.facts.reduction, "fixed_point");
  EXPECT_EQ(r.facts.gl_fault, "wrong_mip");
  EXPECT_EQ(r.info.count("GL_RENDERER"), 0u);  // facts are typed, not prose in info
}

TEST(GlDeviceList, ListsEveryDeviceAndSurfaceless) {
  VCT_REQUIRE_GL();
  const nlohmann::json list = list_gl_devices();
  ASSERT_TRUE(list["devices"].is_array());
  EXPECT_EQ(list["devices"].size(), list_egl_devices().size() + 1);
  EXPECT_EQ(list["devices"].back()["spec"], "surfaceless");
  EXPECT_EQ(list["default"].get<std::string>(), GlContext().device());
  for (const auto& d : list["devices"])
    if (d["status"] == "ok") {
      EXPECT_GE(d["facts"]["max_samples"].get<int>(), 4) << d.dump();
    }
}

}  // namespace vct::gl::test
