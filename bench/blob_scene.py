#!/usr/bin/env python3
"""Blob scenes of many components, as molecule exports (VMD, ASE) write them, and their timing.

    bench/blob_scene.py write N out.pov [--seed S]
        one blob of N sphere components (radius 1.2, strength 1, threshold 0.6) at random
        places in a cube sized so that neighbours overlap about as atoms do, a camera and a light
    bench/blob_scene.py time --glint BIN [--glint BIN2 ...] [--runs 3] [--sizes 200,2000]
                             [--image 160x120]
        renders each size with POV-Ray 3.7 and each glint binary, no anti-aliasing, one thread,
        alternating them run by run; prints each one's median wall and CPU time, their ratios
        to POV-Ray's, and `glint compare` of its image against POV-Ray's

Both times run from process start to image written, parsing included. Wall time is what a user
waits for, but on a busy shared machine it counts other work; CPU time (user + system) does
not. POV-Ray's start-up (about 0.65 s of wall time, little CPU) dominates its wall time at
160x120. Compare ratios from one run, not times across runs.
"""
import argparse
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time


def scene(n, seed):
    rng = random.Random(seed)
    # About one atom per 13.8 cubic units (2.4 apart on average): each sphere's field reaches
    # a few neighbours, so rays cross chains of merged components, as in a molecule.
    side = 2.4 * n ** (1 / 3)
    h = side / 2
    lines = [
        "#version 3.7;",
        "global_settings { assumed_gamma 1.0 }",
        f"camera {{ location <0, {0.6 * side:.3f}, {-1.9 * side:.3f}> look_at <0, 0, 0>"
        " angle 40 }",
        f"light_source {{ <{side:.3f}, {2 * side:.3f}, {-1.5 * side:.3f}> color rgb 1 }}",
        "background { color rgb <0.1, 0.1, 0.15> }",
        "blob {",
        "  threshold 0.6",
    ]
    for _ in range(n):
        x, y, z = (rng.uniform(-h, h) for _ in range(3))
        lines.append(f"  sphere {{ <{x:.4f}, {y:.4f}, {z:.4f}>, 1.2, 1 }}")
    lines += [
        "  pigment { color rgb <0.9, 0.5, 0.3> }",
        "  finish { ambient 0.1 diffuse 0.7 specular 0.4 roughness 0.02 }",
        "}",
    ]
    return "\n".join(lines) + "\n"


def timed(cmd):
    """Wall seconds and CPU seconds (user + system) of one run of cmd."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        sys.exit(f"failed: {' '.join(cmd)}")
    return wall, usage.ru_utime + usage.ru_stime


def compare(glint, image, reference):
    out = subprocess.run([glint, "compare", image, reference], capture_output=True, text=True)
    return " ".join((out.stdout + out.stderr).split())


def time_all(args):
    sizes = [int(s) for s in args.sizes.split(",")]
    w, h = args.image.split("x")
    work = tempfile.mkdtemp(prefix="blob_bench_")
    for n in sizes:
        pov = os.path.join(work, f"blob{n}.pov")
        with open(pov, "w") as f:
            f.write(scene(n, args.seed))
        pov_png = os.path.join(work, f"blob{n}_pov.png")
        pov_cmd = ["povray", f"+W{w}", f"+H{h}", "-A", "+WT1", "-D", "-GA", pov, "+O" + pov_png]
        times = {"povray": []}
        glint_cmds = []
        for k, bin_ in enumerate(args.glint):
            png = os.path.join(work, f"blob{n}_glint{k}.png")
            glint_cmds.append((bin_, png, [bin_, "render", pov, "-o", png, "-W", w, "-H", h,
                                           "--threads", "1", "--progress=none"]))
            times[bin_] = []  # (wall, cpu) per run
        for _ in range(args.runs):
            times["povray"].append(timed(pov_cmd))
            for bin_, _, cmd in glint_cmds:
                times[bin_].append(timed(cmd))
        def medians(runs):
            return (statistics.median(w for w, _ in runs), statistics.median(c for _, c in runs))

        pw, pc = medians(times["povray"])
        print(f"{n} components: povray wall {pw:.3f} s, cpu {pc:.3f} s")
        for bin_, png, _ in glint_cmds:
            gw, gc = medians(times[bin_])
            print(f"  {bin_}: wall {gw:.3f} s, cpu {gc:.3f} s; glint/povray wall "
                  f"{gw / pw:.3f}, cpu {gc / pc:.3f}; {compare(args.glint[-1], png, pov_png)}")
        sys.stdout.flush()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="what", required=True)
    w = sub.add_parser("write")
    w.add_argument("n", type=int)
    w.add_argument("out")
    w.add_argument("--seed", type=int, default=1)
    t = sub.add_parser("time")
    t.add_argument("--glint", action="append", required=True)
    t.add_argument("--runs", type=int, default=3)
    t.add_argument("--sizes", default="200,2000")
    t.add_argument("--seed", type=int, default=1)
    t.add_argument("--image", default="160x120", help="WxH")
    args = ap.parse_args()
    if args.what == "write":
        with open(args.out, "w") as f:
            f.write(scene(args.n, args.seed))
    else:
        time_all(args)


if __name__ == "__main__":
    main()
