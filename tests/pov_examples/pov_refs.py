#!/usr/bin/env python3
"""Renders POV-Ray 3.7's own example scenes with POV-Ray itself: the references of the
compatibility report (compat.py). Each scene is rendered once, without anti-aliasing, one
thread, from a scratch working directory (POV-Ray may write there), with the scene's folder and
POV-Ray's include folder on the library path. Results are cached:

    CACHE/ref/<scene path>.png   the image (absent when POV-Ray failed or ran out of time)
    CACHE/ref/<scene path>.json  {"status": "ok"|"failed"|"timeout", "seconds": s, "log": tail}

A scene already in the cache is skipped, so an interrupted run continues where it stopped.

    tests/pov_examples/pov_refs.py [--cache build/pov-examples] [--size 160x120] [--timeout 120]
                                   [--jobs 1] [SCENE-SUBSTRING...]
"""
import argparse
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

EXAMPLES = "/usr/share/doc/povray/examples"
INCLUDE = "/usr/share/povray-3.7/include"


def list_scenes(root=EXAMPLES):
    scenes = []
    for folder, _dirs, files in os.walk(root):
        for f in files:
            if f.endswith(".pov"):
                scenes.append(os.path.relpath(os.path.join(folder, f), root))
    return sorted(scenes)


def render(scene, cache, width, height, timeout):
    png = os.path.join(cache, "ref", scene[:-4] + ".png")
    meta = png[:-4] + ".json"
    if os.path.exists(meta):
        return scene, None
    os.makedirs(os.path.dirname(png), exist_ok=True)
    src = os.path.join(EXAMPLES, scene)
    work = tempfile.mkdtemp(prefix="glint-povref.")
    cmd = ["nice", "-n", "10", "povray", "+I" + src, "+O" + os.path.join(work, "out.png"),
           f"+W{width}", f"+H{height}", "-A", "+WT1", "-D", "-V", "+FN",
           "+L" + os.path.dirname(src), "+L" + INCLUDE]
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              timeout=timeout)
        status = "ok" if proc.returncode == 0 and os.path.exists(
            os.path.join(work, "out.png")) else "failed"
        log = proc.stdout.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as e:
        status = "timeout"
        log = (e.stdout or b"").decode("utf-8", "replace")
    seconds = time.monotonic() - start
    if status == "ok":
        shutil.copyfile(os.path.join(work, "out.png"), png)
    shutil.rmtree(work, ignore_errors=True)
    with open(meta, "w") as f:
        json.dump({"status": status, "seconds": round(seconds, 3),
                   "log": "\n".join(log.splitlines()[-12:])}, f, indent=1)
    return scene, status


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cache", default="build/pov-examples")
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("filters", nargs="*")
    args = ap.parse_args()
    if not shutil.which("povray"):
        sys.exit("povray is not installed (apt-get install povray povray-examples)")
    width, height = (int(v) for v in args.size.split("x"))
    scenes = [s for s in list_scenes() if not args.filters or any(f in s for f in args.filters)]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(render, s, args.cache, width, height, args.timeout) for s in scenes]
        for fut in concurrent.futures.as_completed(futures):
            scene, status = fut.result()
            if status:
                print(f"{status:8s} {scene}", flush=True)


if __name__ == "__main__":
    main()
