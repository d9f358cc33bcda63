// The native half of `import vct` (python/vct/__init__.py is the other): binds the libraries'
// own API — load_scene, Settings through their JSON form (core/settings.h), the CLI's backend
// runs (app/validate_run.h), stage sets (compare/stage_set.h), the judge (compare/judge.h) and
// measure_bias (compare/bias.h). Nothing is re-implemented here.
// Settings and verdicts cross as JSON text; __init__.py turns them into dicts. docs/python.md.
#include <cstdlib>
#include <optional>

#include <nanobind/nanobind.h>
#include <nanobind/stl/map.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <nlohmann/json.hpp>

#include "arrays.h"
#include "compare/bias.h"
#include "compare/judge.h"
#include "compare/stage_compare.h"
#include "compare/stage_set_frame.h"
#include "compare/stage_set.h"
#include "core/error.h"
#include "io/bounded_json.h"
#include "core/parallel.h"
#include "core/settings.h"
#include "io/image_io.h"
#include "io/nrrd.h"
#include "scene/exposure.h"
#include "scene/gltf_loader.h"
#include "compare_scene.h"
#include "validate_run.h"

namespace nb = nanobind;
using namespace nb::literals;

namespace vct::py {
namespace {

// A settings patch (JSON text of a dict, possibly partial) over `base`, range-checked like
// --config (load_settings_file): unknown keys, wrong types and out-of-range values throw InputError.
Settings settings_from_text(const std::string& text, const Settings& base = Settings{}) {
  // The one bounded reader: a dict nested 300 000 deep must not overflow merge_patch's recursion.
  const nlohmann::json patch = parse_bounded_json(text, "settings");
  if (!patch.is_object()) throw InputError("settings", "expected a dict like {'vct': {'grid': 64}}");
  nlohmann::json merged = base;
  merged.merge_patch(patch);
  Settings s;
  try {
    s = merged.get<Settings>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError("settings", e.what());
  }
  validate_settings(s);
  return s;
}

std::string settings_text(const Settings& s) { return nlohmann::json(s).dump(); }

// The set as a Python object carrying the frame's timings (StageSet has dynamic attributes).
nb::object frame_to_python(const app::BackendRun& run, const Settings& s) {
  nb::object o = nb::cast(cmp::stage_set_from_frame(*run.frame, s.vct));
  o.attr("timings_ms") = nb::cast(run.frame->timings_ms);
  o.attr("ms") = run.ms;
  o.attr("multibounce_energy") = nb::cast(run.frame->multibounce_energy);
  // The frame itself, for vct.compare(..., scene=...): the judge re-traces the cone stages on it
  // exactly as vct validate does on the live frame (a set read from disk is rebuilt instead).
  o.attr("_frame") = nb::cast(std::move(*run.frame));
  return o;
}

// The scene as the settings expose it, as the CLI renders it (docs/scenes.md, "Light units and
// exposure"): load_scene returns it unexposed; a copy is made only when the scale is not 1.
const Scene& exposed(const Scene& scene, const Settings& s, Scene& storage) {
  const ExposureApplied e = resolve_exposure(scene, s.vct.exposure, s.vct.exposure_ev100);
  if (e.scale == 1.0f || scene.exposure.scale != 1.0f) return scene;
  storage = scene;
  pre_expose(storage, e);
  return storage;
}

// `positions`: the GPU-rule voxelizer's sample positions (a GL set's facts, as vct validate takes
// them from its GL run); empty = the standard pattern.
nb::object render(const Scene& unexposed, const std::string& settings, bool gl,
                  const std::vector<vec2>& positions = {}) {
  const Settings s = settings_from_text(settings);
  Scene storage;
  const Scene& scene = exposed(unexposed, s, storage);
  app::BackendRun run;
  {
    nb::gil_scoped_release unlocked;
    set_thread_count(s.threads);
    run = gl ? app::run_gl_backend(scene, s) : app::run_ref_backend(scene, s, positions);
  }
  if (!run.ok()) {
    if (run.status.rfind("unavailable", 0) == 0) throw EnvironmentError("gl " + run.status);
    throw std::runtime_error((gl ? "gl " : "ref ") + run.status);
  }
  return frame_to_python(run, s);
}

struct PathTraceResult {
  std::map<std::string, Image> aovs;  // pt_full, pt_full_var, ... (compare/bias.h reads these)
  int spp = 0;
  double ms = 0.0;
};

void bind_stage_set(nb::module_& m) {
  nb::class_<cmp::StageSet>(m, "StageSet", nb::dynamic_attr(),
                            "Named stage outputs of one renderer (compare/stage_set.h). set[name] is a "
                            "float32 view into the set: images H x W x C, volumes D x H x W x C.")
      .def(nb::init<>())
      .def_rw("backend", &cmp::StageSet::backend)
      .def_rw("storage", &cmp::StageSet::storage)
      .def_rw("reduction", &cmp::StageSet::reduction)
      .def_prop_ro("info_json", [](const cmp::StageSet& s) { return s.info.dump(); })
      .def_prop_ro("facts_json", [](const cmp::StageSet& s) { return nlohmann::json(s.facts).dump(); })
      .def_prop_ro("image_names", [](const cmp::StageSet& s) {
        std::vector<std::string> n;
        for (const auto& kv : s.images) n.push_back(kv.first);
        return n;
      })
      .def_prop_ro("volume_names", [](const cmp::StageSet& s) {
        std::vector<std::string> n;
        for (const auto& kv : s.volumes) n.push_back(kv.first);
        return n;
      })
      .def("__contains__", [](const cmp::StageSet& s, const std::string& n) { return s.has(n); })
      .def("__len__", [](const cmp::StageSet& s) { return s.images.size() + s.volumes.size(); })
      .def("__getitem__",
           [](nb::handle self, const std::string& name) {
             cmp::StageSet& s = nb::cast<cmp::StageSet&>(self);
             if (auto i = s.images.find(name); i != s.images.end()) return image_view(i->second, self);
             if (auto v = s.volumes.find(name); v != s.volumes.end()) return volume_view(v->second, self);
             throw nb::key_error(("no stage '" + name + "' in this set").c_str());
           })
      // Adding, not replacing: arrays handed out earlier point into the stored stages.
      .def("set_image",
           [](cmp::StageSet& s, const std::string& name, const InputArray& a) {
             if (s.has(name)) throw InputError(name, "already in the set (stages are not replaced)");
             s.images[name] = image_from_array(a, name);
           },
           "name"_a, "array"_a)
      .def("set_volume",
           [](cmp::StageSet& s, const std::string& name, const InputArray& a) {
             if (s.has(name)) throw InputError(name, "already in the set (stages are not replaced)");
             s.volumes[name] = volume_from_array(a, name);
           },
           "name"_a, "array"_a);
}

void bind_path_trace(nb::module_& m) {
  nb::class_<PathTraceResult>(m, "PathTraceResult",
                              "The path tracer's AOVs (mean and _var per component), H x W x 3 views.")
      .def_ro("spp", &PathTraceResult::spp)
      .def_ro("ms", &PathTraceResult::ms)
      .def_prop_ro("names", [](const PathTraceResult& r) {
        std::vector<std::string> n;
        for (const auto& kv : r.aovs) n.push_back(kv.first);
        return n;
      })
      .def("__contains__", [](const PathTraceResult& r, const std::string& n) { return r.aovs.count(n) > 0; })
      .def("__getitem__", [](nb::handle self, const std::string& name) {
        PathTraceResult& r = nb::cast<PathTraceResult&>(self);
        auto i = r.aovs.find(name);
        if (i == r.aovs.end()) throw nb::key_error(("no AOV '" + name + "'").c_str());
        return image_view(i->second, self);
      });
}

void bind_functions(nb::module_& m) {
  nb::class_<FrameResult>(m, "_Frame", "A rendered frame (stages/stage_types.h), kept for the judge.");
  nb::class_<Scene>(m, "Scene", "A loaded scene (flat, world space; scene/scene.h).")
      .def_ro("source", &Scene::source)
      .def_prop_ro("triangle_count", [](const Scene& s) { return s.triangle_count(); })
      .def_prop_ro("light_count", [](const Scene& s) { return s.lights.size(); })
      .def_prop_ro("light_kinds", [](const Scene& s) {
        std::vector<std::string> kinds;
        for (const Light& l : s.lights) kinds.push_back(light_kind_name(l.kind));
        return kinds;
      }, "Each light's KHR_lights_punctual type: 'spot', 'point' or 'directional'.")
      .def_prop_ro("spot_light_count", [](const Scene& s) {
        size_t n = 0;
        for (const Light& l : s.lights) n += l.is_spot() ? 1 : 0;
        return n;
      });
  m.def("load_scene", [](const std::string& path) { return load_scene(path); }, "path"_a = "",
        "A .gltf/.glb file; '' = the built-in Cornell box.");
  m.def("_default_settings", []() { return settings_text(Settings{}); });
  m.def("_validate_defaults", []() { return settings_text(app::validate_defaults()); });
  m.def("_check_settings", [](const std::string& t) { return settings_text(settings_from_text(t)); });
  m.def("_apply_sweep_value", [](const std::string& t, const std::string& key, const std::string& value) {
    return settings_text(app::apply_sweep_value(settings_from_text(t), key, value));
  });
  m.def("_render_ref", [](const Scene& sc, const std::string& t, const cmp::StageSet* facts_from) {
    return render(sc, t, false, facts_from ? facts_from->facts.sample_positions : std::vector<vec2>{});
  }, "scene"_a, "settings"_a, "facts_from"_a.none());
  m.def("_render_gl", [](const Scene& sc, const std::string& t) { return render(sc, t, true); });
  m.def("_path_trace", [](const Scene& unexposed, const std::string& t) {
    const Settings s = settings_from_text(t);
    Scene storage;
    const Scene& sc = exposed(unexposed, s, storage);
    PathTraceResult r;
    {
      nb::gil_scoped_release unlocked;
      set_thread_count(s.threads);
      app::PtRun run = app::run_pt_backend(sc, s);
      if (!run.ok()) throw std::runtime_error("pt " + run.status);
      r.aovs = std::move(run.aovs);
      r.spp = run.spp;
      r.ms = run.ms;
    }
    return r;
  });
  m.def("read_stage_set", &cmp::read_stage_set, "path"_a,
        "A directory holding vct-stages.json (or the manifest itself), ours or an external renderer's.");
  m.def("write_stage_set", [](const std::string& dir, cmp::StageSet& s) { cmp::write_stage_set(dir, s); },
        "dir"_a, "stage_set"_a);
  m.def("read_image", [](const std::string& path) { return image_array(read_image(path)); }, "path"_a,
        "Any image OpenImageIO reads (EXR, PNG, ...) as H x W x C float32 (row 0 = top).");
  m.def("read_volume", [](const std::string& path) { return volume_array(read_nrrd(path)); }, "path"_a,
        "A NRRD volume (raw or gzip) as D x H x W x C float32.");
  m.def("read_path_trace", [](const std::string& dir) {
    PathTraceResult r;
    r.aovs = cmp::read_pt_aovs(dir);
    if (r.aovs.empty()) throw InputError(dir, "no pt_*.exr here");
    return r;
  });
  m.def("_compare", [](nb::handle reference_h, nb::handle test_h, size_t worst_n, const std::string& mask_dir,
                       const Scene* scene, const std::string& settings, const std::vector<int>& explain) {
    const auto& reference = nb::cast<const cmp::StageSet&>(reference_h);
    const auto& test = nb::cast<const cmp::StageSet&>(test_h);
    std::optional<FrameResult> rebuilt;
    const FrameResult* frame = nullptr;
    VctSettings vs;
    if (scene) {
      // The settings the test ran with: given, else its own manifest's (as vct compare --scene).
      vs = settings.empty() ? app::settings_of_test_set(test, "") : settings_from_text(settings).vct;
      if (nb::hasattr(test_h, "_frame")) frame = &nb::cast<const FrameResult&>(test_h.attr("_frame"));
      else frame = &rebuilt.emplace(cmp::frame_from_stage_set(test, *scene, vs, &reference));
    }
    cmp::Report rep;
    {
      nb::gil_scoped_release unlocked;
      const cmp::JudgeInputs in = scene ? cmp::JudgeInputs{scene, frame, &vs} : cmp::JudgeInputs{};
      rep = cmp::judge(reference, test, in, {worst_n, mask_dir, mask_dir.empty() ? "" : mask_dir + "/", explain});
    }
    return cmp::to_json(rep).dump();
  }, "reference"_a, "test"_a, "worst_n"_a, "mask_dir"_a, "scene"_a.none(), "settings"_a, "explain"_a);
  m.def("_bias", [](const cmp::StageSet& vct, const PathTraceResult& pt, double k) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& b : cmp::measure_bias(vct, pt.aovs, {k, "", ""})) j.push_back(cmp::to_json(b));
    return j.dump();
  });
  m.def("_settings_as_run_by_gl", [](const std::string& t, const cmp::StageSet& gl) {
    Settings s = settings_from_text(t);
    // app::settings_as_run_by_gl's rule, read from the set's typed facts (the frame is gone by
    // now): counts the settings cannot name are carried by the sample positions instead.
    const int n = gl.facts.msaa_samples;
    if (n == 1 || n == 4 || n == 8) s.vct.msaa_samples = n;
    validate_settings(s);
    return settings_text(s);
  });
}

}  // namespace
}  // namespace vct::py

NB_MODULE(_vct, m) {
  m.doc() = "VCT Oracle's C++ libraries (docs/python.md); use `import vct`, not this module.";
  // Bad input (settings, files) is a ValueError subclass naming what is wrong; a missing GL
  // context is a RuntimeError subclass, so scripts can skip GL where there is none.
  nb::exception<vct::InputError>(m, "InputError", PyExc_ValueError);
  nb::exception<vct::EnvironmentError>(m, "EnvironmentUnavailable", PyExc_RuntimeError);
  vct::py::bind_stage_set(m);
  vct::py::bind_path_trace(m);
  vct::py::bind_functions(m);
}
