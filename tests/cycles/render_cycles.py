"""Renders one of the Cycles cross-check scenes with Cycles: a peer for `glint report`.

    blender -b --factory-startup --python tests/cycles/render_cycles.py -- \
        --scene NAME --spp N --out OUT.exr [--seed S | --seed-index K] [--threads T]
        [--time-file F]

    glint report tests/cycles/scenes/NAME.pov --reference tests/cycles/ref/NAME_mean.exr \
        --spp-steps 4,16,64,256 --out report-NAME \
        --peer "blender -b --factory-startup --python tests/cycles/render_cycles.py -- \
                --scene NAME --spp {spp} --out {out} --time-file {time}"

With glint report's --seeds, give it --seed-index {seed}: the K-th run renders with seed 101 + K.

The scene is rebuilt from the same code as make_scenes.py (no .blend files are kept), with the
same Cycles settings as the references (make_scenes.setup_render), and written as a linear
float OpenEXR.
"""

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_scenes  # noqa: E402  (Blender's Python finds it through the path above)


def main(argv):
    ap = argparse.ArgumentParser(prog="render_cycles.py")
    ap.add_argument("--scene", required=True, choices=sorted(make_scenes.BUILDERS))
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--out", required=True)
    # Not one of the references' seeds (1..16), so the peer's error against them is honest.
    ap.add_argument("--seed", type=int, default=101)
    # glint report --seeds: {seed} is 0, 1, ...; seed 101 + K keeps clear of the references'.
    ap.add_argument("--seed-index", type=int)
    ap.add_argument("--threads", type=int, default=0)
    # glint report's {time}: the seconds of the render call alone (Cycles' scene sync, BVH
    # build, path tracing and EXR write), Blender's start-up and the scene building left out,
    # as glint's own in-process timing leaves out its process start.
    ap.add_argument("--time-file")
    args = ap.parse_args(argv)
    seed = args.seed if args.seed_index is None else 101 + args.seed_index
    make_scenes.build(args.scene)
    start = time.perf_counter()
    make_scenes.render_to(os.path.abspath(args.out), args.spp, seed, threads=args.threads)
    seconds = time.perf_counter() - start
    if args.time_file:
        with open(args.time_file, "w") as f:
            f.write("%.6f\n" % seconds)


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
