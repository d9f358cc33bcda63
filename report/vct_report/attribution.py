"""The error budget section (docs/attribution.md): per component, the ladder's rungs and terms
(mean luminance, standard error, share of the total), the sum check, the waterfall and one heat map
per term; and the budget's sweep rows when the run has them. Read from the file run.json names
under "attribution" (written by `vct attribute` and `vct validate --attribute`)."""
import html
import os

from . import runio

E = html.escape


def load(run):
    name = run.json.get("attribution")
    return runio.load_json(os.path.join(run.path, name)) if isinstance(name, str) else None


def _num(x, spec="%+.5f"):
    return spec % x if isinstance(x, (int, float)) else "-"


def component_table(c):
    total = c.get("total", {}).get("mean", 0.0)
    rows = ["<tr><td>rung</td><td>%s</td><td title='%s'>%s</td><td class=num>%s</td><td class=num>%s</td><td></td></tr>" % (
        E(c["component"]), E(r.get("what", "")), E(r["name"]), _num(r["mean"], "%.5f"), _num(r["se"], "%.5f"))
        for r in c.get("rungs", [])]
    rows += ["<tr><td>term</td><td>%s</td><td>%s</td><td class=num>%s</td><td class=num>%s</td><td class=num>%s</td></tr>" % (
        E(c["component"]), E(t["name"]), _num(t["mean"]), _num(t["se"], "%.5f"),
        _num(100.0 * t["mean"] / total, "%+.1f%%") if total else "-") for t in c.get("terms", [])]
    chk = c.get("sum_check", {})
    rows.append("<tr><td>total</td><td>%s</td><td>VCT - truth</td><td class=num>%s</td><td class=num>%s</td>"
                "<td class='v-%s'>%s</td></tr>" % (
                    E(c["component"]), _num(total), _num(c.get("total", {}).get("se"), "%.5f"),
                    "pass" if chk.get("pass") else "fail",
                    "terms add up (%s)" % _num(chk.get("discrepancy")) if chk.get("pass") else
                    "terms do NOT add up (%s, %.1f SE)" % (_num(chk.get("discrepancy")),
                                                            abs(chk.get("discrepancy", 0)) / max(chk.get("se", 0) or 1e-30, 1e-30))))
    return "".join(rows)


def pictures(p, c):
    files = c.get("files", {})
    run = p.run
    figs = []
    if files.get("waterfall"):
        figs.append(p.img(os.path.join(run.path, files["waterfall"]),
                          "%s waterfall: truth, each term, VCT (red raises, blue lowers, whisker = 1 SE)" % c["component"]))
    for term, f in files.get("heat_maps", {}).items():
        figs.append(p.img(os.path.join(run.path, f["png"]),
                          "%s / %s: blue lowers, red raises, full scale %.3g" % (c["component"], term, f.get("scale", 0))))
    return "<div class='row'>%s</div>" % "".join(figs)


def sweep_tables(doc):
    out = []
    for sw in doc.get("sweeps", []):
        rows = sw.get("rows", [])
        comps = [c["component"] for c in (rows[0]["components"] if rows else [])]
        for comp in comps:
            terms = [t["name"] for t in next(c for c in rows[0]["components"] if c["component"] == comp)["terms"]]
            out.append("<h4>%s = ... : %s</h4><table><tr><th>%s</th>%s<th>total</th></tr>" % (
                E(sw["key"]), E(comp), E(sw["key"]), "".join("<th>%s</th>" % E(t) for t in terms)))
            for r in rows:
                c = next(c for c in r["components"] if c["component"] == comp)
                out.append("<tr><td>%s</td>%s<td class=num>%s &plusmn; %s</td></tr>" % (
                    E(str(r["value"])), "".join("<td class=num>%s &plusmn; %s</td>" % (_num(t["mean"]), _num(t["se"], "%.5f"))
                                               for t in c["terms"]),
                    _num(c["total"]["mean"]), _num(c["total"]["se"], "%.5f")))
            out.append("</table>")
    return "".join(out)


def section(p, missing):
    out = ['<h2 id="attribution">Error budget per component</h2>']
    doc = load(p.run)
    if not doc:
        return "".join(out) + missing("error budget (run vct validate --attribute, or vct attribute)")
    out.append("<p>Each rung replaces one VCT approximation by its exact counterpart on the same pixels, G-buffer "
               "and voxel field (docs/attribution.md); a term is the step between two rungs, in mean luminance of "
               "the radiance the component adds to the frame. Every term and the total are estimated from "
               "independent samples, so the terms add up to the total only within their standard error "
               "(checked at 4 SE).</p>")
    out.append("<table><tr><th></th><th>component</th><th>name</th><th>mean</th><th>SE</th><th>share of total</th></tr>")
    out.append("".join(component_table(c) for c in doc.get("components", [])))
    out.append("</table>")
    out.append("".join("<details open><summary>%s: waterfall and heat maps</summary>%s</details>" % (
        E(c["component"]), pictures(p, c)) for c in doc.get("components", [])))
    out.append(sweep_tables(doc))
    return "".join(out)
