"""Cancel: SIGINT to a headless `blender -b ... -E GLINT -f 1` while glint renders a heavy scene
must end Blender within a few seconds, leave no glint process (checked by pid) and no temporary
render folder behind, and write no image.

    blender -b --factory-startup --python-exit-code 1 --python tests/plugin/test_cancel.py -- \
        --glint build/glint
"""

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_env  # noqa: E402
import bpy  # noqa: E402
from plugin_test_util import (alive, blender_render_cmd, child_pids, fail,  # noqa: E402
                              process_name, script_args)

MAX_EXIT_S = 5.0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--glint", required=True)
    args = ap.parse_args(script_args())
    glint = os.path.abspath(args.glint)

    work = tempfile.mkdtemp(prefix="glint_test_cancel_")
    tmp = os.path.join(work, "tmp")  # the child's TMPDIR: its render folders go there
    os.makedirs(tmp)
    addon_env.enable(glint)
    addon_env.build_scene(heavy=True, light=None)
    blend = os.path.join(work, "heavy.blend")
    bpy.ops.wm.save_as_mainfile(filepath=blend)

    env = dict(os.environ, GLINT_BINARY=glint, TMPDIR=tmp)
    out_pattern = os.path.join(work, "out_####")
    proc = subprocess.Popen(blender_render_cmd(blend, out_pattern), env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    # Wait for glint to run (a child of Blender named glint) and to have rendered a little.
    glint_pid = None
    deadline = time.monotonic() + 60
    while glint_pid is None and time.monotonic() < deadline and proc.poll() is None:
        for pid in child_pids(proc.pid):
            if process_name(pid) == "glint":
                glint_pid = pid
        time.sleep(0.05)
    if glint_pid is None:
        out = proc.communicate()[0] if proc.poll() is not None else ""
        proc.kill()
        fail("glint never started under Blender:\n" + out)
    render_dirs = [d for d in os.listdir(tmp) if d.startswith("glint_render_")]
    if not render_dirs:
        fail("no glint_render_* folder in the child's TMPDIR %s" % tmp)
    time.sleep(1.5)
    if proc.poll() is not None:
        fail("Blender ended before the cancel (the scene is not heavy enough):\n" +
             proc.communicate()[0])

    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    try:
        output = proc.communicate(timeout=30)[0]
    except subprocess.TimeoutExpired:
        proc.kill()
        fail("Blender still runs 30 s after SIGINT")
    blender_s = time.monotonic() - sent
    glint_gone = not alive(glint_pid)
    print(output[-1500:])
    print("cancel: Blender exited %.2f s after SIGINT (exit code %d); glint pid %d %s"
          % (blender_s, proc.returncode, glint_pid, "gone" if glint_gone else "STILL RUNNING"))
    if not glint_gone:
        os.kill(glint_pid, signal.SIGKILL)
        fail("glint (pid %d) outlived the cancel" % glint_pid)
    if blender_s > MAX_EXIT_S:
        fail("Blender took %.2f s to exit after SIGINT (limit %.1f s)" % (blender_s, MAX_EXIT_S))
    left = [d for d in os.listdir(tmp) if d.startswith("glint_render_")]
    if left:
        fail("temporary files left behind: %s" % left)
    images = [f for f in os.listdir(work) if f.startswith("out_")]
    if images:
        fail("a cancelled render wrote %s" % images)
    shutil.rmtree(work, ignore_errors=True)
    print("PASS test_cancel")


main()
