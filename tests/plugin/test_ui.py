"""The add-on in Blender's UI (F12), where RenderEngine.render() runs on the render job's thread
and the OBJ export is queued to the main thread (engine.py). Needs a display: run it under Xvfb.

    xvfb-run -a -s "-screen 0 800x600x24" blender --factory-startup \
        --python tests/plugin/test_ui.py -- --glint build/glint

1. F12 on a small scene (render.render('INVOKE_DEFAULT') in the window's context, as the key
   does): render() must run off the main thread and the export on it, the main thread must keep
   running its event loop, the job must end through render_complete with no error
   reported, and the Render Result (saved with save_render) must have the scene's size and not
   be black; no temp folder left. The same with Lock Interface, Ctrl F12 over two frames, a
   scene holding an object of every type (object_types.py), and with a glint binary that is
   not there (one error report).
2. Esc (a key event from the X server) while glint renders a heavy scene: glint's process must
   be gone within 1 s of the engine's test_break() turning true (the key's own latency through
   Blender's event loop is printed), render_cancel must fire, no temp folder left.
Exits 0 on success, 1 on failure (os._exit: quit_blender always exits 0).
"""

import argparse
import ctypes
import ctypes.util
import os
import shutil
import sys
import tempfile
import threading
import time
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_env  # noqa: E402
import bpy  # noqa: E402
import object_types  # noqa: E402
from bpy.app.handlers import persistent  # noqa: E402
from plugin_test_util import alive, child_pids, process_name, script_args  # noqa: E402

RENDER_TIMEOUT_S = 120.0
GLINT_GONE_S = 1.0
MIN_TICKS = 3  # timer calls on the main thread while glint renders

STATE = {"complete": 0, "cancel": 0, "errors": [], "render_threads": [], "export_threads": [],
         "progress": 0, "glint_runs": [],
         "break_at": None}
WORK = tempfile.mkdtemp(prefix="glint_test_ui_")
TMP = os.path.join(WORK, "tmp")  # the add-on's render folders go here (tempfile.tempdir)


def log(msg):
    print("ui: " + msg, flush=True)


def finish(code, msg):
    log(msg)
    if code == 0:
        print("PASS test_ui", flush=True)
    else:
        print("FAIL: " + msg, flush=True)
        for pid in child_pids(os.getpid()):  # never leave a glint behind
            if process_name(pid) == "glint":
                os.kill(pid, 9)
    shutil.rmtree(WORK, ignore_errors=True)
    scripts = bpy.context.preferences.filepaths.script_directory
    if scripts and os.path.basename(scripts.rstrip("/")).startswith("glint_addon_scripts_"):
        shutil.rmtree(scripts, ignore_errors=True)
    sys.stdout.flush()
    os._exit(code)


class Failure(Exception):
    pass


def check(cond, msg):
    if not cond:
        raise Failure(msg)


@persistent
def on_complete(*_):
    STATE["complete"] += 1


@persistent
def on_cancel(*_):
    STATE["cancel"] += 1


def instrument():
    """Records on which thread render() and the export run, the engine's error reports, glint's
    progress lines and run times (wrapping the add-on's own Python functions; RNA methods such
    as update_progress cannot be wrapped on the class)."""
    engine = sys.modules["glint_blender.engine"]
    cls = engine.GlintRenderEngine
    main = threading.main_thread

    orig_render, orig_error = cls.render, cls._error
    orig_export = engine.native_export.export_frame_native

    def render(self, depsgraph):
        STATE["render_threads"].append(threading.current_thread() is main())
        return orig_render(self, depsgraph)

    def error(self, msg):
        STATE["errors"].append(msg)
        return orig_error(self, msg)

    orig_run = engine.runner.run

    def run(cmd, *a, on_progress=None, test_break=None, **kw):
        def progress(p):
            STATE["progress"] += 1
            if on_progress:
                on_progress(p)

        def brk():
            stop = bool(test_break and test_break())
            if stop and STATE["break_at"] is None:
                STATE["break_at"] = time.monotonic()
            return stop
        t = time.monotonic()
        try:
            return orig_run(cmd, *a, on_progress=progress, test_break=brk, **kw)
        finally:
            STATE["glint_runs"].append((t, time.monotonic()))

    def export_frame(*a, **kw):
        STATE["export_threads"].append(threading.current_thread() is main())
        return orig_export(*a, **kw)

    cls.render, cls._error, engine.runner.run = render, error, run
    engine.native_export.export_frame_native = export_frame


def f12(animation=False):
    """render.render('INVOKE_DEFAULT') in the main window's largest area, as F12 (Ctrl F12)
    does there."""
    win = bpy.context.window_manager.windows[0]
    area = max(win.screen.areas, key=lambda a: a.width * a.height)
    region = next(r for r in area.regions if r.type == 'WINDOW')
    with bpy.context.temp_override(window=win, area=area, region=region):
        return bpy.ops.render.render('INVOKE_DEFAULT', animation=animation)


class _XKeyEvent(ctypes.Structure):
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong),
                ("send_event", ctypes.c_int), ("display", ctypes.c_void_p),
                ("window", ctypes.c_ulong), ("root", ctypes.c_ulong),
                ("subwindow", ctypes.c_ulong), ("time", ctypes.c_ulong),
                ("x", ctypes.c_int), ("y", ctypes.c_int), ("x_root", ctypes.c_int),
                ("y_root", ctypes.c_int), ("state", ctypes.c_uint), ("keycode", ctypes.c_uint),
                ("same_screen", ctypes.c_int), ("pad", ctypes.c_long * 24)]  # >= sizeof(XEvent)


def press_escape():
    """A real Esc key press and release from the X server, sent to each of Blender's top-level
    windows (XSendEvent through libX11, which Blender itself links): Blender turns an Esc
    from the window system into G.is_break, the flag its render job's test_break reads
    (Window.event_simulate cannot: simulated events skip that, and --enable-event-simulate
    drops real ones). Returns the names of the windows it was sent to."""
    x11 = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XDefaultRootWindow.restype = ctypes.c_ulong
    x11.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
    x11.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                               ctypes.POINTER(ctypes.c_ulong),
                               ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)),
                               ctypes.POINTER(ctypes.c_uint)]
    x11.XFetchName.argtypes = [ctypes.c_void_p, ctypes.c_ulong,
                               ctypes.POINTER(ctypes.c_char_p)]
    x11.XKeysymToKeycode.restype = ctypes.c_ubyte
    x11.XKeysymToKeycode.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
    x11.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long,
                               ctypes.POINTER(_XKeyEvent)]
    x11.XFlush.argtypes = x11.XCloseDisplay.argtypes = x11.XFree.argtypes = [ctypes.c_void_p]
    d = x11.XOpenDisplay(None)
    check(d, "Esc: cannot open the X display %s" % os.environ.get("DISPLAY"))
    root = x11.XDefaultRootWindow(d)
    r, p, n = ctypes.c_ulong(), ctypes.c_ulong(), ctypes.c_uint()
    kids = ctypes.POINTER(ctypes.c_ulong)()
    x11.XQueryTree(d, root, ctypes.byref(r), ctypes.byref(p), ctypes.byref(kids), ctypes.byref(n))
    targets = []
    for i in range(n.value):
        name = ctypes.c_char_p()
        if x11.XFetchName(d, kids[i], ctypes.byref(name)) and name.value:
            if b"Blender" in name.value:
                targets.append((kids[i], name.value.decode(errors="replace")))
    if kids:
        x11.XFree(kids)
    keycode = x11.XKeysymToKeycode(d, 0xff1b)  # XK_Escape
    for win, _ in targets:
        for event_type, mask in ((2, 1), (3, 2)):  # KeyPress/KeyPressMask, KeyRelease/...Mask
            ev = _XKeyEvent(type=event_type, send_event=1, display=d, window=win, root=root,
                            keycode=keycode, same_screen=1, x=10, y=10, x_root=10, y_root=10)
            x11.XSendEvent(d, win, 1, mask, ctypes.byref(ev))
    x11.XFlush(d)
    x11.XCloseDisplay(d)
    return [name for _, name in targets]


class Watcher(threading.Thread):
    """Records when a process is gone, polling every 5 ms off the (slow) main thread."""

    def __init__(self, pid):
        super().__init__(daemon=True)
        self.pid, self.gone_at = pid, None
        self.start()

    def run(self):
        while alive(self.pid):
            time.sleep(0.005)
        self.gone_at = time.monotonic()


def render_dirs():
    return [d for d in os.listdir(TMP) if d.startswith("glint_render_")]


def glint_children():
    return [p for p in child_pids(os.getpid()) if process_name(p) == "glint"]


def wait_render_end(what, n0):
    """Yields poll intervals until render_complete or render_cancel fired (n0: their count
    before the render started) and the job ended.
    Returns the longest gap between two calls once the export ran (before it, Blender opens
    and draws the render window, slow under software GL)."""
    start = last = time.monotonic()
    longest = 0.0
    while (STATE["complete"] + STATE["cancel"] == n0 or bpy.app.is_job_running('RENDER')):
        now = time.monotonic()
        if STATE["export_threads"]:
            longest = max(longest, now - last)
        if os.environ.get("GLINT_UI_DEBUG"):
            log("tick +%.3f export %s glint %s" % (now - start, STATE["export_threads"],
                                                  glint_children()))
        last = now
        check(now - start < RENDER_TIMEOUT_S, "%s: the render did not end within %d s"
              % (what, RENDER_TIMEOUT_S))
        yield 0.02
    return longest


def reset():
    STATE["render_threads"].clear()
    STATE["export_threads"].clear()
    STATE["progress"] = 0
    STATE["errors"].clear()
    STATE["glint_runs"].clear()
    STATE["break_at"] = None


def f12_case(what, scene, frames=1):
    """F12 (Ctrl F12 with frames > 1) to the end, then the checks of case 1."""
    reset()
    n_complete, n_cancel = STATE["complete"], STATE["cancel"]
    t0 = time.monotonic()
    res = f12(animation=frames > 1)
    check('RUNNING_MODAL' in res, "%s did not start a render job: %s" % (what, sorted(res)))
    longest = yield from wait_render_end(what, n_complete + n_cancel)
    took = time.monotonic() - t0
    runs = ", ".join("%.2f s" % (b - a) for a, b in STATE["glint_runs"])
    log("%s: ended after %.2f s (complete %d, cancel %d); glint ran %s; render() on main "
        "thread: %s, export on main thread: %s; longest main-loop gap %.2f s; %d progress "
        "lines; errors: %s"
        % (what, took, STATE["complete"] - n_complete, STATE["cancel"] - n_cancel, runs,
           STATE["render_threads"], STATE["export_threads"], longest, STATE["progress"],
           STATE["errors"]))
    check(STATE["complete"] == n_complete + 1 and STATE["cancel"] == n_cancel,
          "%s: the render did not complete" % what)
    check(STATE["errors"] == [], "%s: the engine reported %s" % (what, STATE["errors"]))
    check(STATE["progress"] > 0, "%s: no progress line reached the engine" % what)
    check(STATE["render_threads"] == [False] * frames,
          "%s: render() did not run %d time(s) on the job thread: %s"
          % (what, frames, STATE["render_threads"]))
    check(STATE["export_threads"] == [True] * frames,
          "%s: the export did not run %d time(s) on the main thread: %s"
          % (what, frames, STATE["export_threads"]))
    check(len(STATE["glint_runs"]) == frames, "%s: glint ran %d times"
          % (what, len(STATE["glint_runs"])))
    check(render_dirs() == [], "%s: temp folder left: %s" % (what, render_dirs()))


def check_image(what, path, size):
    """The image at path: `size` and not black."""
    loaded = bpy.data.images.load(path)
    w, h = loaded.size
    px = loaded.pixels[:]
    n = w * h
    mean = [sum(px[c::4]) / max(1, n) for c in range(3)]
    lit = sum(1 for i in range(n) if px[4 * i] + px[4 * i + 1] + px[4 * i + 2] > 0.05)
    bpy.data.images.remove(loaded)
    log("%s: %s %dx%d, mean RGB (%.4f, %.4f, %.4f), %d of %d pixels lit"
        % (what, os.path.basename(path), w, h, mean[0], mean[1], mean[2], lit, n))
    check((w, h) == size, "%s: the image is %dx%d, not %dx%d" % (what, w, h, *size))
    check(sum(mean) > 0.05 and lit > n // 4, "%s: the image is black" % what)
    return mean


def steps(glint):
    yield 0.5  # let the window settle
    addon_env.enable(glint)
    instrument()
    pump = sys.modules["glint_blender.engine"]._pump
    check(bpy.app.timers.is_registered(pump), "the add-on's main-thread timer is not registered")
    bpy.app.handlers.render_complete.append(on_complete)
    bpy.app.handlers.render_cancel.append(on_cancel)

    # ---- 1. F12 on a small scene; the Render Result through save_render.
    scene = addon_env.build_scene(width=96, height=64, samples=16, light='AREA')
    yield from f12_case("F12", scene)
    saved = os.path.join(WORK, "f12.exr")
    bpy.data.images["Render Result"].save_render(saved, scene=scene)
    check(os.path.isfile(saved), "F12: the Render Result could not be saved")
    mean = check_image("F12: Render Result", saved, (96, 64))

    # ---- 1b. The same with Render > Lock Interface (the main thread must still export).
    scene.render.use_lock_interface = True
    yield from f12_case("F12 with Lock Interface", scene)
    saved2 = os.path.join(WORK, "f12_locked.exr")
    bpy.data.images["Render Result"].save_render(saved2, scene=scene)
    mean2 = check_image("F12 with Lock Interface: Render Result", saved2, (96, 64))
    check(max(abs(a - b) for a, b in zip(mean, mean2)) < 1e-6,
          "Lock Interface changed the image: mean %s vs %s" % (mean2, mean))
    scene.render.use_lock_interface = False

    # ---- 1c. Ctrl F12 over 2 animated frames, written as EXR files.
    scene = addon_env.build_scene(width=96, height=64, samples=8, light='AREA',
                                  animated_camera=True)
    scene.frame_start, scene.frame_end = 1, 2
    scene.render.filepath = os.path.join(WORK, "anim_")
    yield from f12_case("Ctrl F12", scene, frames=2)
    means = [check_image("Ctrl F12", os.path.join(WORK, "anim_%04d.exr" % f), (96, 64))
             for f in (1, 2)]
    check(means[0] != means[1], "Ctrl F12: both frames are the same image")

    # ---- 1e. F12 on a scene with an object of every type and collection instances of them
    # (issue 28: an Empty took Blender down), with Cycles' settings left as they are.
    scene = addon_env.build_scene(width=96, height=64, samples=8, light='AREA')
    object_types.build(scene)
    yield from f12_case("F12 with every object type", scene)
    saved = os.path.join(WORK, "f12_types.exr")
    bpy.data.images["Render Result"].save_render(saved, scene=scene)
    check_image("F12 with every object type: Render Result", saved, (96, 64))

    # ---- 1d. A glint that is not there: the error reaches Blender, the job ends, no folder.
    prefs = bpy.context.preferences.addons["glint_blender"].preferences
    prefs.binary = os.path.join(WORK, "no_such_glint")
    reset()
    n0 = STATE["complete"] + STATE["cancel"]
    try:
        res = f12()
        check('RUNNING_MODAL' in res, "F12 (no binary) did not start a render job: %s"
              % sorted(res))
    except RuntimeError as e:
        # The job can fail before the invoke returns; bpy.ops then raises its ERROR report.
        log("F12 (no binary): the operator call raised: %s" % e)
    yield from wait_render_end("F12 (no binary)", n0)
    log("F12 (no binary): errors %s" % STATE["errors"])
    check(len(STATE["errors"]) == 1 and "not found" in STATE["errors"][0],
          "F12 (no binary): expected one 'not found' error, got %s" % STATE["errors"])
    check(render_dirs() == [], "F12 (no binary): temp folder left: %s" % render_dirs())
    prefs.binary = glint

    # ---- 2. Esc during a heavy render.
    reset()
    n_complete, n_cancel = STATE["complete"], STATE["cancel"]
    scene = addon_env.build_scene(heavy=True, light=None)
    scene.glint.threads = 1  # leaves the main thread a core
    res = f12()
    check('RUNNING_MODAL' in res, "Esc: the heavy render did not start: %s" % sorted(res))
    deadline = time.monotonic() + 60
    pids = []
    while not pids:
        check(time.monotonic() < deadline, "Esc: glint never started")
        check(STATE["complete"] == n_complete and STATE["cancel"] == n_cancel,
              "Esc: the render ended before glint started (errors %s)" % STATE["errors"])
        yield 0.05
        pids = glint_children()
    pid = pids[0]
    check(len(render_dirs()) == 1, "Esc: render folders: %s" % render_dirs())
    # While glint renders, the main thread must keep running its event loop (the engine waits
    # on the job thread): at least MIN_TICKS timer calls, and 1.5 s of rendering.
    started = time.monotonic()
    ticks = 0
    while ticks < MIN_TICKS or time.monotonic() - started < 1.5:
        check(time.monotonic() - started < 30.0, "Esc: the main thread ran its timers only %d "
              "times in 30 s while glint rendered" % ticks)
        yield 0.05
        ticks += 1
    check(alive(pid), "Esc: glint (pid %d) ended by itself: the scene is not heavy enough" % pid)
    windows = list(bpy.context.window_manager.windows)
    log("Esc: glint pid %d running; %d window(s); main loop ran %d timer calls in %.2f s; %d "
        "progress update(s) so far" % (pid, len(windows), ticks, time.monotonic() - started,
                                        STATE["progress"]))
    check(len(windows) == 2, "Esc: no render window was opened (%d windows)" % len(windows))
    watcher = Watcher(pid)
    names = press_escape()
    log("Esc: sent to %s" % names)
    check(names, "Esc: no Blender window on the X display")
    sent = time.monotonic()
    while alive(pid):
        check(time.monotonic() - sent < 10.0, "Esc: glint (pid %d) still runs 10 s after Esc"
              % pid)
        yield 0.01
    # The watcher may still be in its 5 ms sleep when the main thread sees the pid gone.
    watcher.join(timeout=5)
    gone = watcher.gone_at
    check(gone is not None, "Esc: the watcher thread never saw glint (pid %d) end" % pid)
    yield from wait_render_end("Esc", n_complete + n_cancel)
    ended_s = time.monotonic() - sent
    brk = STATE["break_at"]
    log("Esc: Blender's test_break true %.2f s after the key (its event loop under software "
        "GL), glint gone %.3f s after that, render job ended %.2f s after the key (complete %d, "
        "cancel %d); render() on main thread: %s; export on main thread: %s; errors: %s"
        % ((brk or sent) - sent, gone - (brk or sent), ended_s,
           STATE["complete"] - n_complete, STATE["cancel"] - n_cancel,
           STATE["render_threads"], STATE["export_threads"], STATE["errors"]))
    check(brk is not None, "Esc: the engine never saw test_break() true")
    check(gone - brk <= GLINT_GONE_S, "Esc: glint took %.2f s to stop after the engine saw the "
          "cancel (limit %.1f s)" % (gone - brk, GLINT_GONE_S))
    check(STATE["cancel"] == n_cancel + 1, "Esc: render_cancel did not fire")
    check(STATE["errors"] == [], "Esc: the engine reported %s" % STATE["errors"])
    check(render_dirs() == [], "Esc: temp folder left: %s" % render_dirs())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--glint", required=True)
    args = ap.parse_args(script_args())
    if bpy.app.background:
        finish(1, "needs Blender's UI: run it without -b under xvfb-run")
    os.makedirs(TMP)
    tempfile.tempdir = TMP
    gen = steps(os.path.abspath(args.glint))

    def tick():
        try:
            return next(gen)
        except StopIteration:
            finish(0, "all checks passed")
        except Failure as e:
            finish(1, str(e))
        except BaseException:
            traceback.print_exc()
            finish(1, "the driver raised")
        return None

    bpy.app.timers.register(tick, first_interval=0.5, persistent=True)

    def watchdog():  # a deadlocked main thread never runs tick() again
        time.sleep(300)
        print("FAIL: test_ui still running after 300 s (main thread stuck?)", flush=True)
        os._exit(1)

    threading.Thread(target=watchdog, daemon=True).start()


main()
