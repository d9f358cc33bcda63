#!/usr/bin/env python3
"""make_report.py RUN_DIR [RUN_DIR...]: writes RUN_DIR/report/index.html for each run directory
(ours from `vct validate`, or a stage directory with vct-stages.json), a static page that opens
from disk: images are files beside it, CSS/JS are inline, float data is embedded (docs/report.md).
Prints each index.html path. Missing parts are shown as missing, never as errors."""
import html
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vct_report import attribution, flip_batch, registry, runio, svg  # noqa: E402
from vct_report import glance as glance_mod  # noqa: E402
from vct_report.glance import glance  # noqa: E402
from vct_report.part_times import TIMES, cpu_ms  # noqa: E402
from vct_report.walkthrough import STAGES  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
E = html.escape


def missing(what):
    return '<div class="missing">missing: %s</div>' % E(what)


class Page:
    def __init__(self, run):
        self.run = run
        self.out_dir = os.path.join(run.path, "report")
        os.makedirs(self.out_dir, exist_ok=True)
        self.parts = []

    def rel(self, path):
        return os.path.relpath(path, self.out_dir)

    def img(self, path, caption, cls="thumb"):
        if not path:
            return '<figure class="%s">%s<figcaption>%s</figcaption></figure>' % (cls, missing(caption), E(caption))
        return '<figure class="%s"><img src="%s" alt="%s"><figcaption>%s</figcaption></figure>' % (
            cls, E(self.rel(path)), E(caption), E(caption))


def verdict_cell(v):
    return '<td class="v-%s">%s</td>' % (E(v), E(v))


def fmt(x, spec="%.4g"):
    if x is None:
        return "-"
    if isinstance(x, (int, float)):
        return spec % x
    return E(str(x))


# ---------------------------------------------------------------- summary
def summary(p):
    j = p.run.json
    scene = j.get("scene", {})
    env = j.get("environment", {})
    backends = j.get("backends", {})
    # The GL side's typed facts (run.json backends.gl.facts, or a stage set's manifest "facts").
    gl_facts = backends.get("gl", {}).get("facts", {})
    for side, m in p.run.sets.items():
        gl_facts = gl_facts or (m.get("facts", {}) if side != "ref" else {})
    rows = []
    for name in ("ref", "gl", "pt"):
        b = backends.get(name)
        if b is None and name in p.run.sets:
            b = {"status": "ok (stage set)", "ms": None}
        if b is None:
            rows.append("<tr><td>%s</td><td class='v-missing'>missing</td><td></td></tr>" % name)
            continue
        ok = str(b.get("status", "")).startswith("ok")
        rows.append("<tr><td>%s</td><td class='v-%s'>%s</td><td class='num'>%s</td></tr>" % (
            name, "pass" if ok else "missing", E(str(b.get("status"))), fmt((b.get("ms") or 0) / 1000, "%.2f s") if b.get("ms") else "-"))
    s = j.get("settings", {})
    out = ['<h2 id="summary">Summary</h2><table>']
    out.append("<tr><th>scene</th><td>%s (%s triangles, %s lights)</td></tr>" % (
        E(str(scene.get("source", "?"))), fmt(scene.get("triangles")), fmt(scene.get("lights"))))
    vct = s.get("vct", {})
    out.append("<tr><th>settings</th><td>%sx%s, grid %s^3, %s, %s, bounces %s; path tracer %s spp</td></tr>" % (
        fmt(vct.get("width")), fmt(vct.get("height")), fmt(vct.get("grid")), E(str(vct.get("storage", "?"))),
        E(str(vct.get("reduction", "?"))), fmt(vct.get("bounces")), fmt(s.get("pt", {}).get("spp"))))
    out.append("<tr><th>machine</th><td>%s, %s cores, %s threads; %s; %s</td></tr>" % (
        E(str(env.get("cpu", "?"))), fmt(env.get("cores")), fmt(env.get("threads")), E(str(env.get("os", "?"))),
        E(str(env.get("compiler", "?")))))
    renderer = gl_facts.get("renderer") or "not available in this run"
    if gl_facts.get("device"):
        renderer += " (%s)" % gl_facts["device"]
    out.append("<tr><th>GL renderer</th><td>%s</td></tr>" % E(str(renderer)))
    out.append("</table><table><tr><th>backend</th><th>status</th><th>time</th></tr>%s</table>" % "".join(rows))
    out.append("<details><summary>all settings (run.json)</summary><pre class='settings'>%s</pre></details>" % E(json.dumps(s, indent=1)))
    out.append(verdict_table(p))
    return "".join(out)


def verdict_table(p):
    v = p.run.json.get("verdicts") or load_compare_json(p.run)
    if not v or not v.get("stages"):
        note = (v or {}).get("note", "no GPU run to compare")
        return '<h3>GPU vs CPU verdicts</h3>' + missing("verdicts (%s)" % note)
    first = v.get("first_failing", "")
    out = ['<h3 id="verdicts">GPU vs CPU verdicts: <span class="v-%s">&nbsp;%s&nbsp;</span></h3>' % (E(v.get("overall", "")), E(v.get("overall", "")))]
    if first:
        out.append('<p class="firstfail">First failing stage: %s (later failures are usually its consequence).</p>' % E(first))
    out.append("<table><tr><th>stage</th><th>verdict</th><th>model</th><th>bound</th><th>result</th><th>admitted by</th><th>max |d|</th><th>worst offenders (reference / test)</th><th>mask</th></tr>")
    for st in v["stages"]:
        cls = ' class="first-fail"' if st["stage"] == first else ""
        worst = st.get("worst", [])[:5]
        wtxt = "<br>".join("%s: %s / %s" % (E(str(w["at"])), E(", ".join("%.4g" % x for x in w["reference"])),
                                             E(", ".join("%.4g" % x for x in w["test"]))) for w in worst)
        if worst:
            wtxt = "<details><summary>%d listed</summary><div class='offenders'>%s</div></details>" % (len(st.get("worst", [])), wtxt)
        mask = st.get("mask")
        mpath = os.path.join(p.run.path, mask) if mask else None
        mcell = '<a href="%s"><img src="%s" style="width:64px"></a>' % (E(p.rel(mpath)), E(p.rel(mpath))) if mpath and os.path.exists(mpath) else ""
        out.append("<tr%s><td>%s</td>%s<td>%s</td><td>%s</td><td>%s</td><td>%s</td><td class='num'>%s</td><td>%s</td><td>%s</td></tr>" % (
            cls, E(st["stage"]), verdict_cell(st["verdict"]), E(st.get("model", "")), E(st.get("bound", "")),
            E(st.get("note", "")), E(glance_mod.admitted_text(st, top=8)), fmt(st.get("max_abs")), wtxt, mcell))
    out.append("</table>")
    out.append(mask_legend(v.get("mask_legend") or []))
    return "".join(out)


def mask_legend(legend):
    """One legend for every mask, images and volumes (compare/admission.h's colours)."""
    if not legend:
        return ""
    items = "".join('<span class="legend-item"><span class="swatch" style="background:rgb(%d,%d,%d)"></span>%s</span> ' % (
        int(l["colour"][0]), int(l["colour"][1]), int(l["colour"][2]), E(l["rule"])) for l in legend)
    return '<p class="small" id="mask-legend"><b>Masks:</b> %s; dimmed reference (images) or dim grey occupied voxels (volumes): within the bound.</p>' % items


def load_compare_json(run):
    j = runio.load_json(os.path.join(run.path, "compare.json"))
    return j.get("verdicts") if j else None


# ---------------------------------------------------------------- final images + viewer
def final_images(p):
    run = p.run
    cands = [("ref", run.stage_file("ref", registry.FINAL), run.stage_file("ref", registry.FINAL, False)),
             ("gl", run.stage_file("gl", registry.FINAL), run.stage_file("gl", registry.FINAL, False)),
             ("pt", run.file("pt", "pt_full.png"), run.file("pt", "pt_full.exr"))]
    for side in run.sets:
        if side not in ("ref", "gl"):
            cands.append((side, run.stage_file(side, registry.FINAL), run.stage_file(side, registry.FINAL, False)))
    out = ['<h2 id="final">Final images</h2><div class="row">']
    labels = {"ref": "CPU reference (VCT)", "gl": "GL (VCT)", "pt": "path tracer (ground truth)"}
    for name, png, _ in cands:
        out.append(p.img(png, labels.get(name, name), "wide" if False else "thumb"))
    out.append("</div>")
    out.append('<p class="note" id="display-transform">Display transform: <b>Khronos PBR Neutral</b> tone mapper, '
               'then the sRGB curve (previews and the viewer below); the EXR and NRRD data stay linear '
               '(luminance in cd/m&sup2; times run.json&rsquo;s exposure scale, docs/scenes.md).</p>')
    floats = {}
    for name, _, exr in cands:
        arr = runio.read_exr(exr) if exr else None
        if arr is not None:
            floats[name] = runio.half_b64(arr)
    out.append('<h3 id="diff">Difference view</h3><div class="viewer"><div class="controls">'
               '<label>A <select id="viewer-a"></select></label><label>B <select id="viewer-b"></select></label>'
               '<label>view <select id="viewer-mode"><option value="a">A</option><option value="b">B</option>'
               '<option value="flip">flip A/B (click or auto)</option><option value="diff">|A-B| heat</option>'
               '<option value="reldiff">|A-B|/(A+0.01) heat</option></select></label>'
               '<label>exposure <input id="viewer-ev" type="range" min="-6" max="6" step="0.25" value="0"> <span id="viewer-ev-out"></span></label>'
               '</div><canvas id="viewer-canvas" width="256" height="256"></canvas><div id="viewer-info"></div></div>')
    if not floats:
        out.append(missing("float data for the viewer (no EXR readable: flip-evaluator missing?)"))
    out.append("<script>window.VCT_FLOAT_IMAGES=%s;</script>" % json.dumps(floats))
    return "".join(out)


# ---------------------------------------------------------------- bias
FLIP_RESULTS = {}  # out png -> mean FLIP (or None), filled by precompute_flips


def flip_mode(run):
    """Which FLIP maps the page computes: $VCT_REPORT_FLIP if set, else what `vct validate --flip`
    recorded in run.json, else none. FLIP is a perceptual side metric (no verdict uses it) and
    HDR-FLIP costs seconds per 256^2 map, so it is opt-in (docs/report.md, docs/performance.md)."""
    mode = os.environ.get("VCT_REPORT_FLIP") or (run.json.get("report_options") or {}).get("flip") or "none"
    return mode if mode in ("full", "all", "none") else "none"


def flip_components(mode, r):
    """Whether component row r gets a FLIP map under `mode` (full: the full image only, all, none)."""
    return mode == "all" or (mode == "full" and r.get("component") == "full")


FLIP_OPT_IN = ("not computed: FLIP is opt-in (<code>vct validate --flip full</code> for the full images, "
               "<code>--flip all</code> for every component; or <code>VCT_REPORT_FLIP=full</code> when rebuilding "
               "with report/make_report.py)")


def flip_jobs(p):
    """(pt_exr, vct_exr, out_png) of every FLIP map the bias section shows."""
    jobs = []
    for side, rows in (p.run.json.get("bias") or {}).items():
        for r in rows:
            if not r.get("available") or not flip_components(flip_mode(p.run), r):
                continue
            vct_exr, pt_exr = p.run.stage_file(side, r["vct"], False), p.run.file("pt", r["pt"] + ".exr")
            if vct_exr and pt_exr:
                jobs.append((pt_exr, vct_exr, os.path.join(p.out_dir, "flip_%s.png" % (side + "_" + r["component"]))))
    return jobs


def precompute_flips(p):
    """Every FLIP of the page in parallel child processes (vct_report/flip_batch.py)."""
    t0, c0 = time.perf_counter(), cpu_ms()
    FLIP_RESULTS.update(flip_batch.run_all(flip_jobs(p)))
    TIMES.nested("FLIP", 1000 * (time.perf_counter() - t0), cpu_ms() - c0)


def flip_for(run, comp, vct_exr, pt_exr, out_dir):
    """Mean HDR-FLIP and its map (computed by precompute_flips, see vct_report/flip_one.py)."""
    if not vct_exr or not pt_exr:
        return None, None
    path = os.path.join(out_dir, "flip_%s.png" % comp)
    mean = FLIP_RESULTS.get(path)
    if mean is None:
        return None, None
    return mean, path if os.path.exists(path) else None


def bias_section(p):
    run = p.run
    b = run.json.get("bias")
    out = ['<h2 id="bias">Bias against the path tracer</h2>']
    if not b:
        return "".join(out) + missing("bias (needs the CPU reference and the path tracer in this run)")
    precompute_flips(p)
    mode = flip_mode(run)
    out.append("<p>Reference = path tracer; relMSE = mean((VCT-PT)^2/(PT^2+eps)) with eps = 0.01; "
               "mean bias = mean(VCT-PT); relative bias = sum(VCT-PT)/sum(PT); SSIM on luminance (Gaussian 11x11); "
               "FLIP (HDR, flip-evaluator); noise-aware: fraction of pixels with |VCT-PT| > 3 sigma_PT (pooled 5x5 "
               "half-split variance) against what PT noise alone gives (Student t, 24 dof).</p>")
    out.append('<p id="flip-note">FLIP: %s.</p>' % (
        FLIP_OPT_IN if mode == "none" else "HDR-FLIP of %s against the path tracer" % (
            "the full image" if mode == "full" else "every component")))
    for side, rows in b.items():
        out.append("<h3>%s vs path tracer</h3><table><tr><th>component</th><th>VCT</th><th>PT</th><th>relMSE</th>"
                   "<th>mean bias</th><th>rel. bias</th><th>SSIM</th><th>FLIP</th><th>&gt;3&sigma;</th><th>noise alone</th>"
                   "<th>mean z</th><th>judgement</th></tr>" % E(side))
        pics = []
        for r in rows:
            if not r.get("available"):
                out.append("<tr><td>%s</td><td colspan=11 class='v-missing'>%s</td></tr>" % (E(r["component"]), E(r.get("note", ""))))
                continue
            vct_exr = run.stage_file(side, r["vct"], False)
            mean_flip, flip_png = flip_for(run, side + "_" + r["component"], vct_exr, run.file("pt", r["pt"] + ".exr"), p.out_dir)
            out.append("<tr><td>%s</td><td>%s</td><td>%s</td><td class=num>%s</td><td class=num>%s</td><td class=num>%s</td>"
                       "<td class=num>%s</td><td class=num>%s</td><td class=num>%s</td><td class=num>%s</td><td class=num>%s</td>"
                       "<td class='v-%s'>%s</td></tr>" % (
                           E(r["component"]), E(r["vct"]), E(r["pt"]), fmt(r.get("rel_mse")), fmt(r.get("mean_bias")),
                           fmt(100 * r.get("relative_bias", 0), "%+.2f%%"), fmt(r.get("ssim"), "%.4f"),
                           fmt(mean_flip, "%.4f") if mean_flip is not None else (
                               "n/a" if flip_components(mode, r) else "not computed"),
                           fmt(100 * r.get("fraction_beyond_k_sigma", 0), "%.2f%%"), fmt(100 * r.get("expected_fraction", 0), "%.2f%%"),
                           fmt(r.get("mean_bias_z"), "%.1f"), "warn" if r.get("significant") else "pass",
                           "bias beyond PT noise" if r.get("significant") else "within PT noise"))
            heat = os.path.join(run.path, r["heatmap"]) if r.get("heatmap") else None
            z = os.path.join(run.path, r["zmap"]) if r.get("zmap") else None
            pics.append('<div><b>%s</b><div class="row">%s%s%s%s%s</div></div>' % (
                E(r["component"]), p.img(run.stage_file(side, r["vct"]), "VCT " + r["vct"]),
                p.img(run.file("pt", r["pt"] + ".png"), "PT " + r["pt"]),
                p.img(heat if heat and os.path.exists(heat) else None, "signed rel. error (blue: VCT darker, red: brighter)"),
                p.img(z if z and os.path.exists(z) else None, "z = (VCT-PT)/sigma, +-6 full scale"),
                p.img(flip_png, "FLIP error map") if flip_png else ""))
        out.append("</table>")
        out.append("<details %s><summary>heat maps (%s)</summary>%s</details>" % ("open" if side == "ref" else "", E(side), "".join(pics)))
    return "".join(out)


def backend_timings(j):
    """run.json's per-backend stage times ({"ref": {...}, "gl": {...}}); other commands' run.json
    (vct metamorphic, vct attribute) keep scalars such as a total there, which are not per stage."""
    return {b: t for b, t in (j.get("timings_ms") or {}).items() if isinstance(t, dict)}


# ---------------------------------------------------------------- walkthrough
def walkthrough(p):
    run = p.run
    j = run.json
    vct = j.get("settings", {}).get("vct", {})
    times = backend_timings(j)
    verdicts = {s["stage"]: s for s in (j.get("verdicts") or {}).get("stages", [])}
    out = ['<h2 id="walkthrough">Walkthrough: the pipeline stage by stage</h2>']
    reg = registry.from_run(j)
    for key, title, text, settings, timing_key in STAGES:
        prefixes = reg.step_prefixes(key)
        body = ['<div class="stage" id="stage-%s"><h3>%s</h3><p>%s</p>' % (key, E(title), E(text))]
        body.append('<div class="settings">%s</div>' % " &middot; ".join(
            "%s = %s" % (E(k), E(json.dumps(vct[k]))) for k in settings if k in vct))
        if timing_key:
            t = ["%s %.2f ms" % (b, times[b][timing_key]) for b in ("ref", "gl") if timing_key in times.get(b, {})]
            if t:
                body.append("<div>time: %s</div>" % E(", ".join(t)))
        stage_names = [s for s in (run.stages("ref") or run.stages("gl")) if any(s == pre or (pre.endswith(".") and s.startswith(pre)) for pre in prefixes)]
        figs = []
        for st in stage_names:
            for side in ("ref", "gl"):
                if side in run.sets:
                    figs.append(p.img(run.stage_file(side, st), "%s: %s" % (side, st)))
            if st in verdicts:
                v = verdicts[st]
                figs.append('<div><table><tr><th>%s</th>%s</tr><tr><td colspan=2>%s<br>%s</td></tr></table></div>' % (
                    E(st), verdict_cell(v["verdict"]), E(v.get("bound", "")), E(v.get("note", ""))))
        if key == "voxelize":
            figs.append(voxel_view(p))
            for extra in registry.VOXEL_DERIVED:
                if extra in verdicts:
                    v = verdicts[extra]
                    figs.append('<div><table><tr><th>%s</th>%s</tr><tr><td colspan=2>%s</td></tr></table></div>' % (
                        E(extra), verdict_cell(v["verdict"]), E(v.get("note", ""))))
        if key == "explain":
            ex = runio.load_json(os.path.join(run.path, "explain", "explain.json"))
            figs.append(p.img(run.file("explain", "explain.png"), "cones of the explained pixel over a slice of the grid", "wide"))
            if ex:
                figs.append(explain_table(ex))
        if key == "multibounce":
            mb = j.get("multibounce_energy", {})
            figs.append(svg.line_plot("voxel energy per multibounce frame", list(range(1, 1 + max((len(v) for v in mb.values()), default=0))),
                                      [(k, v) for k, v in mb.items()], "frame", "total voxel radiance") if mb else missing("multibounce energy"))
            # Every frame judged on the test's own previous frame (docs/compare.md, "Every multibounce
            # frame is judged"): each earlier frame's voxels and the energy sequence, the frame named.
            for st in sorted((s for s in verdicts if s.startswith("voxel.frame.")), key=lambda s: int(s.rsplit(".", 1)[1])) + \
                    [s for s in ("voxel.energy",) if s in verdicts]:
                v = verdicts[st]
                figs.append('<div><table><tr><th>%s</th>%s</tr><tr><td colspan=2>%s<br>%s</td></tr></table></div>' % (
                    E(st), verdict_cell(v["verdict"]), E(v.get("bound", "")), E(v.get("note", ""))))
        if not figs:
            figs.append(missing("%s (not produced in this run)" % title))
        body.append('<div class="row">%s</div></div>' % "".join(figs))
        out.append("".join(body))
    return "".join(out)


def explain_table(ex):
    # Every cone: the diffuse set has diffuse_cone_count of them (up to 16), then specular and shadow cones.
    rows = []
    for c in ex.get("cones", []):
        rows.append("<tr><td>%s %s</td><td>%s</td><td class=num>%.4g</td><td class=num>%d</td><td>%s</td></tr>" % (
            E(str(c.get("kind"))), E(str(c.get("index"))), E(", ".join("%.2f" % d for d in c.get("direction", []))),
            float(c.get("weight", 1.0)), len(c.get("samples", [])),
            E(", ".join("%.3f" % d for d in c.get("result_rgba", [])))))
    px = ex.get("pixel", "")
    return ('<div><b>pixel %s</b><table><tr><th>cone</th><th>direction</th><th>weight</th><th>samples</th>'
            '<th>result rgba</th></tr>%s</table></div>') % (E(str(px)), "".join(rows))


def voxel_view(p):
    run = p.run
    side = "ref" if "ref" in run.sets else next(iter(run.sets), None)
    path = run.stage_file(side, registry.VOXEL_RADIANCE, False) if side else None
    vol = runio.read_nrrd(path) if path else None
    if vol is None:
        return missing("voxel radiance volume for the 3D view")
    n = vol.shape[0]
    alpha = vol[..., 3] if vol.shape[3] >= 4 else vol[..., 0]
    zz, yy, xx = np.nonzero(alpha > 0)
    step = max(1, int(np.ceil(len(xx) / 30000)))
    xs, ys, zs = xx[::step], yy[::step], zz[::step]
    # All points at once (a per-point loop was most of the walkthrough's time at 128^3).
    c = vol[zs, ys, xs, :3]
    c = c / (1.0 + c)  # Reinhard, enough to tell surfaces apart
    rgb = (np.clip(c ** (1 / 2.2), 0, 1) * 255).astype(np.int64)
    pts = [[int(x), int(y), int(z), "%02x%02x%02x" % (r, g, b)]
           for x, y, z, (r, g, b) in zip(xs.tolist(), ys.tolist(), zs.tolist(), rgb.tolist())]
    return ('<figure><canvas id="voxel-canvas" width="360" height="360"></canvas><figcaption>occupied voxels (%d of %d shown), '
            'turn: <input id="voxel-rot" type="range" min="-180" max="180" value="30"></figcaption></figure>'
            '<script>window.VCT_VOXELS=%s;</script>') % (len(pts), len(xx), json.dumps({"n": int(n), "points": pts}, separators=(",", ":")))


# ---------------------------------------------------------------- performance
def seed_tables():
    """The seed report's published performance tables: data in the repository
    (vct_report/seed_tables.json names its source), not read from anywhere else."""
    return runio.load_json(os.path.join(HERE, "vct_report", "seed_tables.json"))


def performance(p):
    j = p.run.json
    times = backend_timings(j)
    out = ['<h2 id="performance">Performance</h2>']
    stages = sorted({k for b in times.values() for k in b})
    if stages:
        out.append("<h3>This run: per-stage time (ms)</h3><table><tr><th>stage</th><th>CPU reference</th><th>GL</th></tr>")
        for s in stages:
            out.append("<tr><td>%s</td><td class=num>%s</td><td class=num>%s</td></tr>" % (
                E(s), fmt(times.get("ref", {}).get(s), "%.2f"), fmt(times.get("gl", {}).get(s), "%.2f")))
        out.append("</table>")
    else:
        out.append(missing("stage timings"))
    out.append(sweeps(p))
    seed = seed_tables()
    if not seed:
        out.append(missing("the seed's tables (vct_report/seed_tables.json)"))
        return "".join(out)
    out.append("<h3>The seed's tables beside ours</h3><p class='small'>Source: %s Machine: %s. Times in %s.</p>" % (
        E(seed["source"]), E(seed["machine"]), E(seed["unit"])))
    ours_vox = {}
    ours_cone = {}
    for sw in j.get("sweeps", []):
        if sw.get("key") == "grid":
            for r in sw["rows"]:
                ours_vox[str(r["value"])] = (r.get("ref_timings_ms", {}).get("voxelize"), r.get("gl_timings_ms", {}).get("voxelize"))
                ours_cone[str(r["value"])] = (r.get("ref_timings_ms", {}).get("indirect_cones"), r.get("gl_timings_ms", {}).get("indirect_cones"))
    if "voxelization" in seed:
        out.append("<table><tr><th>grid</th><th>seed: no HDR, no TM</th><th>seed: HDR, no TM</th><th>seed: HDR + TM</th>"
                   "<th>ours ref voxelize</th><th>ours GL voxelize</th></tr>")
        for row in seed["voxelization"]["rows"]:
            o = ours_vox.get(str(row[0]), (None, None))
            out.append("<tr><td>%d</td>%s<td class=num>%s</td><td class=num>%s</td></tr>" % (
                row[0], "".join("<td class=num>%.2f</td>" % c for c in row[1:]), fmt(o[0], "%.2f"), fmt(o[1], "%.2f")))
        out.append("</table>")
    if "cone_tracing" in seed:
        out.append("<table><tr><th>grid</th><th>seed cone tracing (HDR)</th><th>ours ref cones</th><th>ours GL cones</th></tr>")
        for g, ms in seed["cone_tracing"]["rows"]:
            o = ours_cone.get(str(g), (None, None))
            out.append("<tr><td>%d</td><td class=num>%.2f</td><td class=num>%s</td><td class=num>%s</td></tr>" % (g, ms, fmt(o[0], "%.2f"), fmt(o[1], "%.2f")))
        out.append("</table>")
    def ours_pair(key, stage):
        """Our frame/stage times for a false,true sweep of `key`, as table rows (ref, gl)."""
        rows = ""
        for sw in j.get("sweeps", []):
            if sw.get("key") != key:
                continue
            by = {str(r["value"]).lower(): r for r in sw["rows"]}
            for side in ("ref", "gl"):
                vals = [by.get(v, {}).get(side + "_timings_ms", {}).get(stage) for v in ("false", "true")]
                rows += "<tr><td>ours %s (%s)</td><td class=num>%s</td><td class=num>%s</td></tr>" % (
                    side, E(stage), fmt(vals[0], "%.2f"), fmt(vals[1], "%.2f"))
        return rows
    if "aniso" in seed:
        out.append("<table><tr><th></th><th>isotropic</th><th>anisotropic</th></tr><tr><td>seed</td><td class=num>%s</td><td class=num>%s</td></tr>%s</table>" % (
            fmt(seed["aniso"]["row"][0], "%.2f"), fmt(seed["aniso"]["row"][1], "%.2f"), ours_pair("anisotropic", "indirect_cones")))
    if "culling" in seed:
        out.append("<table><tr><th></th><th>no occlusion culling</th><th>with depth pre-pass</th></tr><tr><td>seed</td><td class=num>%s</td><td class=num>%s</td></tr>%s</table>" % (
            fmt(seed["culling"]["row"][0], "%.2f"), fmt(seed["culling"]["row"][1], "%.2f"), ours_pair("depth_prepass", "total")))
    out.append("<p>Ours for these rows: <code>vct bench</code> and <code>vct validate --sweep grid=32,64,128,256</code> / "
               "<code>--sweep anisotropic=false,true</code> / <code>--sweep depth_prepass=false,true</code> fill them.</p>")
    return "".join(out)


def sweeps(p):
    sw = p.run.json.get("sweeps")
    if not sw:
        return "<h3>Sweeps</h3>" + missing("sweeps (run with --sweep grid=64,128,256 ...)")
    out = []
    for s in sw:
        key, rows = s["key"], s["rows"]
        comps = []
        for r in rows:
            for b in r.get("bias", []):
                if b.get("available") and b["component"] not in comps:
                    comps.append(b["component"])
        out.append("<h3>Sweep: %s</h3><table><tr><th>%s</th><th>ref ms</th><th>GL ms</th><th>GL verdict</th>%s</tr>" % (
            E(key), E(key), "".join("<th>%s relMSE / rel. bias</th>" % E(c) for c in comps)))
        for r in rows:
            bias = {b["component"]: b for b in r.get("bias", []) if b.get("available")}
            out.append("<tr><td>%s</td><td class=num>%s</td><td class=num>%s</td><td>%s</td>%s</tr>" % (
                E(str(r["value"])), fmt(r.get("ref_ms"), "%.1f"), fmt(r.get("gl_ms"), "%.1f"),
                E(str(r.get("gl_verdict", r.get("gl_status", "-")))),
                "".join("<td class=num>%s / %s</td>" % (fmt(bias[c]["rel_mse"]), fmt(100 * bias[c]["relative_bias"], "%+.1f%%"))
                        if c in bias else "<td>-</td>" for c in comps)))
        out.append("</table>")
        xs = [str(r["value"]) for r in rows]
        series = [(c, [next((b["rel_mse"] for b in r.get("bias", []) if b.get("component") == c and b.get("available")), None) for r in rows]) for c in comps]
        tseries = [("ref", [r.get("ref_ms") for r in rows])]
        if any(r.get("gl_ms") for r in rows):
            tseries.append(("gl", [r.get("gl_ms") for r in rows]))
        out.append('<div class="row">%s%s</div>' % (svg.line_plot("relMSE vs " + key, xs, series, key, "relMSE", logy=True),
                                                      svg.line_plot("frame time vs " + key, xs, tseries, key, "ms", logy=True)))
    return "".join(out)


# ---------------------------------------------------------------- page
def build(run_dir):
    run = runio.Run(run_dir)
    if not run.json and not run.sets:
        raise SystemExit("make_report.py: %s: neither run.json nor vct-stages.json here" % run_dir)
    p = Page(run)
    css = open(os.path.join(HERE, "vct_report", "style.css")).read()
    js = open(os.path.join(HERE, "vct_report", "viewer.js")).read()
    scene = run.json.get("scene", {}).get("source", os.path.basename(run.path))
    # The first screen answers the question (vct_report/glance.py); the long tables follow.
    verdicts = run.json.get("verdicts") or load_compare_json(run)
    sections = [TIMES.run(name, fn, p) for name, fn in (("first screen", lambda page: glance(page, verdicts)),
                                                        ("summary and verdicts", summary), ("final images", final_images),
                                                        ("bias tables and heat maps", bias_section),
                                                        ("error budget", lambda page: attribution.section(page, missing)),
                                                        ("walkthrough", walkthrough), ("performance", performance))]
    doc = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>VCT Oracle: %s</title><style>%s</style></head><body>" % (E(str(scene)), css),
           "<header><h1>VCT Oracle report: %s</h1><div class='sub' title='%s'>run %s</div></header>" % (
               E(str(scene)), E(run.path), E(os.path.basename(run.path))),
           "<nav><a href='#glance'>at a glance</a><a href='#summary'>summary</a><a href='#verdicts'>verdicts</a><a href='#final'>final images</a><a href='#bias'>bias</a><a href='#attribution'>error budget</a>"
           "<a href='#walkthrough'>walkthrough</a><a href='#performance'>performance</a></nav><main>",
           "".join(sections),
           "<p>Report status (for tests): <code id='status' data-ok='pending'>pending</code></p>",
           "</main><script>%s</script></body></html>" % js]
    index = os.path.join(p.out_dir, "index.html")
    tmp = index + ".tmp"
    with open(tmp, "w") as f:
        f.write("".join(doc))
    os.replace(tmp, index)
    TIMES.write(p.out_dir)
    return index


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 2
    for d in argv[1:]:
        if not os.path.isdir(d):
            print("make_report.py: %s: not a directory" % d, file=sys.stderr)
            return 2
        print(build(d))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
