// vct_gl_runner: the GL half of the oracle alone, for GPU machines that lack the project's
// packages. Renders every GL stage of a scene into a stage set that `vct compare --scene` judges
// on any machine, or (--timings) the per-stage GPU times at several grid sizes. Links EGL/GL, the
// scene loader and the stage-set writer only: no Embree, no OpenImageIO (runner_image_io.cpp).
// Exit: 0 ok, 2 bad input, 3 no GL context. docs/gl_backend.md, "GL runner".
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "compare/stage_set.h"
#include "core/error.h"
#include "gl/gl_context.h"
#include "gl/gl_faults.h"
#include "gl/gl_pipeline.h"
#include "io/atomic_file.h"
#include "runner_options.h"
#include "runner_timings.h"
#include "scene/gltf_loader.h"

namespace vct::gl {
namespace {

void add_flags(CLI::App& app, RunnerOptions& o) {
  app.add_option("scene", o.scene, "glTF 2.0 scene (default: the built-in Cornell box)");
  app.add_option("--out", o.out, "Directory for the stage set (or the timings)");
  app.add_option("--config", o.config, "Settings JSON ({\"vct\": {...}}), under the flags");
  app.add_option("--gl-device", o.device, "EGL device index, a name, or 'surfaceless' (default: first hardware device)");
  app.add_option("--gl-fault", o.fault, "Deliberate fault: " + gl_fault_names());
  app.add_flag_callback(
      "--list-faults",
      [] {
        for (const GlFault& f : kGlFaults) std::printf("%s\n", f.name);
        throw CLI::Success();
      },
      "Print the fault names, one a line, and exit");
  app.add_option("--width", o.width, "Image width");
  app.add_option("--height", o.height, "Image height");
  app.add_option("--grid", o.grid, "Voxel grid N (N^3)");
  app.add_option("--msaa", o.msaa, "Voxelization MSAA samples requested (1, 4, 8)");
  app.add_flag("--max-msaa", o.max_msaa, "Voxelize with the driver's GL_MAX_FRAMEBUFFER_SAMPLES (beats --msaa)");
  app.add_option("--shadow-map-size", o.shadow_map_size, "Shadow map side");
  app.add_option("--bounces", o.bounces, "Multibounce frames");
  app.add_option("--reduction", o.reduction, "exact | fixed | cas");
  app.add_option("--storage", o.storage, "rgba8 | rgba16f");
  app.add_option("--voxelizer", o.voxelizer, "conservative | gpu: the reference's voxelizer (GL runs the sample rule "
                 "unless --conservative-raster)");
  app.add_option("--conservative-raster", o.conservative_raster,
                 "off | gs | nv | intel: GL's conservative voxelization mode (nv, intel: exit 3 without the extension)");
  app.add_flag("--aniso", o.aniso, "Anisotropic mips");
  app.add_flag("--no-depth-prepass", o.no_depth_prepass, "Skip the depth pre-pass");
  app.add_option("--timings", o.timing_grids, "Grid sizes to time (e.g. 32,64,128,256) instead of writing a stage set")
      ->delimiter(',');
  app.add_option("--repeat", o.repeat, "Timing repetitions per configuration (best kept)")->check(CLI::Range(1, 50));
}

int render(const RunnerOptions& o) {
  if (o.out.empty()) throw InputError("--out", "is required (the stage set directory)");
  check_gl_fault(o.fault, "--gl-fault");
  Settings s = runner_settings(o);
  const Scene scene = load_scene(o.scene);
  GlContext context(o.device);
  if (o.max_msaa) s.vct.msaa_samples = max_settable_samples(context);
  const FrameResult frame = render_gl_frame(context, scene, s, {o.device, o.fault});
  cmp::StageSet set = cmp::stage_set_from_frame(frame, s.vct);
  cmp::write_stage_set(o.out, set);
  const nlohmann::json summary = {{"scene", scene.source}, {"settings", s}, {"facts", frame.facts},
                                  {"timings_ms", frame.timings_ms}, {"info", frame.info},
                                  {"fault", o.fault}, {"fault_blamed", o.fault.empty() ? "" : find_gl_fault(o.fault)->blamed},
                                  {"fault_where", o.fault.empty() ? "" : find_gl_fault(o.fault)->where},
                                  {"fault_visible_on_cpu_rasterizer",
                                   o.fault.empty() || find_gl_fault(o.fault)->visible_on_cpu_rasterizer}};
  write_text_atomically((std::filesystem::path(o.out) / "runner.json").string(), summary.dump(2) + "\n");
  std::printf("vct_gl_runner: %s on %s (%s), grid %d, %d samples%s -> %s\n", scene.source.c_str(),
              frame.facts.renderer.c_str(), frame.facts.device.c_str(), s.vct.grid, frame.facts.msaa_samples,
              o.fault.empty() ? "" : (", fault " + o.fault).c_str(), o.out.c_str());
  return kExitOk;
}

}  // namespace
}  // namespace vct::gl

int main(int argc, char** argv) {
  using namespace vct;
  CLI::App app{"vct_gl_runner: render every GL stage of a scene into a stage set (judge it with vct compare --scene)"};
  gl::RunnerOptions o;
  gl::add_flags(app, o);
  try {
    app.parse(argc, argv);
    return o.timing_grids.empty() ? gl::render(o) : gl::run_timings(o);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "vct_gl_runner: %s (see --help)\n", e.what());
    return kExitBadInput;
  } catch (const InputError& e) {
    std::fprintf(stderr, "vct_gl_runner: %s\n", e.what());
    return kExitBadInput;
  } catch (const EnvironmentError& e) {
    std::fprintf(stderr, "vct_gl_runner: environment: %s\n", e.what());
    return kExitNoEnvironment;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "vct_gl_runner: out of memory (try a smaller --grid or image size)\n");
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "vct_gl_runner: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vct_gl_runner: error: %s\n", e.what());
    return kExitFailed;
  }
}
