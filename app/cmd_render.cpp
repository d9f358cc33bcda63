// vct render SCENE --backend ref|gl: one VCT frame. Always writes final.exr/final.png and
// run.json (settings, environment, timings, scene summary, multibounce energy); --dump writes
// every stage through the shared dump writer and vct-stages.json over it (compare/dump_manifest.h,
// so `vct compare` reads a dumped run); --explain X,Y writes one pixel's cones.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "camera_aspect.h"
#include "commands.h"
#include "compare/dump_manifest.h"
#include "compare/stage_set.h"
#include "core/error.h"
#include "core/memory_budget.h"
#include "freedoms/reference_frame.h"
#include "io/atomic_file.h"
#include "io/bounded_json.h"
#include "io/image_io.h"
#include "io/run_dir.h"
#include "options.h"
#include "scene/exposure.h"
#include "scene/gltf_loader.h"
#include "scene_warnings.h"
#include "stages/dumps.h"
#include "stages/explain.h"
#include "stages/scene_footprint.h"

#ifdef VCT_HAVE_GL  // the GL backend is a build option (VCT_BUILD_GL)
#include "gl/gl_context.h"
#include "gl/gl_conservative.h"
#include "gl/gl_pipeline.h"
#endif

namespace vct::app {

namespace {

// The VCT knobs a user most often turns, as flags; each one left unset keeps the --config value.
struct VctFlags {
  std::string backend = "ref";
  bool dump = false;
  std::string explain;
  bool aniso = false, soft_shadows = false, random_rotation = false, no_particles = false;
  bool no_diffuse = false, no_specular = false;
  std::optional<int> bounces, msaa, shadow_map_size, frame, cone_count;
  std::optional<float> restitution, tolerance, quality, offset, aperture, cone_tilt, time;
  std::optional<std::string> light_model, voxelizer, storage, reduction, weighting;
  GlFlags gl;
  std::string facts_from;  // ref: mirror the sample positions of this GL stage set / run.json
  bool stage_set = false;  // also write OUT/stages (a stage set `vct compare` reads)
};

void add_vct_flags(CLI::App* cmd, VctFlags& f) {
  cmd->add_option("--backend", f.backend, "ref (CPU reference) or gl (OpenGL 4.5)")->check(CLI::IsMember({"ref", "gl"}));
  cmd->add_flag("--dump", f.dump, "Write every stage (images, volumes, mips) into the run directory");
  cmd->add_flag("--stage-set", f.stage_set, "Also write the frame as a stage set in OUT/stages (for vct compare)");
  cmd->add_option("--facts-from", f.facts_from,
                  "ref: emulate the MSAA sample positions a GL run reported (its stage set dir, manifest or run.json)");
  add_gl_flags(cmd, f.gl);
  cmd->add_option("--explain", f.explain, "X,Y: write that pixel's cones (JSON + picture); row 0 = top");
  cmd->add_flag("--aniso", f.aniso, "Anisotropic voxels (six directional mip volumes)");
  cmd->add_flag("--soft-shadows", f.soft_shadows, "Cone-traced shadows instead of PCF");
  cmd->add_flag("--random-rotation", f.random_rotation, "Rotate the diffuse cones per pixel (hash of pixel, frame)");
  cmd->add_flag("--no-particles", f.no_particles, "Leave out the fire particles");
  cmd->add_flag("--no-diffuse", f.no_diffuse, "Skip the diffuse cones");
  cmd->add_flag("--no-specular", f.no_specular, "Skip the specular cone");
  cmd->add_option("--bounces", f.bounces, "Temporal multibounce frames (1 = direct light in voxels only)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--restitution", f.restitution, "Multibounce attenuation factor");
  cmd->add_option("--tolerance", f.tolerance, "Stop multibounce when the relative energy change is below this");
  cmd->add_option("--quality", f.quality, "Cone step = diameter x quality");
  cmd->add_option("--offset", f.offset, "Cone start offset in voxels");
  cmd->add_option("--aperture", f.aperture, "Diffuse cone aperture in degrees");
  cmd->add_option("--cone-count", f.cone_count, "Diffuse cones: 1 along the normal + N-1 tilted (1..16, default 5)");
  cmd->add_option("--cone-tilt", f.cone_tilt, "Tilt of the diffuse cones from the normal in degrees (0..90, default 45)");
  cmd->add_option("--time", f.time, "Time in seconds (particles)");
  cmd->add_option("--frame", f.frame, "Frame index (random cone rotation hash)");
  cmd->add_option("--msaa", f.msaa, "Samples of the GPU voxelizer rule (1, 4, 8)");
  cmd->add_option("--shadow-map-size", f.shadow_map_size, "Shadow map resolution");
  cmd->add_option("--light-model", f.light_model, "gltf or seed");
  cmd->add_option("--voxelizer", f.voxelizer, "conservative or gpu");
  cmd->add_option("--storage", f.storage, "rgba8 or rgba16f");
  cmd->add_option("--reduction", f.reduction, "exact, fixed or cas");
  cmd->add_option("--weighting", f.weighting, "Diffuse cone weights: cosine or seed");
}

// Flags become a JSON patch over the settings, so enum names and errors are the --config ones.
Settings apply_vct_flags(Settings s, const VctFlags& f) {
  nlohmann::json patch = nlohmann::json::object();
  if (f.aniso) patch["anisotropic"] = true;
  if (f.soft_shadows) patch["soft_shadows"] = true;
  if (f.random_rotation) patch["random_rotation"] = true;
  if (f.no_particles) patch["particles"] = false;
  if (f.no_diffuse) patch["diffuse_cones"] = false;
  if (f.no_specular) patch["specular_cones"] = false;
  if (f.bounces) patch["bounces"] = *f.bounces;
  if (f.msaa) patch["msaa_samples"] = *f.msaa;
  if (f.shadow_map_size) patch["shadow_map_size"] = *f.shadow_map_size;
  if (f.frame) patch["frame"] = *f.frame;
  if (f.restitution) patch["restitution"] = *f.restitution;
  if (f.tolerance) patch["convergence_tolerance"] = *f.tolerance;
  if (f.quality) patch["cone_quality"] = *f.quality;
  if (f.offset) patch["cone_offset_voxels"] = *f.offset;
  if (f.aperture) patch["diffuse_aperture_deg"] = *f.aperture;
  if (f.cone_count) patch["diffuse_cone_count"] = *f.cone_count;
  if (f.cone_tilt) patch["diffuse_cone_tilt_deg"] = *f.cone_tilt;
  if (f.time) patch["time"] = *f.time;
  if (f.light_model) patch["light_model"] = *f.light_model;
  if (f.voxelizer) patch["voxelizer"] = *f.voxelizer;
  if (f.storage) patch["storage"] = *f.storage;
  if (f.reduction) patch["reduction"] = *f.reduction;
  if (f.weighting) patch["diffuse_weighting"] = *f.weighting;
  nlohmann::json j = s.vct;
  j.merge_patch(patch);
  from_json(j, s.vct);
  validate_settings(s);
  return s;
}

// The facts of a GL run: a stage set directory or manifest ("facts"), or a render run.json
// ("facts" keyed by backend, the GL one preferred).
BackendFacts read_facts(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path file = fs::is_directory(path) ? fs::path(path) / "vct-stages.json" : fs::path(path);
  if (!fs::exists(file)) throw InputError(file.string(), "cannot read (--facts-from wants a stage set or a run.json)");
  try {
    const nlohmann::json j = read_bounded_json_file(file.string(), "--facts-from file");
    if (!j.is_object() || !j.contains("facts")) throw InputError(file.string(), "has no \"facts\" (--facts-from)");
    const nlohmann::json& f = j.at("facts");
    if (f.is_object() && f.contains("gl") && f.at("gl").is_object()) return f.at("gl").get<BackendFacts>();
    BackendFacts facts = f.get<BackendFacts>();
    if (facts.sample_positions.empty()) throw InputError(file.string(), "its facts list no sample positions");
    return facts;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string(), std::string("bad facts: ") + e.what());
  }
}

ivec2 parse_pixel(const std::string& text) {
  int x = 0, y = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d,%d%c", &x, &y, &extra) != 2) {
    throw InputError("--explain", "expected X,Y (two integers), got '" + text + "'");
  }
  return ivec2(x, y);
}

// The backend's frame, ready to run. Whatever the backend refuses (--explain off the reference,
// a setting only the reference runs, a GL device that does not exist, no GL at all) is refused
// here, before the run directory exists, so a refused render leaves no INCOMPLETE directory.
std::function<FrameResult()> prepare_frame(const Scene& scene, const Settings& s, const VctFlags& flags) {
  if (!flags.explain.empty() && flags.backend != "ref")
    throw InputError("--explain", "needs --backend ref (it re-traces the CPU cones)");
  if (flags.backend == "ref") {
    const std::vector<vec2> positions = flags.facts_from.empty() ? std::vector<vec2>{} : read_facts(flags.facts_from).sample_positions;
    return [&scene, &s, positions] { return render_ref_frame(scene, s, positions); };
  }
#ifdef VCT_HAVE_GL
  const vct::gl::GlOptions options{flags.gl.device, flags.gl.fault};
  vct::gl::check_gl_accepts(scene, s, options);
  auto context = std::make_shared<vct::gl::GlContext>(options.device);  // a missing device fails here
  vct::gl::require_conservative_raster(s.vct, context->renderer());  // a missing extension too
  return [&scene, &s, context, options] { return vct::gl::render_gl_frame(*context, scene, s, options); };
#else
  throw EnvironmentError("GL backend not built (no gl/gl_pipeline.h or no GL libraries at configure time)");
#endif
}

nlohmann::json scene_summary(const Scene& scene) {
  return {{"source", scene.source},
          {"triangles", scene.triangle_count()},
          {"vertices", scene.positions.size()},
          {"materials", scene.materials.size()},
          {"lights", scene.lights.size()},
          {"emitters", scene.emitters.size()},
          {"warnings", scene.stats.warnings},
          {"volume", {{"origin", {scene.volume.origin.x, scene.volume.origin.y, scene.volume.origin.z}},
                      {"size", scene.volume.size}}}};
}

void write_explain(RunDir& run, const Scene& scene, const FrameResult& frame, const VctSettings& s, ivec2 px) {
  const PixelExplanation e = explain_pixel(scene, frame, s, px.x, px.y);
  const std::string stem = "explain_" + std::to_string(px.x) + "_" + std::to_string(px.y);
  write_text_atomically(run.file(stem + ".json"), e.json.dump(1) + "\n");
  write_png_linear(run.file(stem + ".png"), e.picture, 0.0f, 1.0f);
}

// What the shared dump writer has no slot for: each diffuse cone's image (the multibounce frames
// before the last are the registry's voxel.frame.<frame>, dumped as multibounce_frame_<frame>).
void write_ref_extras(RunDir& run, const FrameResult& frame) {
  for (size_t i = 0; i < frame.images.diffuse_cones.size(); ++i) {
    run.write_color("diffuse_cone_" + std::to_string(i), frame.images.diffuse_cones[i]);
  }
}

void run_render(const std::string& scene_path, const CommonOptions& common, const VctFlags& flags) {
  const Settings flagged = apply_vct_flags(resolve_settings(common), flags);
  Scene loaded = load_scene_and_warn(scene_path, common.scene_load, flagged.vct);
  const Settings settings = fit_image_to_camera_and_warn(flagged, loaded, common);
  const Scene scene = std::move(loaded);
  std::optional<ivec2> explain;
  if (!flags.explain.empty()) {
    explain = parse_pixel(flags.explain);
    // Checked before the frame is rendered, so a typo costs nothing.
    if (explain->x < 0 || explain->y < 0 || explain->x >= settings.vct.width || explain->y >= settings.vct.height) {
      throw InputError("--explain", "pixel " + flags.explain + " is outside the " + std::to_string(settings.vct.width) +
                                        "x" + std::to_string(settings.vct.height) + " image");
    }
  }
  if (!flags.facts_from.empty()) read_facts(flags.facts_from);  // bad input fails before rendering
  // Predicted with the loaded scene (triangles, textures, alpha masks) before anything is rendered.
  // The GL backend's host memory is llvmpipe's and the frame it reads back, not the reference's
  // buffers (core/memory_budget.h, GlMemoryEstimate; docs/performance.md, "Validate's memory").
  const SceneFootprint footprint = scene_footprint(scene);
  const MemoryEstimate predicted = estimate_memory(settings, footprint);
  const bool gl = flags.backend == "gl";
  const GlMemoryEstimate predicted_gl = gl ? estimate_gl_memory(settings, footprint) : GlMemoryEstimate();
  const uint64_t predicted_total = gl ? predicted_gl.total() : predicted.total();
  if (gl) warn_if_memory_short(predicted_gl, "vct render");
  else warn_if_memory_short(predicted, "vct render");
  const std::function<FrameResult()> render_frame = prepare_frame(scene, settings, flags);
  // Locked before rendering, so a second process writing the same --out is refused at once.
  RunDir run(common.out.empty() ? default_out_dir("render", scene_path) : common.out, RunRole::Run);
  const FrameResult frame = render_frame();
  if (frame.images.final_image.empty()) throw EnvironmentError("backend '" + flags.backend + "' produced no frame");
  run.json()["command"] = "render";
  run.json()["backend"] = frame.backend;
  run.json()["settings"] = settings;
  run.json()["environment"] = environment_info();
  run.json()["scene"] = scene_summary(scene);
  run.json()["exposure"] = exposure_json(scene.exposure);
  // Keyed by backend, the shape the dump writer uses too.
  run.json()["multibounce_energy"][frame.backend] = frame.multibounce_energy;
  for (const auto& [key, value] : frame.info) run.json()["info"][frame.backend][key] = value;
  run.json()["facts"][frame.backend] = frame.facts;
  for (const auto& [stage, ms] : frame.timings_ms) run.add_timing(frame.backend, stage, ms);
  run.write_color("final", frame.images.final_image);
  if (flags.dump) {
    write_frame_dumps(run, frame, scene);
    write_ref_extras(run, frame);
    cmp::write_dump_manifest(run.path(), frame, settings.vct);  // a dumped run is a stage set too
  }
  if (flags.stage_set) {
    cmp::StageSet set = cmp::stage_set_from_frame(frame, settings.vct);
    cmp::write_stage_set(run.file("stages"), set);
  }
  if (explain) {
    write_explain(run, scene, frame, settings.vct, *explain);
  }
  // Predicted up front (validate_settings refuses what cannot fit) beside what the run used.
  run.json()["memory"] = {{"predicted_bytes", predicted_total},
                          {"predicted_voxel_bytes", gl ? predicted_gl.textures + predicted_gl.frame : predicted.voxels},
                          {"predicted_scene_bytes", gl ? predicted_gl.scene : predicted.scene},
                          {"predicted_fragments", fragment_count(footprint, settings.vct.grid)},  // Steiner's count
                          {"predicted", format_bytes(predicted_total)},
                          {"peak_rss_bytes", peak_rss_bytes()},
                          {"peak_rss", format_bytes(peak_rss_bytes())}};
  run.finish();
  std::printf("vct render: %s frame of %s in %.0f ms, memory predicted %s, peak RSS %s -> %s\n",
              frame.backend.c_str(), scene.source.c_str(),
              frame.timings_ms.count("total") ? frame.timings_ms.at("total") : 0.0,
              format_bytes(predicted_total).c_str(), format_bytes(peak_rss_bytes()).c_str(), run.path().c_str());
}

}  // namespace

void register_render(CLI::App& app, int& exit_code) {
  static std::string scene_storage;  // live as long as the process (CLI11 binds by reference);
  static CommonOptions common_storage;  // static, not new, so LeakSanitizer sees no leak
  static VctFlags flags_storage;
  auto* scene_path = &scene_storage;
  auto* common = &common_storage;
  auto* flags = &flags_storage;
  CLI::App* cmd = app.add_subcommand("render", "Render one VCT frame (no SCENE = built-in default scene)");
  cmd->add_option("scene", *scene_path, "glTF 2.0 file (.gltf or .glb)");
  add_common_flags(cmd, *common);
  add_scene_access_flag(cmd, common->scene_load);
  add_image_flags(cmd, *common);
  add_grid_flag(cmd, *common);
  add_vct_flags(cmd, *flags);
  cmd->callback([scene_path, common, flags, &exit_code]() {
    run_render(*scene_path, *common, *flags);
    exit_code = kExitOk;
  });
}

}  // namespace vct::app
