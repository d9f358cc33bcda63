#!/usr/bin/env python3
"""The report in a real browser (issue 8, item 5): builds a small run with `vct validate`, and a
partial copy without GL, PT and bias (missing parts must show as missing, not break the page);
opens both in headless Chromium; checks that every <img> loaded (naturalWidth > 0), that the
difference viewer drew A, B and the |A-B| heat map, and that the voxel view drew; that the first
screen's elements (verdict sentence, stage card with mask, the three final images and the flip
view, the bias headline) lie wholly inside the first 1366x768 viewport, and that the first screen
re-flows without running off the right edge at 700 px; saves screenshots next to the runs.
Exit 0 on success, 1 on failure (ctest)."""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def chromium(binary, args, url, profile):
    cmd = [binary, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync",
           "--user-data-dir=" + profile, "--virtual-time-budget=8000"] + args + [url]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


# The first screen at the smallest common laptop size (docs/report.md, "At a glance"). Headless
# Chromium's 1366x768 window leaves a 1366x625 viewport, about what a browser's own bars leave
# on such a screen: the page must fit that.
FIRST_SCREEN = "1366,768"


def full_run_first_screen(run):
    """What the first screen of this run must show: GL's image and a stage mask only where the
    run has them (no GL context: validate still runs ref + pt; every stage passing: no mask)."""
    with open(os.path.join(run, "run.json")) as f:
        j = json.load(f)
    need = ["verdict-sentence", "glance-stage", "glance-ref", "glance-pt", "glance-flip", "glance-bias"]
    if os.path.exists(os.path.join(run, "gl", "vct-stages.json")):
        need.append("glance-gl")
    if any(s["verdict"] in ("warn", "fail") for s in (j.get("verdicts") or {}).get("stages", [])):
        need.append("glance-mask")
    return need
PARTIAL_RUN_FIRST_SCREEN = ["verdict-sentence", "glance-stage", "glance-ref", "glance-bias"]


def page_status(binary, url, profile, window):
    dom = chromium(binary, ["--dump-dom", "--window-size=" + window], url, profile).stdout
    m = re.search(r'<code id="status" data-ok="(\w+)">([^<]*)</code>', dom)
    if not m:
        return None, None
    return m, json.loads(m.group(2).replace("&quot;", '"'))


def check_page(binary, index, shot, need_viewer, work, first_screen):
    profile = tempfile.mkdtemp(prefix="chromium-", dir=work)
    url = "file://" + index
    m, status = page_status(binary, url, profile, FIRST_SCREEN)
    if not m:
        return ["status element not found (JS did not run?)"]
    errors = []
    vw, vh = status.get("viewport", [0, 0])
    if vw != 1366 or not 560 <= vh <= 768:
        errors.append("viewport is %sx%s, not the 1366 x (560..768) a %s window gives" % (vw, vh, FIRST_SCREEN))
    for el in first_screen:
        where = status.get("glance", {}).get(el, "absent")
        if where != "in":
            errors.append("first screen: #%s is %s the %s viewport" % (el, where, FIRST_SCREEN))
    _, narrow = page_status(binary, url, profile, "700,900")
    if narrow is None or narrow.get("glanceOverflow") is not False:
        errors.append("first screen runs off the right edge at 700 px wide")
    if m.group(1) != "true":
        errors.append("page reports not ok: %s" % m.group(2))
    if status["images"] == 0 or status["loaded"] != status["images"]:
        errors.append("images: %d of %d loaded, broken: %s" % (status["loaded"], status["images"], status["broken"]))
    if need_viewer and status["viewer"] != "ok":
        errors.append("difference viewer: %s" % status["viewer"])
    if need_viewer and status["voxels"] != "ok":
        errors.append("voxel view: %s" % status["voxels"])
    chromium(binary, ["--window-size=1366,2000", "--screenshot=" + shot], url, profile)
    if not os.path.exists(shot) or os.path.getsize(shot) < 10000:
        errors.append("no screenshot written")
    shutil.rmtree(profile, ignore_errors=True)
    print("%s: %s" % (index, m.group(2)))
    return errors


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--vct", required=True)
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    run = os.path.join(a.work, "run")
    env = dict(os.environ, VCT_SOURCE_DIR=ROOT)
    p = subprocess.run([a.vct, "validate", "--out", run, "--width", "64", "--height", "64", "--grid", "16", "--spp", "4",
                        "--threads", "2", "--sweep", "grid=16,32"], capture_output=True, text=True, env=env, timeout=300)
    print(p.stdout[-3000:])
    if p.returncode not in (0, 1, 3):
        print("vct validate failed (%d): %s" % (p.returncode, p.stderr[-2000:]))
        return 1
    index = os.path.join(run, "report", "index.html")
    if not p.stdout.strip().endswith(index) or not os.path.exists(index):
        print("validate did not print the report path last (expected %s)" % index)
        return 1
    errors = check_page(a.chromium, index, os.path.join(a.work, "report_full.png"), True, a.work,
                        full_run_first_screen(run))

    # A partial run: no GL, no path tracer, no bias, no sweeps.
    partial = os.path.join(a.work, "partial")
    shutil.copytree(run, partial, ignore=shutil.ignore_patterns("report"))
    for d in ("gl", "pt", "bias", "bias_gl", "compare"):
        shutil.rmtree(os.path.join(partial, d), ignore_errors=True)
    with open(os.path.join(partial, "run.json")) as f:
        j = json.load(f)
    for k in ("bias", "sweeps", "verdicts"):
        j.pop(k, None)
    with open(os.path.join(partial, "run.json"), "w") as f:
        json.dump(j, f)
    r = subprocess.run([sys.executable, os.path.join(ROOT, "report", "make_report.py"), partial], capture_output=True, text=True)
    if r.returncode != 0:
        print("make_report.py failed on the partial run: " + r.stderr)
        return 1
    pidx = os.path.join(partial, "report", "index.html")
    html = open(pidx).read()
    if "missing: GL (VCT)" not in html or "missing: bias" not in html:
        errors.append("partial run: missing parts not shown as missing")
    errors += check_page(a.chromium, pidx, os.path.join(a.work, "report_partial.png"), False, a.work,
                         PARTIAL_RUN_FIRST_SCREEN)
    for e in errors:
        print("FAIL: " + e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
