"""Renders a saved add-on test scene with Cycles: a peer for `glint report`.

    blender -b BUILD/tests/plugin/scenes/NAME.blend --python tests/plugin/peer_cycles.py -- \
        --spp N --out OUT.exr [--seed-index K] [--threads T] [--time-file F]

    glint report EXPORTED/scene.json --reference tests/plugin/ref/NAME_mean.exr \
        --spp-steps 16,64,256 --seeds 2 --peer-name cycles \
        --peer "blender -b NAME.blend --python tests/plugin/peer_cycles.py -- \
                --spp {spp} --out {out} --time-file {time} --seed-index {seed}"

The scene keeps the Cycles settings make_scenes.py saved in it (the references' own); the
seed is 101 + K, clear of the references' 1..16. {time} gets the seconds of the render call
alone (Cycles' sync, BVH, path tracing and EXR write), Blender's start-up left out.
"""

import argparse
import sys
import time

import bpy


def main(argv):
    ap = argparse.ArgumentParser(prog="peer_cycles.py")
    ap.add_argument("--spp", type=int, required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--seed-index", type=int, default=0)
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--time-file")
    args = ap.parse_args(argv)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.samples = args.spp
    scene.cycles.seed = 101 + args.seed_index
    if args.threads > 0:
        scene.render.threads_mode = "FIXED"
        scene.render.threads = args.threads
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = args.out
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    if args.time_file:
        with open(args.time_file, "w") as f:
            f.write("%.6f\n" % (time.perf_counter() - start))


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
