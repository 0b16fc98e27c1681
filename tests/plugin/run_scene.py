#!/usr/bin/env python3
"""One tests/plugin CTest: a scene rendered through the glint add-on in headless Blender,
re-rendered from the exported folder with the CLI, and Z-tested against Cycles.

    run_scene.py --name NAME --blender BLENDER --glint GLINT --ztest CYCLES_ZTEST \
                 --scenes DIR_WITH_NAME.blend --ref tests/plugin/ref --work OUT_DIR [--threads 2]

Steps (each failure is reported and makes the test fail):
 1. `blender -b --factory-startup NAME.blend --python enable_addon.py -E GLINT
     -o WORK/blender_#### -F OPEN_EXR -f 1` (anim: -a, frames 1-3), with BLENDER_USER_SCRIPTS
    holding a link to plugin/blender/glint_blender and TMPDIR inside WORK, so the kept
    per-render folders (keep_temp) land there.
 2. Each exported folder's command.txt is run again with GLINT (its -o redirected into WORK,
    --variance added): Blender's EXR (full float) must equal that image bit for bit.
 3. cycles_ztest compare CLI.exr CLI.variance.exr REF_mean.exr REF_stderr.exr: >= 99.75% of
    the pixels accepted (tests/plugin/README.md).
 4. With REF_alpha_mean.exr (transparent film): compare_exr.py alpha, the CLI image's alpha
    against Cycles' (>= 99.75% of the pixels accepted).
 anim: every frame goes through 2 and 3, and consecutive frames must differ (relMSE >= 0.01).
Times (Blender + add-on + glint wall seconds; the CLI re-render alone) are printed, and the
Cycles seconds per seed image of the references from ref/cycles_times.txt if present.
"""

import argparse
import json
import os
import shlex
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
ANIM_FRAMES = (1, 2, 3)
MIN_FRAME_RELMSE = 0.01


class Failure(Exception):
    pass


def run(cmd, env=None, cwd=None, log=None):
    print("+ " + " ".join(shlex.quote(c) for c in cmd), flush=True)
    t0 = time.time()
    p = subprocess.run(cmd, env=env, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, errors="replace")
    dt = time.time() - t0
    if log:
        with open(log, "w") as f:
            f.write(p.stdout)
    return p.returncode, p.stdout, dt


def blender_env(extra=None):
    """The environment for Blender: without a pyenv (or virtualenv) interpreter first on PATH,
    which Blender's embedded Python would otherwise take its standard library from (and then
    lack numpy)."""
    env = dict(os.environ, **(extra or {}))
    env["PATH"] = os.pathsep.join(p for p in env.get("PATH", "").split(os.pathsep)
                                  if "/.pyenv/" not in p and p != os.environ.get("VIRTUAL_ENV"))
    for k in ("PYTHONHOME", "PYTHONPATH", "VIRTUAL_ENV"):
        env.pop(k, None)
    return env


def tail(text, n=25):
    return "\n".join(text.rstrip().splitlines()[-n:])


def blender_compare(args, *rest):
    rc, out, _ = run([args.blender, "-b", "--factory-startup", "--python-exit-code", "1",
                      "--python", os.path.join(HERE, "compare_exr.py"), "--", *rest],
                      env=blender_env())
    for line in out.splitlines():
        if line.startswith("compare_exr:"):
            print(line)
    return rc


def export_frame(folder):
    """The frame an export folder holds (scene.json's render.frame), or None."""
    try:
        with open(os.path.join(folder, "scene.json")) as f:
            frame = json.load(f).get("render", {}).get("frame")
        return int(frame) if frame is not None else None
    except (OSError, ValueError):
        return None


def find_exports(tmp):
    """The kept per-render folders (every folder under tmp holding command.txt), in frame order
    (scene.json's render.frame), else oldest first."""
    found = []
    for root, _dirs, files in os.walk(tmp):
        if "command.txt" in files:
            path = os.path.join(root, "command.txt")
            frame = export_frame(root)
            found.append((frame if frame is not None else 0, os.path.getmtime(path), root))
    return [r for _f, _t, r in sorted(found)]


def cli_argv(export_dir, glint, out_exr, threads):
    """command.txt's line with the binary replaced, -o redirected and --variance added."""
    with open(os.path.join(export_dir, "command.txt")) as f:
        argv = shlex.split(f.read().strip())
    if not argv or os.path.basename(argv[0]) != "glint":
        raise Failure("%s/command.txt does not start with glint: %r" % (export_dir, argv[:2]))
    argv = [glint] + argv[1:]
    if "-o" not in argv:
        raise Failure("%s/command.txt has no -o OUT" % export_dir)
    argv[argv.index("-o") + 1] = out_exr
    argv.append("--variance")
    if threads:  # the image is the same whatever the count; this only fixes the timing
        if "--threads" in argv:
            argv[argv.index("--threads") + 1] = str(threads)
        else:
            argv += ["--threads", str(threads)]
    return argv


def cycles_seconds(ref_dir, ref_name):
    path = os.path.join(ref_dir, "cycles_times.txt")
    if not os.path.exists(path):
        return None
    t = [float(l.split()[2]) for l in open(path) if l.split() and l.split()[0] == ref_name]
    return sorted(t)[len(t) // 2] if t else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--name", required=True)
    ap.add_argument("--blender", required=True)
    ap.add_argument("--glint", required=True)
    ap.add_argument("--ztest", required=True)
    ap.add_argument("--scenes", required=True)
    ap.add_argument("--ref", default=os.path.join(HERE, "ref"))
    ap.add_argument("--work", required=True)
    ap.add_argument("--threads", type=int, default=0)
    args = ap.parse_args()
    args.glint, args.ztest = os.path.abspath(args.glint), os.path.abspath(args.ztest)
    args.ref, args.scenes = os.path.abspath(args.ref), os.path.abspath(args.scenes)
    name = args.name
    anim = name == "anim"
    frames = ANIM_FRAMES if anim else (1,)
    ref_names = ["%s_f%d" % (name, f) for f in frames] if anim else [name]

    work = os.path.abspath(os.path.join(args.work, name))
    shutil.rmtree(work, ignore_errors=True)
    addons = os.path.join(work, "scripts", "addons")
    tmp = os.path.join(work, "tmp")
    os.makedirs(addons)
    os.makedirs(tmp)
    os.symlink(os.path.join(ROOT, "plugin", "blender", "glint_blender"),
               os.path.join(addons, "glint_blender"))
    env = blender_env(dict(BLENDER_USER_SCRIPTS=os.path.join(work, "scripts"), TMPDIR=tmp,
               TMP=tmp, TEMP=tmp, GLINT_TEST_BINARY=os.path.abspath(args.glint),
               GLINT_TEST_THREADS=str(args.threads)))
    failures = []

    # 1. Render through the add-on.
    blend = os.path.join(args.scenes, name + ".blend")
    cmd = [args.blender, "-b", "--factory-startup", "--python-exit-code", "1", blend,
           "--python", os.path.join(HERE, "enable_addon.py"), "-E", "GLINT",
           "-o", os.path.join(work, "blender_####"), "-F", "OPEN_EXR"]
    cmd += ["-a"] if anim else ["-f", "1"]
    rc, out, t_blender = run(cmd, env=env, log=os.path.join(work, "blender.log"))
    blender_exrs = [os.path.join(work, "blender_%04d.exr" % f) for f in frames]
    missing = [p for p in blender_exrs if not os.path.exists(p)]
    if rc != 0 or missing:
        print(tail(out, 40))
        raise Failure("blender exited %d%s" % (rc, "; missing " + ", ".join(missing)
                                                  if missing else ""))
    print("%s: add-on render of %d frame(s) in Blender: %.2f s wall (Blender start, export, "
          "glint)" % (name, len(frames), t_blender))
    warnings = [l for l in out.splitlines() if "WARNING" in l.upper()]
    for w in warnings[:20]:
        print("%s: Blender reported: %s" % (name, w.strip()))

    exports = find_exports(tmp)
    if len(exports) != len(frames):
        raise Failure("expected %d kept export folder(s) with command.txt under %s, found %d "
                      "(is keep_temp honoured, and the folder made under TMPDIR?)"
                      % (len(frames), tmp, len(exports)))

    cli_exrs = []
    for frame, ref_name, export, bl_exr in zip(frames, ref_names, exports, blender_exrs):
        # 2. Re-render from command.txt.
        cli_exr = os.path.join(work, ref_name + ".exr")
        argv = cli_argv(export, args.glint, cli_exr, args.threads)
        rc, out, t_cli = run(argv, cwd=export, log=os.path.join(work, ref_name + ".log"))
        if rc != 0 or not os.path.exists(cli_exr):
            print(tail(out))
            failures.append("%s: the CLI re-render from %s/command.txt exited %d"
                            % (ref_name, export, rc))
            continue
        cli_exrs.append(cli_exr)
        t_cycles = cycles_seconds(args.ref, ref_name)
        print("%s: glint CLI at 256 spp: %.2f s wall (threads %s); Cycles 3.4 at 256 spp "
              "(reference seed images, median): %s" % (
                  ref_name, t_cli, args.threads or "all",
                  "%.2f s" % t_cycles if t_cycles else "not recorded"))
        if blender_compare(args, "same", bl_exr, cli_exr) != 0:
            failures.append("%s: the add-on's image differs from the CLI re-render" % ref_name)
        # 3. Z-test against Cycles.
        mean = os.path.join(args.ref, ref_name + "_mean.exr")
        stderr = os.path.join(args.ref, ref_name + "_stderr.exr")
        variance = os.path.join(work, ref_name + ".variance.exr")
        rc, out, _ = run([args.ztest, "compare", cli_exr, variance, mean, stderr, work])
        print(tail(out, 50))
        if rc != 0:
            failures.append("%s: Z-test against Cycles failed (exit %d)" % (ref_name, rc))
        # 4. Transparent film: alpha against Cycles' alpha (16 seed images).
        alpha_mean = os.path.join(args.ref, ref_name + "_alpha_mean.exr")
        if os.path.exists(alpha_mean):
            if blender_compare(args, "alpha", cli_exr, alpha_mean,
                               os.path.join(args.ref, ref_name + "_alpha_stderr.exr"),
                               "16", "256") != 0:
                failures.append("%s: alpha differs from Cycles'" % ref_name)

    if anim:
        for a, b in zip(blender_exrs, blender_exrs[1:]):
            if blender_compare(args, "differ", a, b, str(MIN_FRAME_RELMSE)) != 0:
                failures.append("anim: %s and %s are (nearly) the same picture" % (a, b))

    if failures:
        raise Failure("\n  ".join(failures))
    print("%s: PASS" % name)


if __name__ == "__main__":
    try:
        main()
    except Failure as e:
        print("FAIL: " + str(e))
        sys.exit(1)
