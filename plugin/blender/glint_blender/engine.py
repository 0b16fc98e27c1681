"""The "GLINT" render engine: export the frame, run the glint CLI, load its EXR.

Blender calls render(depsgraph) once per frame (F12, `blender -b f.blend -E GLINT -f 1`, and each
frame of `-a`). In the UI render() runs on a job thread, where operators such as the OBJ exporter
fail their context poll, so the export is put on a queue that a bpy.app.timers function, registered
on the main thread when the add-on is (registering a timer from another thread is not thread-safe
in Blender), runs there; the render thread waits for it and keeps checking for cancel. Headless,
render() is on the main thread and exports directly.

Outcomes: success loads glint's linear float EXR into the render result (Blender applies its view
transform afterwards); a failure reports glint's own error lines with self.report({'ERROR'}) so
`blender -b` exits non-zero without writing an image; a cancel (Esc, or SIGINT to `blender -b`)
stops glint (SIGTERM, then SIGKILL after a second) and ends quietly. The per-render temp folder is
removed in every case unless the keep_temp preference is on; those of a Blender that crashed or
was killed are removed at the next render (render_dirs.py).
"""

import os
import queue
import signal
import threading
import time
import traceback

import bpy

from . import exporter, native_export, preferences, render_dirs, runner

EXPORT_TIMEOUT_S = 600.0
PUMP_INTERVAL_S = 0.05

# Work for the main thread, put there by render threads (queue.Queue does its own locking).
_main_thread_jobs = queue.Queue()


def _pump():
    """The persistent timer on the main thread: runs what render threads queued. Never raises
    (Blender would drop the timer)."""
    while True:
        try:
            job = _main_thread_jobs.get_nowait()
        except queue.Empty:
            return PUMP_INTERVAL_S
        try:
            job()
        except Exception:
            traceback.print_exc()


class GlintRenderEngine(bpy.types.RenderEngine):
    bl_idname = "GLINT"
    bl_label = "glint"
    bl_use_preview = False
    bl_use_shading_nodes_custom = False
    bl_use_postprocess = True
    bl_use_eevee_viewport = True

    # ------------------------------------------------------------------ reporting

    def _warn_once(self, msg):
        if msg not in self._warned:
            self._warned.add(msg)
            self.report({'WARNING'}, "glint: " + msg)

    def _error(self, msg):
        self.report({'ERROR'}, "glint: " + msg)

    # ------------------------------------------------------------------ render

    def render(self, depsgraph):
        self._warned = set()
        prefs = preferences.get()
        keep = bool(prefs and prefs.keep_temp)
        try:
            out_dir = render_dirs.create()
        except OSError as e:  # e.g. a full or read-only temp folder
            self._error("cannot make a temporary folder for the render: %s" % e)
            return
        try:
            self._render(depsgraph, prefs, out_dir)
        except exporter.ExportError as e:
            self._error(str(e))
        except Exception as e:  # never let an exception escape into Blender's render job
            traceback.print_exc()
            self._error("%s: %s" % (type(e).__name__, e))
        finally:
            if keep:
                render_dirs.keep(out_dir)
                print("glint: render folder kept: %s" % out_dir)
            else:
                render_dirs.remove(out_dir)

    def _render(self, depsgraph, prefs, out_dir):
        configured = prefs.binary if prefs else ""
        binary = preferences.find_binary(configured)
        if binary is None:
            where = ("'%s' (add-on preferences)" % configured if configured else
                     "'%s' ($GLINT_BINARY)" % os.environ["GLINT_BINARY"]
                     if os.environ.get("GLINT_BINARY") else "'glint' on PATH")
            self._error("the glint executable was not found: %s is not an executable file"
                        % where)
            return

        self.update_stats("", "glint: exporting the scene")
        warnings = []
        export = self._export_on_main_thread(depsgraph, out_dir, warnings.append)
        for w in warnings:
            self._warn_once(w)
        if export is None:  # cancelled while waiting for the export
            return
        if self.test_break():
            return

        frame = depsgraph.scene_eval.frame_current
        self.update_stats("", "glint: rendering frame %d" % frame)
        started = time.monotonic()
        shown = [-1.0]

        def progress(p):
            self.update_progress(p)
            # The status line (printed per update by `blender -b`) at most twice a second.
            now = time.monotonic()
            if now - shown[0] >= 0.5 or p >= 1.0:
                shown[0] = now
                self.update_stats("", "glint: frame %d, %d%%, %.1f s" %
                                  (frame, int(p * 100), now - started))

        try:
            result = runner.run([binary] + export.argv, cwd=out_dir, on_progress=progress,
                                test_break=self.test_break)
        except OSError as e:
            self._error("cannot run %s: %s" % (binary, e))
            return
        with open(os.path.join(out_dir, "glint.log"), "w", encoding="utf-8") as f:
            f.write("\n".join(result.stderr_lines + result.stdout_lines) + "\n")

        if result.cancelled:
            self.update_stats("", "glint: cancelled")
            return
        if not result.ok:
            lines = exporter.translate_lines(result.error_lines(), export) or \
                ["(glint printed nothing)"]
            how = "exit code %d" % result.returncode
            if result.returncode < 0:
                try:
                    how = "killed by %s" % signal.Signals(-result.returncode).name
                except ValueError:
                    how = "killed by signal %d" % -result.returncode
            self._error("render failed (%s):\n%s" % (how, "\n".join(lines)))
            return
        for line in result.stderr_lines:
            if "warning" in line:
                self._warn_once(exporter.translate_message(line, export))
        if not os.path.isfile(export.output_path):
            self._error("glint exited with 0 but wrote no image (%s)" % export.output_path)
            return
        self._load(depsgraph, export)

    def _load(self, depsgraph, export):
        """glint's EXR (linear RGB; RGBA, premultiplied as Cycles' combined pass, with a
        transparent film or holdouts, else alpha is 1) into the render result, alpha included.
        The result must be ended whatever happens, or Blender crashes."""
        r = depsgraph.scene_eval.render
        x = y = 0
        if r.use_border:
            # Blender's result is the region only; glint rendered the whole frame.
            x = int(r.border_min_x * export.width)
            y = int(r.border_min_y * export.height)
        # Blender calls render() once per view layer (each its own depsgraph): fill that one.
        result = self.begin_result(0, 0, export.width, export.height,
                                   layer=depsgraph.view_layer.name)
        try:
            if getattr(export, "alpha", False):
                self._load_premultiplied(result, export.output_path, x, y)
            else:
                result.layers[0].load_from_file(export.output_path, x=x, y=y)
        except Exception as e:
            self.end_result(result, cancel=True)
            self._error("cannot load glint's image %s: %s" % (export.output_path, e))
            return
        self.end_result(result)

    @staticmethod
    def _load_premultiplied(result, path, x, y):
        """An RGBA EXR into the Combined pass as stored. RenderLayer.load_from_file treats a
        float image as straight alpha and multiplies it by alpha again (Blender 3.4's
        imb_handle_alpha without IB_alphamode_detect), which would darken every partly
        transparent pixel; an Image datablock reads EXR as premultiplied, as Cycles' pass is."""
        import numpy as np
        img = bpy.data.images.load(path, check_existing=False)
        try:
            img.colorspace_settings.name = "Non-Color"  # the values as stored, no transform
            w, h = img.size[0], img.size[1]
            pixels = np.empty(w * h * 4, dtype=np.float32)
            img.pixels.foreach_get(pixels)
        finally:
            bpy.data.images.remove(img)
        combined = result.layers[0].passes["Combined"]
        rw, rh = result.resolution_x, result.resolution_y
        pixels = pixels.reshape(h, w, 4)[y:y + rh, x:x + rw]
        combined.rect = np.ascontiguousarray(pixels).reshape(-1, 4)  # a row of 4 per pixel

    # ------------------------------------------------------------------ export

    def _export_on_main_thread(self, depsgraph, out_dir, warn):
        if threading.current_thread() is threading.main_thread():
            return native_export.export_frame_native(depsgraph, out_dir, warn, engine=self)

        state = {"abandoned": False, "started": False, "result": None, "error": None}
        done = threading.Event()
        lock = threading.Lock()

        def job():
            with lock:
                if state["abandoned"]:
                    return None
                state["started"] = True
            try:
                state["result"] = native_export.export_frame_native(depsgraph, out_dir, warn,
                                                                      engine=self)
            except BaseException as e:  # handed to the render thread
                state["error"] = e
            finally:
                done.set()
            return None

        _main_thread_jobs.put(job)  # no bpy.app.timers call here: not thread-safe
        deadline = time.monotonic() + EXPORT_TIMEOUT_S
        while not done.wait(0.05):
            with lock:
                if not state["started"] and (self.test_break() or
                                             time.monotonic() > deadline):
                    state["abandoned"] = True
                    if self.test_break():
                        return None
                    raise exporter.ExportError("the export did not start within %d s (is "
                                               "Blender's main thread busy?)"
                                               % EXPORT_TIMEOUT_S)
        if state["error"] is not None:
            raise state["error"]
        return state["result"]


def register():
    bpy.utils.register_class(GlintRenderEngine)
    if not bpy.app.timers.is_registered(_pump):
        bpy.app.timers.register(_pump, first_interval=0.0, persistent=True)


def unregister():
    if bpy.app.timers.is_registered(_pump):
        bpy.app.timers.unregister(_pump)
    bpy.utils.unregister_class(GlintRenderEngine)
