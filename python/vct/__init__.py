"""VCT Oracle from Python (docs/python.md): load a scene, read and change settings as a dict,
render the CPU reference, the GL build and the path tracer, read every stage as a NumPy array,
compare two stage sets and measure bias, with the verdicts as plain data.

    import vct
    scene = vct.load_scene()                      # the built-in Cornell box
    s = vct.default_settings(); s["vct"]["grid"] = 32
    ref = vct.render_ref(scene, s)                # StageSet; ref["image.final"] is H x W x 3
    gl = vct.render_gl(scene, vct.settings_as_run_by_gl(s, ...))  # raises EnvironmentUnavailable
    report = vct.compare(ref, gl)                 # {"overall": "pass", "stages": [...], ...}

Everything here calls the C++ libraries (the native module vct._vct); settings cross as JSON, so
a dict is checked exactly like `vct render --config FILE.json`: unknown keys, wrong types and
out-of-range values raise vct.InputError (a ValueError) naming the key.
"""
import copy as _copy
import json as _json

from . import _vct
from ._vct import (EnvironmentUnavailable, InputError, PathTraceResult, Scene, StageSet,  # noqa: F401
                   load_scene, read_image, read_path_trace, read_stage_set, read_volume, write_stage_set)

__all__ = ["load_scene", "default_settings", "validate_defaults", "check_settings", "sweep_settings",
           "render_ref", "render_gl", "path_trace", "settings_as_run_by_gl", "compare", "bias",
           "read_stage_set", "write_stage_set", "read_path_trace", "read_image", "read_volume", "info", "facts", "copy_settings", "Scene", "StageSet",
           "PathTraceResult", "InputError", "EnvironmentUnavailable"]


def _text(settings):
    if settings is None:
        return "{}"
    if not isinstance(settings, dict):
        raise InputError("settings: expected a dict like {'vct': {'grid': 64}}, got %s" % type(settings).__name__)
    return _json.dumps(settings)


def default_settings():
    """Every setting with the defaults of `vct render` (core/settings.h), as a fresh dict."""
    return _json.loads(_vct._default_settings())


def validate_defaults():
    """The smaller defaults `vct validate` starts from (app/validate_run.cpp)."""
    return _json.loads(_vct._validate_defaults())


def check_settings(settings):
    """The complete settings a (possibly partial) dict means, checked; raises InputError."""
    return _json.loads(_vct._check_settings(_text(settings)))


def sweep_settings(settings, key, value):
    """Settings with one sweep value applied as `vct validate --sweep key=value` does (aliases
    grid, cones, aperture, quality; any vct.* key)."""
    return _json.loads(_vct._apply_sweep_value(_text(settings), str(key), str(value)))


def render_ref(scene, settings=None, facts_from=None):
    """One CPU reference frame; every stage in a StageSet (also .timings_ms, .ms). facts_from: a GL
    set whose driver's MSAA sample positions the voxelizer emulates (as `vct validate` and
    `vct render --facts-from` do); None = the standard pattern."""
    return _vct._render_ref(scene, _text(settings), facts_from)


def render_gl(scene, settings=None):
    """One GL 4.5 frame (EGL, headless); raises EnvironmentUnavailable without a GL context."""
    return _vct._render_gl(scene, _text(settings))


def settings_as_run_by_gl(settings, gl_set):
    """The settings GL actually ran (a driver may clamp the MSAA samples): render the reference
    with these, or every voxel stage differs for a reason that is not a GPU bug."""
    return _json.loads(_vct._settings_as_run_by_gl(_text(settings), gl_set))


def path_trace(scene, settings=None):
    """The path tracer's AOVs (settings["pt"]: width, height, spp, ...) as a PathTraceResult."""
    return _vct._path_trace(scene, _text(settings))


def compare(reference, test, worst_n=10, mask_dir="", scene=None, settings=None, explain=None):
    """Stage-by-stage verdicts of `test` against `reference` from the one judge (compare/judge.h),
    as data: {"overall", "first_failing", "stages": [{"stage", "verdict", "model", "bound",
    "admitted_by", "max_abs", "worst": [...], ...}]}. mask_dir: where error-mask PNGs go ("" = none).
    scene: the Scene both were rendered from; then the cone-traced and shading stages are judged on
    the test's own inputs, as `vct validate` does (the same report). settings: what the test ran
    with (default: the test set's own settings). explain: (x, y) or (x, y, z): each stage holding that
    element says in extra["explain"] which rule admitted it, with both values and the bound."""
    text = "" if settings is None else _text(settings)
    where = [int(c) for c in explain] if explain is not None else []
    return _json.loads(_vct._compare(reference, test, int(worst_n), str(mask_dir), scene, text, where))


def bias(vct_set, pt, k=3.0):
    """VCT against the path tracer per component (compare/bias.h): a list of dicts with rel_mse,
    mean_bias, relative_bias, ssim, fraction_beyond_k_sigma, significant, ..."""
    return _json.loads(_vct._bias(vct_set, pt, float(k)))


def info(stage_set):
    """A stage set's free-form info (GL_RENDERER, counts, ...) as a dict."""
    return _json.loads(stage_set.info_json)


def facts(stage_set):
    """What the backend reported about itself (typed BackendFacts: renderer, msaa_samples, sample
    positions, ...) as a dict."""
    return _json.loads(stage_set.facts_json)


def copy_settings(settings):
    """A deep copy (settings dicts are nested)."""
    return _copy.deepcopy(settings)
