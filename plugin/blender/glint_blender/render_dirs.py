"""The per-render temporary folders: made, marked with their owner, and swept.

A render's export and image live in tempdir/glint_render_XXXX, removed when the render ends in
any way the add-on sees (engine.py). A Blender that crashes or is killed cannot remove its own,
so each folder holds an owner file (the Blender process's pid and start time) and every new
render first removes the folders whose owner is gone. Folders kept on purpose (the keep_temp
preference) hold a keep file and are never swept. No Blender API here: testable without it.
"""

import os
import shutil
import tempfile
import time

PREFIX = "glint_render_"
OWNER_FILE = ".glint_owner"
KEEP_FILE = ".glint_keep"
# A folder without an owner file (one being made right now, or an older add-on's) is only
# swept once it is this old.
UNOWNED_GRACE_S = 3600.0


def _start_time(pid):
    """The process's start time in clock ticks since boot (Linux /proc), or None."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            return int(f.read().rsplit(")", 1)[1].split()[19])
    except (OSError, IndexError, ValueError):
        return None


def _alive(pid, start):
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass  # someone else's process: it exists
    now = _start_time(pid)
    return start is None or now is None or now == start  # another start time: pid reused


def create():
    """Sweeps dead renders' folders, then makes this render's, owned by this process."""
    sweep()
    path = tempfile.mkdtemp(prefix=PREFIX)
    with open(os.path.join(path, OWNER_FILE), "w", encoding="utf-8") as f:
        f.write("%d %s\n" % (os.getpid(), _start_time(os.getpid())))
    return path


def keep(path):
    """Marks a folder as kept on purpose: sweep() leaves it."""
    with open(os.path.join(path, KEEP_FILE), "w", encoding="utf-8") as f:
        f.write("kept by the glint add-on's keep_temp preference\n")


def remove(path):
    shutil.rmtree(path, ignore_errors=True)


def _owner_gone(path):
    try:
        with open(os.path.join(path, OWNER_FILE), encoding="utf-8") as f:
            fields = f.read().split()
        pid = int(fields[0])
        start = int(fields[1]) if len(fields) > 1 and fields[1] != "None" else None
    except (OSError, ValueError, IndexError):
        try:
            return time.time() - os.stat(path).st_mtime > UNOWNED_GRACE_S
        except OSError:
            return False
    return not _alive(pid, start)


def sweep(parent=None):
    """Removes the folders under `parent` (default: the temp folder) left by renders whose
    Blender is gone. Returns the paths removed."""
    parent = parent or tempfile.gettempdir()
    removed = []
    try:
        names = os.listdir(parent)
    except OSError:
        return removed
    uid = os.getuid() if hasattr(os, "getuid") else None
    for name in names:
        if not name.startswith(PREFIX):
            continue
        path = os.path.join(parent, name)
        try:
            st = os.lstat(path)
        except OSError:
            continue
        if not os.path.isdir(path) or os.path.islink(path):
            continue
        if uid is not None and st.st_uid != uid:
            continue  # another user's render
        if os.path.exists(os.path.join(path, KEEP_FILE)) or not _owner_gone(path):
            continue
        remove(path)
        removed.append(path)
    return removed
