#!/usr/bin/env python3
"""The compatibility report: renders POV-Ray 3.7's example scenes with glint and compares each
with POV-Ray's own rendering of it (the references that pov_refs.py caches), writing
tests/pov_examples/REPORT.md.

Each scene is rendered at the references' size (160x120, no anti-aliasing, one thread) from a
scratch working directory, with the scene's folder and POV-Ray's include folder on the search
path, and a limit of 30 CPU seconds. Per scene the report gives: whether glint parses it, the unsupported features
glint met (its `... is not supported` warnings), agreement with POV-Ray (`glint compare`:
fraction of pixels within 2/255, SSIM, mean absolute error) and a verdict:

    exact         >= 99% of the pixels within 2/255 in every channel
    close         SSIM >= 0.95 and mean absolute error <= 2% (5.1/255)
    differs       neither
    fails         glint stopped with an error (or ran out of time)
    no reference  POV-Ray itself failed or ran out of time on the scene

    tests/pov_examples/compat.py [--glint build/glint] [--cache build/pov-examples]
                                 [--jobs 2] [--timeout 30] [--only SUBSTRING]... [--out FILE]
                                 [--time-pov]

With --only the results are printed and REPORT.md is left alone unless --out is given.
With --time-pov POV-Ray renders each scene again right after glint, one scene at a time, and
the report compares their CPU times (user + system, each process's own) in the same run.
"""
import argparse
import concurrent.futures
import datetime
import json
import math
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pov_refs import EXAMPLES, INCLUDE, list_scenes  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

# `file:line:col: warning: <text>`; unsupported features say `<feature> is not supported`.
WARNING = re.compile(r"^(.*?):(\d+):(\d+): warning: (.*)$")
UNSUPPORTED = re.compile(r"(.*?) (?:is|are) not supported")
ERROR = re.compile(r"^(.*?): error: (.*)$")

MAE_LIMIT = 0.02 * 255  # `glint compare` reports MAE in 1/255 steps
SSIM_LIMIT = 0.95
EXACT_LIMIT = 0.99


def feature_name(text):
    """The feature an `... is not supported` warning names, without the location."""
    m = UNSUPPORTED.match(text)
    if not m:
        return None
    name = m.group(1)
    quoted = re.findall(r"'([^']+)'", name)
    return quoted[0] if len(quoted) == 1 and name.startswith(("'", "the '")) else name


def parse_compare(line):
    fields = dict(re.findall(r"(\w+)=([^\s]+)", line))
    try:
        return {"within": float(fields["within"]), "ssim": float(fields["ssim"]),
                "mae": float(fields["mae"])}
    except (KeyError, ValueError):
        return None


def cpu_since(before):
    """CPU seconds (user + system) of the children reaped since `before` (one job at a time)."""
    now = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (now.ru_utime - before.ru_utime) + (now.ru_stime - before.ru_stime)


def time_povray(scene, args):
    """POV-Ray's CPU seconds on the scene with the references' settings, or None."""
    src = os.path.join(EXAMPLES, scene)
    work = tempfile.mkdtemp(prefix="glint-povtime.")
    cmd = ["povray", "+I" + src, "+O" + os.path.join(work, "out.png"), f"+W{args.width}",
           f"+H{args.height}", "-A", "+WT1", "-D", "-V", "+FN", "+L" + os.path.dirname(src),
           "+L" + INCLUDE]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        proc = subprocess.run(cmd, cwd=work, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL, timeout=args.timeout * 6)
        ok = proc.returncode == 0
    except subprocess.TimeoutExpired:
        ok = False
    seconds = cpu_since(before)
    shutil.rmtree(work, ignore_errors=True)
    return round(seconds, 3) if ok else None


def run_scene(scene, args):
    src = os.path.join(EXAMPLES, scene)
    ref_png = os.path.join(args.cache, "ref", scene[:-4] + ".png")
    ref_json = ref_png[:-4] + ".json"
    result = {"scene": scene}
    ref_status = "missing"
    if os.path.exists(ref_json):
        with open(ref_json) as f:
            ref_status = json.load(f).get("status", "missing")
    result["ref"] = ref_status if ref_status != "ok" or os.path.exists(ref_png) else "missing"

    work = tempfile.mkdtemp(prefix="glint-compat.")
    out = os.path.join(work, "glint.png")
    cmd = ["nice", "-n", "5", args.glint, "render", src, "-o", out, "-W", str(args.width),
           "-H", str(args.height), "--threads", str(args.threads), "--progress=none",
           "-I", os.path.dirname(src), "-I", INCLUDE]
    start = time.monotonic()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)

    def limit_cpu():
        # The limit is on CPU time, so a busy machine does not turn slow scenes into
        # timeouts; the wall-clock limit below only catches a process that stops running.
        resource.setrlimit(resource.RLIMIT_CPU, (int(args.timeout), int(args.timeout) + 1))

    try:
        proc = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              timeout=args.timeout * 6, preexec_fn=limit_cpu)
        rc = proc.returncode
        stderr = proc.stderr.decode("utf-8", "replace")
        if rc in (-signal.SIGXCPU, -signal.SIGKILL):
            rc = None
    except subprocess.TimeoutExpired as e:
        rc = None
        stderr = (e.stderr or b"").decode("utf-8", "replace")
    result["seconds"] = round(time.monotonic() - start, 2)
    result["rc"] = rc
    if args.time_pov:
        result["glint_cpu"] = round(cpu_since(before), 3)

    features = []
    error = ""
    for line in stderr.splitlines():
        w = WARNING.match(line)
        if w:
            name = feature_name(w.group(4))
            if name and name not in features:
                features.append(name)
            continue
        e = ERROR.match(line)
        if e and not error:
            error = line.strip()
    result["unsupported"] = features
    # Exit 2 (scene error) and 3 (missing file) come from the parser; 4 and 5 after it.
    result["parses"] = ("timeout" if rc is None else "crash" if rc < 0 else
                        "no" if rc in (2, 3) else "yes")
    if rc is None:
        result["error"] = f"ran past the limit of {args.timeout:g} s"
    elif rc != 0:
        last = stderr.strip().splitlines()[-1] if stderr.strip() else ""
        result["error"] = error or last or f"exit {rc}"

    if rc == 0 and result["ref"] == "ok":
        proc = subprocess.run([args.glint, "compare", out, ref_png], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE)
        metrics = parse_compare(proc.stdout.decode())
        if metrics:
            result.update(metrics)
        else:
            result["error"] = proc.stderr.decode("utf-8", "replace").strip()
    if args.keep and rc == 0:
        dest = os.path.join(args.keep, scene[:-4] + ".png")
        os.makedirs(os.path.dirname(dest), exist_ok=True)
        shutil.copyfile(out, dest)
    shutil.rmtree(work, ignore_errors=True)
    result["verdict"] = verdict(result)
    if args.time_pov and result["verdict"] in ("exact", "close"):
        pov = time_povray(scene, args)
        if pov is not None:
            result["pov_cpu"] = pov
    return result


def verdict(r):
    if r["ref"] != "ok":
        return "no reference"
    if r["rc"] != 0:
        return "fails"
    if "within" not in r:
        return "differs"
    if r["within"] >= EXACT_LIMIT:
        return "exact"
    if r["ssim"] >= SSIM_LIMIT and r["mae"] <= MAE_LIMIT:
        return "close"
    return "differs"


VERDICTS = ["exact", "close", "differs", "fails", "no reference"]


def md_escape(text):
    return text.replace("|", "\\|").replace("\n", " ")


def write_report(results, args, path, elapsed):
    counts = {v: sum(1 for r in results if r["verdict"] == v) for v in VERDICTS}
    parses = sum(1 for r in results if r["parses"] == "yes")
    crashes = [r for r in results if r["rc"] is not None and r["rc"] not in (0, 1, 2, 3, 4, 5)]
    timeouts = [r for r in results if r["rc"] is None]
    features = {}
    for r in results:
        for f in r["unsupported"]:
            features[f] = features.get(f, 0) + 1
    lines = []
    lines.append("# POV-Ray 3.7 example scenes: glint against POV-Ray")
    lines.append("")
    lines.append(f"Generated by `tests/pov_examples/compat.py` on "
                 f"{datetime.date.today().isoformat()} ({len(results)} scenes, "
                 f"{args.width}x{args.height}, no anti-aliasing, {elapsed / 60:.1f} min). "
                 f"References: POV-Ray 3.7 `-A +WT1` (`pov_refs.py`).")
    lines.append("")
    lines.append("| verdict | scenes |")
    lines.append("|---|---:|")
    for v in VERDICTS:
        lines.append(f"| {v} | {counts[v]} |")
    lines.append(f"| **exact + close** | **{counts['exact'] + counts['close']}** |")
    lines.append("")
    lines.append(f"- glint parses {parses} of {len(results)} scenes; "
                 f"{len(timeouts)} ran past the limit of {args.timeout:g} CPU seconds; "
                 f"{len(crashes)} ended abnormally (signal or unexpected exit code).")
    lines.append("- exact: >= 99% of pixels within 2/255 in every channel; close: SSIM >= 0.95 "
                 "and mean absolute error <= 2%; fails: glint stopped with an error; "
                 "no reference: POV-Ray failed or timed out.")
    lines.append("- SSIM: Wang et al. 2004 on Rec. 601 luma, 11x11 Gaussian window (sigma 1.5), "
                 "mean over the windows inside the image. MAE: mean absolute difference over "
                 "all RGB values, in 1/255 steps.")
    timed = [r for r in results if "pov_cpu" in r and r.get("glint_cpu", 0) > 0]
    if timed:
        g = sum(r["glint_cpu"] for r in timed)
        p = sum(r["pov_cpu"] for r in timed)
        logs = [math.log(r["glint_cpu"] / max(r["pov_cpu"], 1e-3)) for r in timed]
        gmean = math.exp(sum(logs) / len(logs))
        slower = sum(1 for r in timed if r["glint_cpu"] > r["pov_cpu"])
        lines.append(f"- Time, the {len(timed)} scenes that agree, each rendered by glint then "
                     f"POV-Ray in the same run, one thread each, CPU seconds (user + system, "
                     f"start-up included): glint {g:.1f} s, POV-Ray {p:.1f} s, ratio "
                     f"{g / p:.2f}; geometric mean of the per-scene ratios {gmean:.2f}; glint "
                     f"slower on {slower}.")
    if features:
        top = sorted(features.items(), key=lambda kv: (-kv[1], kv[0]))
        lines.append("- Unsupported features met (scenes): " +
                     ", ".join(f"{md_escape(k)} ({v})" for k, v in top[:40]) +
                     (" ..." if len(top) > 40 else ""))
    lines.append("")
    pov_col = bool(timed)
    lines.append("| scene | parses | unsupported features | within 2/255 | SSIM | MAE (1/255) "
                 "| verdict | glint s |" + (" glint CPU s | POV-Ray CPU s |" if pov_col else "") +
                 " note |")
    lines.append("|---|---|---|---:|---:|---:|---|---:|" + ("---:|---:|" if pov_col else "") +
                 "---|")
    for r in sorted(results, key=lambda r: r["scene"]):
        within = f"{r['within']:.4f}" if "within" in r else ""
        ssim = f"{r['ssim']:.4f}" if "ssim" in r else ""
        mae = f"{r['mae']:.2f}" if "mae" in r else ""
        note = r.get("error", "")
        if len(note) > 140:
            note = note[:137] + "..."
        lines.append(f"| {r['scene']} | {r['parses']} | "
                     f"{md_escape(', '.join(r['unsupported']))} | {within} | {ssim} | {mae} | "
                     f"{r['verdict']} | {r['seconds']:.1f} |" +
                     (f" {r.get('glint_cpu', '')} | {r.get('pov_cpu', '')} |" if pov_col else "") +
                     f" {md_escape(note)} |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--glint", default=os.path.join(REPO, "build", "glint"))
    ap.add_argument("--cache", default="build/pov-examples",
                    help="pov_refs.py's cache (the references under CACHE/ref)")
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--timeout", type=float, default=30,
                    help="CPU seconds per scene (glint is stopped past them)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--threads", type=int, default=1, help="glint threads per scene")
    ap.add_argument("--only", action="append", default=[],
                    help="only scenes whose path contains this (repeatable)")
    ap.add_argument("--out", help="report file (default tests/pov_examples/REPORT.md, "
                                  "not written with --only unless given)")
    ap.add_argument("--json", help="also write the per-scene results as JSON")
    ap.add_argument("--keep", help="keep glint's images under this folder")
    ap.add_argument("--time-pov", action="store_true",
                    help="also time POV-Ray on each scene that agrees, right after glint "
                         "(runs one scene at a time)")
    args = ap.parse_args()
    args.width, args.height = (int(v) for v in args.size.split("x"))
    args.glint = os.path.abspath(args.glint)
    if not os.access(args.glint, os.X_OK):
        sys.exit(f"no glint binary at {args.glint} (--glint)")
    if not os.path.isdir(os.path.join(args.cache, "ref")):
        sys.exit(f"no references under {args.cache}/ref: run pov_refs.py --cache {args.cache}")
    if args.time_pov:
        args.jobs = 1  # per-process CPU times come from the children reaped, one at a time
    scenes = [s for s in list_scenes() if not args.only or any(f in s for f in args.only)]
    start = time.monotonic()
    results = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run_scene, s, args) for s in scenes]
        for fut in concurrent.futures.as_completed(futures):
            r = fut.result()
            results.append(r)
            extra = f" within={r['within']:.4f} ssim={r['ssim']:.4f}" if "within" in r else ""
            print(f"{r['verdict']:12s} {r['scene']}{extra} {r.get('error', '')[:100]}",
                  flush=True)
    elapsed = time.monotonic() - start
    out = args.out or (None if args.only else os.path.join(HERE, "REPORT.md"))
    if out:
        write_report(results, args, out, elapsed)
        print(f"wrote {out}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(sorted(results, key=lambda r: r["scene"]), f, indent=1)
    counts = {v: sum(1 for r in results if r["verdict"] == v) for v in VERDICTS}
    print(", ".join(f"{v}: {n}" for v, n in counts.items()))


if __name__ == "__main__":
    main()
