#!/usr/bin/env python3
"""The false-alarm hunt (issue 34, item 2): random valid scenes through `vct validate`, failures
shrunk to minimal regression cases.

    .venv/bin/python tools/scenegen/hunt.py --seeds 0-299 [--size-class small] [--vct build/bin/vct]
        [--out runs/hunt] [--save scenes/regressions] [--threads 2] [--no-shrink] [--budget 120]
        [--time-limit SECONDS]
    .venv/bin/python tools/scenegen/hunt.py --write-only --seeds 5 --out DIR   # just the scene files
    .venv/bin/python tools/scenegen/hunt.py --summarize --out runs/hunt         # counts per verdict, stage
    .venv/bin/python tools/scenegen/hunt.py --rerun-saved [--save scenes/regressions]  # every saved case again

Per seed: writes OUT/seed-N/scene.gltf and settings.json (everything validate needs: image size,
grid, shadow map size, pt.spp 4 and the drawn settings), runs `vct validate --config settings.json --no-report`, and
prints one line: seed, verdict (pass, warn, fail, refused = exit 2, no-gl = exit 3, crash = any
other exit, timeout = stopped after --time-limit seconds: a scene too slow to judge, reported, not
a failure), first failing stage. A FAIL is shrunk while it still FAILs with the same first failing
stage (digits in the stage name ignored: a light's index changes when lights are dropped), the
triangles that hold the scene's extreme vertices kept (shrink.py, pin_bounds), and saved
as SAVE/seed-N-CLASS/ {scene.gltf, settings.json, case.json (seed, verdict line, first failing
stage, its note, sizes before and after, "cause": to fill)}. Results: OUT/results.jsonl.
Exit 1 when any seed FAILed, crashed or was refused (a valid scene refused is a loader or
generator bug); no-gl (no GL context) is not a failure.
docs/compare.md, "False-alarm hunt", has the campaign command and results.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate  # noqa: E402
import gltf_writer  # noqa: E402
import shrink  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def settings_document(spec):
    vct = dict(spec["settings"], width=spec["width"], height=spec["height"], grid=spec["grid"],
               shadow_map_size=spec["shadow_map_size"])
    return {"vct": vct, "pt": {"spp": 4}}


def write_case(spec, folder):
    """scene.gltf + settings.json of a spec, each written to a temporary name, then renamed."""
    os.makedirs(folder, exist_ok=True)
    files = {"scene.gltf": gltf_writer.gltf_bytes(spec),
             "settings.json": (json.dumps(settings_document(spec), indent=1, sort_keys=True) + "\n").encode()}
    for name, data in files.items():
        with open(os.path.join(folder, name + ".tmp"), "wb") as f:
            f.write(data)
        os.replace(os.path.join(folder, name + ".tmp"), os.path.join(folder, name))


def run_validate(args, folder):
    """Runs validate on folder/scene.gltf; returns {verdict, first_failing, line, note, rc, seconds}."""
    run = os.path.join(folder, "run")
    shutil.rmtree(run, ignore_errors=True)
    cmd = [args.vct, "validate", os.path.join(folder, "scene.gltf"), "--config", os.path.join(folder, "settings.json"),
           "--threads", str(args.threads), "--no-report", "--flip", "none", "--out", run]
    start = time.time()
    rc, output = run_with_limit(cmd, args.time_limit)
    result = {"rc": rc, "seconds": round(time.time() - start, 2), "first_failing": "", "note": "", "line": ""}
    result["line"] = verdict_line(output)
    kinds = {0: None, 1: "fail", 2: "refused", 3: "no-gl", None: "timeout"}
    result["verdict"] = kinds.get(rc, "crash")
    if rc is None:
        result["line"] = "stopped after --time-limit %g s" % args.time_limit
        if not args.keep_runs:
            shutil.rmtree(run, ignore_errors=True)  # a killed run's directory is incomplete
        return result
    try:
        verdicts = json.load(open(os.path.join(run, "run.json")))["verdicts"]
        result["first_failing"] = verdicts.get("first_failing", "")
        result["verdict"] = result["verdict"] or verdicts.get("overall", "pass")
        for stage in verdicts.get("stages", []):
            if stage["stage"] == result["first_failing"]:
                result["note"] = stage.get("note", "")
    except (OSError, ValueError, KeyError):
        result["verdict"] = result["verdict"] or "pass"
    if not args.keep_runs:
        shutil.rmtree(run, ignore_errors=True)
    return result


def run_with_limit(cmd, limit):
    """(exit code, output) of cmd; (None, output so far) when it ran past `limit` seconds (0: no
    limit), its whole process group (validate's GL runner too) then killed."""
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace",
                            start_new_session=True)
    try:
        output, _ = proc.communicate(timeout=limit or None)
        return proc.returncode, output
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        output, _ = proc.communicate()
        return None, output


def verdict_line(output):
    """validate's verdict line, else (a refusal, a crash) the last line it printed."""
    m = re.search(r"GPU \(gl\) vs CPU reference: .*", output)
    if m:
        return m.group(0).strip()
    lines = output.strip().splitlines()
    return lines[-1] if lines else ""


def stage_family(name):
    return re.sub(r"\d+", "N", name)


def spec_size(spec):
    return {"meshes": len(spec["meshes"]), "triangles": int(sum(len(m["indices"]) for m in spec["meshes"])),
            "lights": len(spec["lights"]), "textures": len(spec["textures"]), "settings": len(spec["settings"]),
            "width": spec["width"], "height": spec["height"], "grid": spec["grid"],
            "shadow_map_size": spec["shadow_map_size"]}


def shrink_failure(args, spec, first):
    work = os.path.join(args.out, "shrink-%d" % spec["seed"])

    def still_fails(candidate):
        write_case(candidate, work)
        r = run_validate(args, work)
        return r["verdict"] == "fail" and stage_family(r["first_failing"]) == stage_family(first["first_failing"])

    # Bounds pinned: the voxel grid, the camera's far plane and the spot lights' depth ranges are
    # fitted to them, so a voxel or depth failure stays where it is while triangles go.
    small, calls = shrink.shrink(spec, still_fails, budget=args.budget, log=print, pin=True)
    write_case(small, work)
    final = run_validate(args, work)  # the minimal case's own verdict line and note
    if final["verdict"] != "fail":  # cannot happen for a deterministic validate; keep the original
        small, final = spec, first
    folder = os.path.join(args.save, "seed-%d-%s" % (spec["seed"], spec["size_class"]))
    write_case(small, folder)
    case = {"seed": spec["seed"], "size_class": spec["size_class"], "generator": "tools/scenegen/hunt.py",
            "reproduce": "tools/scenegen/hunt.py --write-only --seeds %d --size-class %s" % (spec["seed"], spec["size_class"]),
            "command": "vct validate scene.gltf --config settings.json --no-report",
            "verdict_line": final["line"], "first_failing_stage": final["first_failing"], "note": final["note"],
            "original": spec_size(spec), "minimal": spec_size(small), "shrink_calls": calls, "cause": ""}
    with open(os.path.join(folder, "case.json"), "w") as f:
        f.write(json.dumps(case, indent=1) + "\n")
    shutil.rmtree(work, ignore_errors=True)
    return folder


def summarize(out):
    """Counts per verdict, then per first failing stage with its seeds, from OUT/results.jsonl."""
    rows = [json.loads(line) for line in open(os.path.join(out, "results.jsonl")) if line.strip()]
    verdicts, stages = {}, {}
    for r in rows:
        verdicts[r["verdict"]] = verdicts.get(r["verdict"], 0) + 1
        if r["verdict"] not in ("pass", "warn"):
            stages.setdefault(r["first_failing"] or r["verdict"], []).append(r["seed"])
    seconds = sum(r["seconds"] for r in rows)
    print("%d scenes, %.0f s of validate runs; %s" % (len(rows), seconds,
                                                        ", ".join("%s %d" % kv for kv in sorted(verdicts.items()))))
    for stage, seeds in sorted(stages.items(), key=lambda kv: -len(kv[1])):
        print("  %-24s %3d  seeds %s" % (stage, len(seeds), ",".join(map(str, seeds))))


def parse_seeds(text):
    seeds = []
    for part in text.split(","):
        lo, _, hi = part.partition("-")
        seeds += list(range(int(lo), int(hi or lo) + 1))
    return seeds


def rerun_saved(args):
    """Every saved case (SAVE/*/scene.gltf with its settings.json) through validate again, in name
    order: one line each; exit 1 when any FAILs, crashes or is refused (a judge that regressed)."""
    if not os.path.isdir(args.save):
        print("hunt.py: %s: not a folder" % args.save, file=sys.stderr)
        return 2
    cases = sorted(d for d in os.listdir(args.save) if os.path.isfile(os.path.join(args.save, d, "scene.gltf")))
    if not cases:
        print("hunt.py: %s: no saved case (a folder with scene.gltf)" % args.save, file=sys.stderr)
        return 2
    bad = 0
    for name in cases:
        case = os.path.join(args.out, name)
        shutil.rmtree(case, ignore_errors=True)
        os.makedirs(case)
        for f in ("scene.gltf", "settings.json"):
            shutil.copyfile(os.path.join(args.save, name, f), os.path.join(case, f))
        r = run_validate(args, case)
        shutil.rmtree(case, ignore_errors=True)
        bad += r["verdict"] not in ("pass", "warn", "no-gl")
        print("%-22s %-8s %6.1f s  %s" % (name, r["verdict"], r["seconds"], r["first_failing"] or r["line"][:100]),
              flush=True)
    return 1 if bad else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", help="e.g. 0-299 or 1,5,9")
    ap.add_argument("--summarize", action="store_true", help="print OUT/results.jsonl's counts, run nothing")
    ap.add_argument("--size-class", default="small", choices=generate.SIZE_CLASSES)
    ap.add_argument("--vct", default=os.path.join(ROOT, "build", "bin", "vct"))
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "hunt"))
    ap.add_argument("--save", default=os.path.join(ROOT, "scenes", "regressions"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--budget", type=int, default=120, help="validate runs per shrink")
    ap.add_argument("--no-shrink", action="store_true")
    ap.add_argument("--time-limit", type=float, default=0,
                    help="seconds per validate run; a longer one is stopped and recorded as timeout (0: none)")
    ap.add_argument("--keep-runs", action="store_true")
    ap.add_argument("--write-only", action="store_true", help="write the scenes, run nothing")
    ap.add_argument("--rerun-saved", action="store_true", help="validate every case in SAVE again, generate nothing")
    args = ap.parse_args()
    if args.summarize:
        summarize(args.out)
        return 0
    if args.rerun_saved:
        return rerun_saved(args)
    if not args.seeds:
        print("hunt.py: --seeds is required (or --summarize)", file=sys.stderr)
        return 2
    try:
        seeds = parse_seeds(args.seeds)
    except ValueError:
        print("hunt.py: --seeds %r: expected N, A-B or a comma list of them" % args.seeds, file=sys.stderr)
        return 2
    bad = 0
    counts = {}
    os.makedirs(args.out, exist_ok=True)
    open(os.path.join(args.out, "results.jsonl"), "w").close()  # one campaign per out folder
    for seed in seeds:
        spec = generate.generate(seed, args.size_class)
        folder = os.path.join(args.out, "seed-%d-%s" % (seed, args.size_class))
        write_case(spec, folder)
        if args.write_only:
            print(folder)
            continue
        r = run_validate(args, folder)
        counts[r["verdict"]] = counts.get(r["verdict"], 0) + 1
        print("seed %-6d %-8s %6.1f s  %s" % (seed, r["verdict"], r["seconds"], r["first_failing"] or r["line"][:100]),
              flush=True)
        record = dict(r, seed=seed, size_class=args.size_class, size=spec_size(spec), settings=spec["settings"])
        with open(os.path.join(args.out, "results.jsonl"), "a") as f:
            f.write(json.dumps(record) + "\n")
        if r["verdict"] in ("fail", "crash", "refused"):  # a valid scene refused is a finding too
            bad += 1
        if r["verdict"] == "fail" and not args.no_shrink:
            print("  saved %s" % shrink_failure(args, spec, r), flush=True)
        if r["verdict"] in ("pass", "warn"):
            shutil.rmtree(folder, ignore_errors=True)
    if not args.write_only:
        print("verdicts: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
