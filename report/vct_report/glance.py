"""The report's first screen (docs/report.md, "At a glance"): it must answer the question at
1366x768 without scrolling: one verdict sentence, the first failing (else first warning) stage
with its mask, worst offenders and where that stage is documented and implemented, the three
final images side by side with a flip view, and the bias headline per component. Everything
here reads run.json and files the run already wrote: no image is decoded, nothing is computed."""
import html
import os

from . import registry

E = html.escape


def verdict_sentence(verdicts):
    """(css class, sentence) for the GPU-vs-CPU result."""
    stages = (verdicts or {}).get("stages") or []
    if not stages:
        note = (verdicts or {}).get("note", "no GPU run in this directory")
        return "missing", "GL was not compared with the CPU reference (%s)." % note
    first = verdicts.get("first_failing", "")
    if first:
        st = next((s for s in stages if s["stage"] == first), {})
        fails = sum(1 for s in stages if s["verdict"] == "fail")
        more = " (%d stages fail in all; later ones usually follow from it)" % fails if fails > 1 else ""
        # The note's first clause: the card beside it holds the whole note.
        note = st.get("note", "beyond its bound").split(";")[0].rstrip(".")
        if len(note) > 150:  # two lines at most: the images must stay on the first screen
            note = note[:147].rstrip() + "..."
        return "fail", "GL fails at %s: %s%s." % (first, note, more)
    warns = [s["stage"] for s in stages if s["verdict"] == "warn"]
    missing = [s["stage"] for s in stages if s["verdict"] == "missing"]
    text = "GL matches the CPU reference at every stage (%d compared)" % (len(stages) - len(missing))
    if warns:
        text += "; %d warning%s %s ties the tolerance models allow (first: %s)" % (
            len(warns), "s" if len(warns) > 1 else "", "are" if len(warns) > 1 else "is", warns[0])
    if missing:
        text += "; %d missing on one side" % len(missing)
    return ("warn" if warns else "pass"), text + "."


def focus_stage(verdicts):
    """The stage the reader should look at first: the first failing one, else the first warning."""
    stages = (verdicts or {}).get("stages") or []
    first = (verdicts or {}).get("first_failing", "")
    for s in stages:
        if (first and s["stage"] == first) or (not first and s["verdict"] == "warn"):
            return s
    return None


def offenders_table(stage, n=3):
    rows = []
    for w in stage.get("worst", [])[:n]:
        rows.append("<tr><td>%s</td><td class=num>%s</td><td class=num>%s</td></tr>" % (
            E(",".join(str(c) for c in w["at"] if c >= 0)), E(", ".join("%.3g" % x for x in w["reference"])),
            E(", ".join("%.3g" % x for x in w["test"]))))
    if not rows:
        return "<div class='small'>no offender beyond the bound listed</div>"
    return ("<table class='compact' id='glance-offenders'><tr><th>at (x,y[,z])</th><th>reference</th><th>GL</th></tr>%s</table>"
            % "".join(rows))


WITHIN_BOUND = ("within-bound", "volume-within-bound", "radiance-within-bound")


def admitted_text(stage, top=4):
    """The rules that admitted this stage's elements beyond their bound, most first (run.json
    admitted_by, compare/admission.h): "raster-alternative 12, edge-neighbour 3"."""
    counts = [(n, r) for r, n in (stage.get("admitted_by") or {}).items() if r not in WITHIN_BOUND and r != "beyond"]
    counts.sort(key=lambda c: (-c[0], c[1]))
    text = ", ".join("%s %d" % (r, n) for n, r in counts[:top])
    if len(counts) > top:
        text += ", +%d more" % (len(counts) - top)
    beyond = (stage.get("admitted_by") or {}).get("beyond", 0)
    if beyond:
        text = ("admitted by no rule %d" % beyond) + ("; " + text if text else "")
    return text


def focus_card(page, verdicts):
    st = focus_stage(verdicts)
    if st is None:
        stages = (verdicts or {}).get("stages") or []
        body = "every stage passes: nothing to point at" if stages else "no comparison in this run"
        return "<div class='card' id='glance-stage'><h3>Stage to look at</h3><p>%s.</p></div>" % E(body)
    name = st["stage"]
    title = "First failing stage" if st["verdict"] == "fail" else "First warning"
    mask = st.get("mask")
    mpath = os.path.join(page.run.path, mask) if mask else None
    mimg = ('<a href="%s"><img id="glance-mask" class="mask" src="%s" alt="error mask of %s"></a>' % (
        E(page.rel(mpath)), E(page.rel(mpath)), E(name)) if mpath and os.path.exists(mpath)
        else "<div class='missing'>missing: mask</div>")
    doc = registry.from_run(page.run.json).doc(name)
    where = ("<div class='small'><b>computes</b> %s<br><b>docs</b> <code>%s</code><br><b>ref</b> <code>%s</code>"
             "<br><b>gl</b> <code>%s</code></div>" % tuple(E(x) for x in doc)) if doc else ""
    admitted = admitted_text(st)
    admitted = "<div class='small' id='glance-admitted'><b>admitted by</b> %s</div>" % E(admitted) if admitted else ""
    return ("<div class='card' id='glance-stage'><h3>%s: <code>%s</code> <span class='v-%s'>&nbsp;%s&nbsp;</span></h3>"
            "<div class='small'>%s &middot; %s</div>%s<div class='focus'>%s<div>%s%s</div></div></div>" % (
                title, E(name), E(st["verdict"]), E(st["verdict"]), E(st.get("model", "")),
                E(st.get("note", "")), admitted, mimg, offenders_table(st), where))


def final_strip(page):
    """The three final images side by side plus a flip panel that alternates two of them."""
    run = page.run
    cands = [("ref", "CPU reference", run.stage_file("ref", registry.FINAL)),
             ("gl", "GL", run.stage_file("gl", registry.FINAL)),
             ("pt", "path tracer", run.file("pt", "pt_full.png"))]
    figs = []
    for key, label, png in cands:
        if png:
            figs.append('<figure class="glance-img"><img id="glance-%s" src="%s" alt="%s"><figcaption>%s</figcaption></figure>'
                        % (key, E(page.rel(png)), E(label), E(label)))
        else:
            figs.append('<figure class="glance-img"><div class="missing">missing: %s</div><figcaption>%s</figcaption></figure>'
                        % (E(label), E(label)))
    avail = [(k, l, page.rel(p)) for k, l, p in cands if p]
    if len(avail) >= 2:
        opts = "".join('<option value="%d,%d"%s>%s / %s</option>' % (
            i, j, " selected" if (i, j) == (0, 1) else "", E(avail[i][0]), E(avail[j][0]))
            for i in range(len(avail)) for j in range(i + 1, len(avail)))
        figs.append('<figure class="glance-img" id="glance-flip"><img id="glance-flip-img" src="%s" alt="flip view">'
                    '<figcaption><select id="glance-flip-pair">%s</select> <label><input type="checkbox" '
                    'id="glance-flip-auto" checked> flip</label> <span id="glance-flip-shown"></span></figcaption></figure>'
                    '<script>window.VCT_FLIP=%s;</script>' % (
                        E(avail[0][2]), opts, "[%s]" % ",".join('["%s","%s"]' % (E(l), E(p)) for _, l, p in avail)))
    return "<div class='glance-images'>%s</div>" % "".join(figs)


def bias_headline(run_json):
    b = run_json.get("bias") or {}
    budget = run_json.get("error_budget")
    if not b:
        return "<div class='card' id='glance-bias'><h3>Bias against the path tracer</h3><div class='missing'>missing: bias</div></div>"
    sides = [s for s in ("ref", "gl") if s in b] + [s for s in b if s not in ("ref", "gl")]
    comps = []
    for s in sides:
        for r in b[s]:
            if r.get("available") and r["component"] not in comps:
                comps.append(r["component"])
    head = "".join("<th>%s rel. bias</th>" % E(s) for s in sides)
    rows = []
    for c in comps:
        cells, judge = [], "pass"
        for s in sides:
            r = next((x for x in b[s] if x.get("component") == c and x.get("available")), None)
            cells.append("<td class=num>%s</td>" % ("%+.2f%%" % (100 * r["relative_bias"]) if r else "-"))
            if r and r.get("significant"):
                judge = "warn"
        ref = next((x for x in b[sides[0]] if x.get("component") == c and x.get("available")), {})
        rows.append("<tr><td>%s</td>%s<td class=num>%s</td><td class='v-%s'>%s</td></tr>" % (
            E(c), "".join(cells), "%.3g" % ref["rel_mse"] if "rel_mse" in ref else "-", judge,
            "beyond PT noise" if judge == "warn" else "within PT noise"))
    extra = ""
    if budget:
        extra = "<div class='small'><b>error budget</b> %s</div>" % E(", ".join(
            "%s %s" % (k, ("%.3g" % v) if isinstance(v, (int, float)) else v) for k, v in budget.items())
            if isinstance(budget, dict) else str(budget))
    return ("<div class='card' id='glance-bias'><h3>Bias against the path tracer</h3><table class='compact'>"
            "<tr><th>component</th>%s<th>relMSE (%s)</th><th>judgement</th></tr>%s</table>%s</div>" % (
                head, E(sides[0]), "".join(rows), extra))


def scene_warnings_line(run_json):
    """The loader's warnings (run.json scene.warnings, docs/scenes.md): what the engines could not
    render as the file asks. Empty when there are none; the first one in full, the count of the rest."""
    scene = run_json.get("scene")
    warnings = scene.get("warnings", []) if isinstance(scene, dict) else []
    if not warnings:
        return ""
    more = " (+%d more in run.json scene.warnings)" % (len(warnings) - 1) if len(warnings) > 1 else ""
    return "<div class='card small' id='glance-warnings'><b>Scene warning%s:</b> %s%s</div>" % (
        "s" if len(warnings) > 1 else "", E(warnings[0]), E(more))


def glance(page, verdicts):
    """verdicts: run.json["verdicts"] (or compare.json's), None when there are none."""
    j = page.run.json
    cls, sentence = verdict_sentence(verdicts)
    return ("<section id='glance'><p id='verdict-sentence' class='sentence s-%s'>%s</p>"
            "<div class='glance-grid'><div class='glance-main'>%s%s</div><div class='glance-side'>%s</div></div></section>" % (
                cls, E(sentence), final_strip(page), bias_headline(j), focus_card(page, verdicts) + scene_warnings_line(j)))
