"""Shared by the plugin tests that drive `blender -b` as a child process (cancel, failure)."""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ADDON_ENV = os.path.join(HERE, "addon_env.py")


def script_args():
    """The arguments after `--` on Blender's command line."""
    return sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []


def blender_binary():
    import bpy
    return bpy.app.binary_path or "blender"


def blender_render_cmd(blend, out_pattern, frame=1):
    """`blender -b FILE --python addon_env.py -E GLINT -o OUT -f N` (the add-on enabled from
    this tree, the glint binary from $GLINT_BINARY)."""
    return [blender_binary(), "-b", "--factory-startup", blend, "--python", ADDON_ENV,
            "-E", "GLINT", "-o", out_pattern, "-F", "OPEN_EXR", "-f", str(frame)]


def child_pids(pid):
    """Direct children of pid (from /proc)."""
    kids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            kids.append(int(entry))
    return kids


def process_name(pid):
    try:
        with open("/proc/%d/comm" % pid) as f:
            return f.read().strip()
    except OSError:
        return None


def alive(pid):
    """Exists and is not a zombie."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def fail(msg):
    print("FAIL: " + msg)
    sys.stdout.flush()
    os._exit(1)


def run(cmd, env, timeout=120):
    return subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, timeout=timeout)
