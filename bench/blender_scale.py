#!/usr/bin/env python3
"""Issue 30's scale check: two large Blender scenes rendered at 1 spp by Cycles and by glint
through the add-on, each render its own `blender -b` process, timed and measured for peak memory.

    python3 bench/blender_scale.py [--blender /usr/bin/blender] [--glint build/glint] \
        [--work /tmp/glint_blender_scale] [--runs 3] [--scenes mesh1m,suzanne10k] \
        [--engines cycles,glint] [--threads 0] [--keep]

Scenes (built from code by this file run inside Blender, 640 x 480, 1 spp, a sun and a world
colour, Principled materials; Cycles' denoiser off):
  mesh1m      one UV sphere of 1,000 segments x 501 rings = 1,000,000 triangles, smooth shaded
  suzanne10k  Suzanne with a Subdivision modifier (level 2) applied: 15,744 triangles, in
              10,000 linked duplicates (one mesh datablock, bpy.data.objects.new) on a 100 x 100
              grid with random turns, seen from above at an angle

Each run, the engines interleaved:
  cycles  /usr/bin/time -v blender -b --factory-startup S.blend --python THIS -E CYCLES
          --debug-cycles -f 1: wall seconds, max RSS (Blender with Cycles in it), CPU seconds;
          Cycles' sync time is its own log line "Total time spent synchronizing data"
          (BlenderSync, Blender's data into Cycles' scene); "to sampling" adds the device update
          (shaders, meshes, BVH: "Total render time" less "Rendered 1 samples in")
  glint   the same with -E GLINT and the add-on enabled as tests/plugin does (a link in
          WORK/scripts/addons, BLENDER_USER_SCRIPTS); its binary is a wrapper, WORK/bin/glint,
          that notes Blender's VmRSS as glint starts and runs `/usr/bin/time -v GLINT "$@" -v`,
          so glint's own max RSS and its -v `time:` line come back apart from Blender's.
          Blender's own peak is the VmHWM of its /proc/self/status at exit (/usr/bin/time on
          blender reports the largest process of the tree, and counts glint's CPU in). The
          export is timed by wrapping native_export.export_frame_native. keep_temp is on so that
          glint.log can be read; each run's folder is removed afterwards (--keep keeps them).

Memory ratios: glint's process alone, and Blender's RSS while glint runs plus glint's peak (what
the two hold at once) against Cycles' one process. Prints a table of medians and the phases,
writes WORK/results.json and WORK/logs/. Blender's start and the .blend's load are inside both
totals (about 1 s for mesh1m, 2 s for suzanne10k).
"""

import os
import sys

MODE = os.environ.get("GLINT_SCALE_MODE", "")

# =============================================================================== in Blender

if MODE:
    import atexit
    import json
    import math
    import random
    import time

    import bpy

    def _vm_hwm_kb():
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1])
        return None

    def _material(name, color, roughness=0.4, metallic=0.0):
        m = bpy.data.materials.new(name)
        m.use_nodes = True
        p = m.node_tree.nodes["Principled BSDF"]
        p.inputs["Base Color"].default_value = (*color, 1.0)
        p.inputs["Roughness"].default_value = roughness
        p.inputs["Metallic"].default_value = metallic
        return m

    def _common(scene, cam_loc, cam_target, lens=35.0):
        for ob in list(bpy.data.objects):
            bpy.data.objects.remove(ob)
        r = scene.render
        r.resolution_x, r.resolution_y, r.resolution_percentage = 640, 480, 100
        r.image_settings.file_format = 'PNG'
        c = scene.cycles
        c.samples = 1
        c.use_denoising = False
        c.use_adaptive_sampling = False
        c.device = 'CPU'
        scene.world = bpy.data.worlds.new("World") if scene.world is None else scene.world
        scene.world.use_nodes = False
        scene.world.color = (0.05, 0.06, 0.08)
        cam = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
        cam.data.lens = lens
        cam.data.clip_end = 1000.0
        scene.collection.objects.link(cam)
        cam.location = cam_loc
        d = (cam_target[0] - cam_loc[0], cam_target[1] - cam_loc[1],
             cam_target[2] - cam_loc[2])
        from mathutils import Vector
        cam.rotation_euler = Vector(d).to_track_quat('-Z', 'Y').to_euler()
        scene.camera = cam
        sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", 'SUN'))
        sun.data.energy = 3.0
        sun.data.angle = math.radians(2.0)
        sun.rotation_euler = (math.radians(40), math.radians(10), math.radians(30))
        scene.collection.objects.link(sun)

    def uv_sphere(name, seg, rings, radius=1.0):
        """A UV sphere as Blender's (quads, triangle fans at the poles), smooth shaded: built
        with numpy because primitive_uv_sphere_add stops at 500 segments."""
        import numpy as np
        th = np.linspace(0.0, math.pi, rings + 1)[1:-1]          # rings - 1 latitudes
        ph = np.linspace(0.0, 2.0 * math.pi, seg, endpoint=False)
        T, P = np.meshgrid(th, ph, indexing="ij")
        body = np.stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)], -1)
        verts = np.concatenate([[[0.0, 0.0, 1.0]], body.reshape(-1, 3), [[0.0, 0.0, -1.0]]])
        verts *= radius
        nb = rings - 1
        top, bottom = 0, 1 + nb * seg
        j = np.arange(seg)
        jn = (j + 1) % seg
        loops = [np.stack([np.full(seg, top), 1 + j, 1 + jn], -1).ravel()]
        i = np.arange(nb - 1)[:, None]
        a = 1 + i * seg + j
        b = 1 + i * seg + jn
        quads = np.stack([a, a + seg, b + seg, b], -1).reshape(-1, 4)
        loops.append(quads.ravel())
        last = 1 + (nb - 1) * seg
        loops.append(np.stack([last + j, np.full(seg, bottom), last + jn], -1).ravel())
        loops = np.concatenate(loops).astype(np.int32)
        sizes = np.concatenate([np.full(seg, 3), np.full(len(quads), 4), np.full(seg, 3)])
        starts = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int32)
        me = bpy.data.meshes.new(name)
        me.vertices.add(len(verts))
        me.vertices.foreach_set("co", verts.astype(np.float32).ravel())
        me.loops.add(len(loops))
        me.loops.foreach_set("vertex_index", loops)
        me.polygons.add(len(sizes))
        me.polygons.foreach_set("loop_start", starts)
        me.polygons.foreach_set("loop_total", sizes.astype(np.int32))
        me.polygons.foreach_set("use_smooth", np.ones(len(sizes), dtype=bool))
        me.update(calc_edges=True)
        me.validate()
        return me

    def build_mesh1m(path):
        scene = bpy.context.scene
        _common(scene, (0.0, -3.2, 0.9), (0.0, 0.0, 0.0))
        me = uv_sphere("Sphere1M", 1000, 501)  # 2 x 1000 x 500 = 1,000,000 triangles
        ob = bpy.data.objects.new("Sphere1M", me)
        scene.collection.objects.link(ob)
        me.calc_loop_triangles()
        tris = len(me.loop_triangles)
        ob.data.materials.append(_material("Sphere", (0.8, 0.3, 0.2), 0.3))
        floor_me = bpy.data.meshes.new("Floor")
        floor_me.from_pydata([(-20, -20, -1), (20, -20, -1), (20, 20, -1), (-20, 20, -1)], [],
                             [(0, 1, 2, 3)])
        floor = bpy.data.objects.new("Floor", floor_me)
        floor.data.materials.append(_material("Floor", (0.6, 0.6, 0.6), 0.8))
        scene.collection.objects.link(floor)
        bpy.ops.wm.save_as_mainfile(filepath=path)
        return tris + 2

    def build_suzanne10k(path, n=100, spacing=2.5):
        scene = bpy.context.scene
        half = (n - 1) * spacing / 2.0
        _common(scene, (0.0, -half - 25.0, 45.0), (0.0, -half * 0.25, 0.0), lens=28.0)
        bpy.ops.mesh.primitive_monkey_add(size=1.0)
        src = bpy.context.active_object
        mod = src.modifiers.new("Subdivision", 'SUBSURF')
        mod.levels = mod.render_levels = 2
        bpy.ops.object.modifier_apply(modifier=mod.name)
        me = src.data
        me.name = "Suzanne"
        me.polygons.foreach_set("use_smooth", [True] * len(me.polygons))
        me.update()
        me.calc_loop_triangles()
        tris = len(me.loop_triangles)
        me.materials.append(_material("Suzanne", (0.75, 0.55, 0.2), 0.35))
        bpy.data.objects.remove(src)
        coll = bpy.data.collections.new("Scatter")
        scene.collection.children.link(coll)
        rng = random.Random(30)
        for i in range(n * n):
            ob = bpy.data.objects.new("Suzanne.%05d" % i, me)
            ob.location = (-half + (i % n) * spacing + rng.uniform(-0.4, 0.4),
                           -half + (i // n) * spacing + rng.uniform(-0.4, 0.4), 0.0)
            ob.rotation_euler = (0.0, 0.0, rng.uniform(-math.pi, math.pi))
            coll.objects.link(ob)
        floor_me = bpy.data.meshes.new("Floor")
        s = half + 10.0
        floor_me.from_pydata([(-s, -s, -0.8), (s, -s, -0.8), (s, s, -0.8), (-s, s, -0.8)], [],
                             [(0, 1, 2, 3)])
        floor = bpy.data.objects.new("Floor", floor_me)
        floor.data.materials.append(_material("Floor", (0.5, 0.5, 0.5), 0.8))
        scene.collection.objects.link(floor)
        bpy.ops.wm.save_as_mainfile(filepath=path)
        return tris

    if MODE == "build":
        out = os.environ["GLINT_SCALE_OUT"]
        info = {}
        for name, fn in (("mesh1m", build_mesh1m), ("suzanne10k", build_suzanne10k)):
            if name not in os.environ.get("GLINT_SCALE_SCENES", name).split(","):
                continue
            bpy.ops.wm.read_homefile(use_empty=True)
            t0 = time.perf_counter()
            tris = fn(os.path.join(out, name + ".blend"))
            info[name] = {"triangles_per_mesh": tris,
                          "build_s": time.perf_counter() - t0}
            print("blender_scale: built %s (%d triangles a mesh) in %.1f s"
                  % (name, tris, info[name]["build_s"]), flush=True)
        with open(os.path.join(out, "build.json"), "w") as f:
            json.dump(info, f)

    elif MODE == "hook":
        report_path = os.environ["GLINT_SCALE_REPORT"]
        report = {"script_start": time.time()}
        threads = int(os.environ.get("GLINT_SCALE_THREADS", "0"))

        def _write():
            report["blender_vmhwm_kb"] = _vm_hwm_kb()
            with open(report_path, "w") as f:
                json.dump(report, f)

        for scene in bpy.data.scenes:
            scene.cycles.samples = 1
            scene.cycles.use_denoising = False
            scene.cycles.device = 'CPU'
            scene.render.threads_mode = 'AUTO' if threads == 0 else 'FIXED'
            if threads:
                scene.render.threads = threads
        if os.environ.get("GLINT_SCALE_ENGINE") == "glint":
            import addon_utils
            mod = addon_utils.enable("glint_blender", default_set=True, handle_error=None)
            if mod is None:
                print("blender_scale: cannot enable glint_blender", file=sys.stderr)
                sys.exit(1)
            prefs = bpy.context.preferences.addons["glint_blender"].preferences
            prefs.binary = os.environ["GLINT_SCALE_WRAPPER"]
            prefs.keep_temp = True  # glint.log (its -v timings) is read from the kept folder
            for scene in bpy.data.scenes:
                g = scene.glint
                g.integrator, g.samples, g.max_depth = "PATH", 1, 8
                g.time_limit, g.seed, g.threads = 0.0, 0, threads
            from glint_blender import native_export
            real = native_export.export_frame_native

            def timed(*a, **k):
                hwm0 = _vm_hwm_kb()
                t0 = time.perf_counter()
                try:
                    return real(*a, **k)
                finally:
                    report.setdefault("export_s", []).append(time.perf_counter() - t0)
                    report["vmhwm_before_export_kb"] = hwm0
                    report["vmhwm_after_export_kb"] = _vm_hwm_kb()
                    print("blender_scale: export %.3f s" % report["export_s"][-1], flush=True)

            native_export.export_frame_native = timed

        def _post(*_a):
            report["render_done"] = time.time()
            _write()

        bpy.app.handlers.render_complete.append(_post)
        atexit.register(_write)
        _write()

# =============================================================================== the driver

else:
    import argparse
    import json
    import re
    import shutil
    import statistics
    import subprocess
    import time

    HERE = os.path.dirname(os.path.abspath(__file__))
    ROOT = os.path.normpath(os.path.join(HERE, ".."))
    THIS = os.path.abspath(__file__)
    ADDON = os.path.join(ROOT, "plugin", "blender", "glint_blender")

    def blender_env(extra):
        """Without a pyenv/virtualenv Python on PATH (Blender's embedded one would take its
        standard library from there), as tests/plugin/run_scene.py."""
        env = dict(os.environ, **extra)
        env["PATH"] = os.pathsep.join(p for p in env.get("PATH", "").split(os.pathsep)
                                      if "/.pyenv/" not in p and p != os.environ.get(
                                          "VIRTUAL_ENV"))
        for k in ("PYTHONHOME", "PYTHONPATH", "VIRTUAL_ENV"):
            env.pop(k, None)
        return env

    def parse_time_v(path):
        """/usr/bin/time -v's file: wall seconds, max RSS in KiB, user+sys CPU seconds."""
        out = {}
        with open(path) as f:
            for line in f:
                line = line.strip()
                if line.startswith("Maximum resident set size"):
                    out["maxrss_kb"] = int(line.rsplit(":", 1)[1])
                elif line.startswith("Elapsed (wall clock) time"):
                    t = line.rsplit(" ", 1)[1].split(":")
                    s = 0.0
                    for part in t:
                        s = s * 60 + float(part)
                    out["wall_s"] = s
                elif line.startswith("User time"):
                    out["user_s"] = float(line.rsplit(":", 1)[1])
                elif line.startswith("System time"):
                    out["sys_s"] = float(line.rsplit(":", 1)[1])
                elif line.startswith("Exit status"):
                    out["exit"] = int(line.rsplit(":", 1)[1])
        if "user_s" in out:
            out["cpu_s"] = out["user_s"] + out.get("sys_s", 0.0)
        return out

    STATUS = re.compile(r"^Fra:\d+ Mem:\S+ \(Peak (\S+)\) \| Time:(\d+):(\d+\.\d+) \| (.*)$")

    def parse_cycles_log(text):
        """Seconds since the render job began (Blender's status lines; this includes the
        render depsgraph's evaluation, common to both engines) when Cycles' scene sync ended
        (first line after the "Synchronizing object" ones) and when sampling began (first
        "Sample" line), the last status line, Blender's peak figure; and --debug-cycles' own
        figures: sync_s (BlenderSync: "Total time spent synchronizing data"), session_s (device
        update + sampling: "Total render time"), sampling_s."""
        sync_end = first_sample = last = None
        seen_sync = False
        peak = None
        phases = []
        for line in text.splitlines():
            m = STATUS.match(line)
            if not m:
                continue
            t = int(m.group(2)) * 60 + float(m.group(3))
            rest = m.group(4)
            peak = m.group(1)
            last = t
            what = rest.split("|")[-1].strip()
            if "Synchroniz" in rest:
                seen_sync = True
            elif seen_sync and sync_end is None:
                sync_end = t
            if first_sample is None and re.match(r"Sample \d", what):
                first_sample = t
            key = re.sub(r"\s*\|.*$", "", what)
            if not phases or phases[-1][0] != key.split(" ")[0]:
                phases.append((key.split(" ")[0], t))
        out = {"sync_end_s": sync_end, "sync_bvh_s": first_sample, "render_s": last,
               "blender_peak": peak, "phases": phases}
        # --debug-cycles: BlenderSync's own figure, and the session's (device update + sampling)
        for key, pat in (("sync_s", r"Total time spent synchronizing data: ([0-9.e-]+)"),
                         ("session_s", r"Total render time: ([0-9.e-]+)"),
                         ("sampling_s", r"Rendered \d+ samples in ([0-9.e-]+) seconds")):
            m = re.search(pat, text)
            out[key] = float(m.group(1)) if m else None
        return out

    GLINT_TIMING = re.compile(r"([A-Za-z][A-Za-z /_-]*?)\s*[:=]\s*([0-9.]+)\s*(ms|s)\b")

    def glint_timings(log_text):
        """glint -v's lines that carry timings (kept as text), and its `time:` line as a dict
        (parse, prepare, render, write, total seconds)."""
        lines = [l for l in log_text.splitlines()
                 if re.search(r"\b\d+(\.\d+)?\s*(ms|s)\b", l) and not l.startswith("progress")]
        phases = {}
        for l in lines:
            if l.startswith("time:"):
                for k, v in re.findall(r"(\w+) ([0-9.]+) s", l):
                    phases[k] = float(v)
        return lines, phases

    def run_one(args, scene, engine, i):
        work = args.work
        tag = "%s_%s_%d" % (scene, engine, i)
        tmp = os.path.join(work, "tmp", tag)
        shutil.rmtree(tmp, ignore_errors=True)
        os.makedirs(tmp)
        report = os.path.join(work, "logs", tag + ".report.json")
        btime = os.path.join(work, "logs", tag + ".blender.time")
        gtime = os.path.join(work, "logs", tag + ".glint.time")
        for p in (report, btime, gtime):
            if os.path.exists(p):
                os.remove(p)
        env = blender_env({"GLINT_SCALE_MODE": "hook", "GLINT_SCALE_ENGINE": engine,
                           "GLINT_SCALE_REPORT": report, "GLINT_SCALE_THREADS": str(args.threads),
                           "GLINT_SCALE_WRAPPER": os.path.join(work, "bin", "glint"),
                           "GLINT_SCALE_TIME": gtime, "TMPDIR": tmp,
                           "BLENDER_USER_SCRIPTS": os.path.join(work, "scripts")})
        cmd = ["/usr/bin/time", "-v", "-o", btime, args.blender, "-b", "--factory-startup",
               os.path.join(work, scene + ".blend"), "--python", THIS,
               "-E", "GLINT" if engine == "glint" else "CYCLES"] + \
            (["--debug-cycles"] if engine == "cycles" else []) + [
               "-o", os.path.join(work, "out", tag + "_####"), "-F", "PNG", "-f", "1"]
        t0 = time.perf_counter()
        p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, errors="replace")
        wall = time.perf_counter() - t0
        with open(os.path.join(work, "logs", tag + ".log"), "w") as f:
            f.write(p.stdout)
        img = os.path.join(work, "out", tag + "_0001.png")
        res = {"scene": scene, "engine": engine, "run": i, "rc": p.returncode, "wall_s": wall,
               "image": os.path.isfile(img)}
        res["blender_time"] = parse_time_v(btime)
        if os.path.exists(report):
            with open(report) as f:
                res["hook"] = json.load(f)
        if engine == "cycles":
            res["cycles"] = parse_cycles_log(p.stdout)
        else:
            if os.path.exists(gtime):
                res["glint_time"] = parse_time_v(gtime)
            if os.path.exists(gtime + ".parent"):
                with open(gtime + ".parent") as f:
                    res["blender_rss_at_glint_start_kb"] = int(f.read().split()[1])
                os.remove(gtime + ".parent")
            logs = []
            for root, _d, files in os.walk(tmp):
                if "glint.log" in files:
                    with open(os.path.join(root, "glint.log"), errors="replace") as f:
                        logs.append(f.read())
                    sizes = {n: os.path.getsize(os.path.join(root, n)) for n in files}
                    res["export_files"] = sizes
            res["glint_log"] = logs[0] if logs else ""
            res["glint_timing_lines"], res["glint_phases"] = glint_timings(res["glint_log"])
        m = re.search(r"^\s*Time: (\d+):(\d+\.\d+)", p.stdout, re.M)
        if m:
            res["blender_render_s"] = int(m.group(1)) * 60 + float(m.group(2))
        if not args.keep:
            shutil.rmtree(tmp, ignore_errors=True)
        ok = p.returncode == 0 and res["image"]
        print("  %-11s %-6s run %d: rc %d, %.1f s wall, Blender max RSS %s MB%s" % (
            scene, engine, i, p.returncode, wall,
            _mb(res["blender_time"].get("maxrss_kb")),
            (", glint max RSS %s MB" % _mb(res.get("glint_time", {}).get("maxrss_kb"))
             if engine == "glint" else "")) + ("" if ok else "  FAILED (see logs/%s.log)" % tag),
            flush=True)
        return res

    def _mb(kb):
        return "%.0f" % (kb / 1024.0) if kb else "?"

    def med(xs):
        xs = [x for x in xs if x is not None]
        return statistics.median(xs) if xs else None

    def summarize(results, scenes):
        rows = []
        for scene in scenes:
            cyc = [r for r in results if r["scene"] == scene and r["engine"] == "cycles"
                   and r["rc"] == 0]
            gl = [r for r in results if r["scene"] == scene and r["engine"] == "glint"
                  and r["rc"] == 0]
            row = {"scene": scene, "cycles_runs": len(cyc), "glint_runs": len(gl)}
            row["cycles_total_s"] = med([r["wall_s"] for r in cyc])
            row["cycles_peak_mb"] = med([r["blender_time"].get("maxrss_kb", 0) / 1024.0
                                         for r in cyc])
            row["cycles_sync_s"] = med([r["cycles"]["sync_s"] for r in cyc])
            row["cycles_sync_bvh_s"] = med([r["cycles"]["sync_bvh_s"] for r in cyc])
            row["cycles_sync_end_s"] = med([r["cycles"]["sync_end_s"] for r in cyc])
            row["cycles_to_sampling_s"] = med([
                r["cycles"]["sync_s"] + r["cycles"]["session_s"] - r["cycles"]["sampling_s"]
                if None not in (r["cycles"]["sync_s"], r["cycles"]["session_s"],
                                r["cycles"]["sampling_s"]) else None for r in cyc])
            row["cycles_session_s"] = med([r["cycles"]["session_s"] for r in cyc])
            row["cycles_sampling_s"] = med([r["cycles"]["sampling_s"] for r in cyc])
            for k in ("parse", "prepare", "render", "write", "total"):
                row["glint_" + k + "_phase_s"] = med([r.get("glint_phases", {}).get(k)
                                                      for r in gl])
            row["blender_rss_during_glint_mb"] = med([
                r.get("blender_rss_at_glint_start_kb", 0) / 1024.0 for r in gl])
            row["concurrent_peak_mb"] = med([
                (r.get("blender_rss_at_glint_start_kb", 0) +
                 r.get("glint_time", {}).get("maxrss_kb", 0)) / 1024.0 for r in gl])
            row["blender_peak_before_export_mb"] = med([
                (r.get("hook", {}).get("vmhwm_before_export_kb") or 0) / 1024.0 for r in gl])
            row["export_json_mb"] = med([r.get("export_files", {}).get("scene.json", 0) / 1e6
                                         for r in gl])
            row["export_bin_mb"] = med([r.get("export_files", {}).get("scene.bin", 0) / 1e6
                                        for r in gl])
            row["cycles_render_s"] = med([r.get("blender_render_s") for r in cyc])
            row["glint_total_s"] = med([r["wall_s"] for r in gl])
            # CPU seconds of the whole process tree (/usr/bin/time counts waited-for children)
            row["cycles_cpu_s"] = med([r["blender_time"].get("cpu_s") for r in cyc])
            row["glint_cpu_s"] = med([r["blender_time"].get("cpu_s") for r in gl])
            row["glint_render_s"] = med([r.get("blender_render_s") for r in gl])
            row["glint_export_s"] = med([sum(r.get("hook", {}).get("export_s", [0])) or None
                                         for r in gl])
            row["glint_proc_wall_s"] = med([r.get("glint_time", {}).get("wall_s") for r in gl])
            row["glint_peak_mb"] = med([r.get("glint_time", {}).get("maxrss_kb", 0) / 1024.0
                                        for r in gl])
            row["blender_peak_mb"] = med([(r.get("hook", {}).get("blender_vmhwm_kb") or 0)
                                          / 1024.0 for r in gl])
            row["blender_peak_cycles_hook_mb"] = med([
                (r.get("hook", {}).get("blender_vmhwm_kb") or 0) / 1024.0 for r in cyc])
            if row["cycles_total_s"] and row["glint_total_s"]:
                row["time_ratio"] = row["glint_total_s"] / row["cycles_total_s"]
            if row["cycles_peak_mb"] and row["glint_peak_mb"]:
                row["mem_ratio_glint"] = row["glint_peak_mb"] / row["cycles_peak_mb"]
                row["mem_ratio_sum"] = (row["glint_peak_mb"] + row["blender_peak_mb"]) / \
                    row["cycles_peak_mb"]
                row["mem_ratio_concurrent"] = row["concurrent_peak_mb"] / row["cycles_peak_mb"]
            if row["cycles_sync_s"] and row["glint_export_s"]:
                row["export_over_sync"] = row["glint_export_s"] / row["cycles_sync_s"]
            rows.append(row)
        return rows

    def fmt(x, nd=1):
        return "-" if x is None else ("%.*f" % (nd, x))

    def print_table(rows):
        print("\n| scene | Cycles total s | Cycles peak MB | Cycles sync s (to sampling) | "
              "glint total s "
              "| glint export s | glint process peak MB | Blender peak MB | time ratio | "
              "memory ratio glint (glint+Blender) | export / sync |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            print("| %s | %s | %s | %s (%s) | %s | %s | %s | %s | %s | %s (%s) | %s |" % (
                r["scene"], fmt(r["cycles_total_s"]), fmt(r["cycles_peak_mb"], 0),
                fmt(r["cycles_sync_s"], 2), fmt(r["cycles_to_sampling_s"], 2),
                fmt(r["glint_total_s"]), fmt(r["glint_export_s"], 2), fmt(r["glint_peak_mb"], 0),
                fmt(r["blender_peak_mb"], 0), fmt(r.get("time_ratio"), 2),
                fmt(r.get("mem_ratio_glint"), 2), fmt(r.get("mem_ratio_sum"), 2),
                fmt(r.get("export_over_sync"), 2)))

    def main():
        ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
        ap.add_argument("--blender", default="/usr/bin/blender")
        ap.add_argument("--glint", default=os.path.join(ROOT, "build", "glint"))
        ap.add_argument("--work", default="/tmp/glint_blender_scale")
        ap.add_argument("--runs", type=int, default=3)
        ap.add_argument("--scenes", default="mesh1m,suzanne10k")
        ap.add_argument("--engines", default="cycles,glint")
        ap.add_argument("--threads", type=int, default=0, help="0: all (both renderers)")
        ap.add_argument("--keep", action="store_true", help="keep the export folders")
        ap.add_argument("--no-build", action="store_true", help="reuse WORK/*.blend")
        args = ap.parse_args()
        args.work = os.path.abspath(args.work)
        args.glint = os.path.abspath(args.glint)
        scenes = args.scenes.split(",")
        engines = args.engines.split(",")
        for d in ("logs", "out", "tmp", "bin", "scripts/addons"):
            os.makedirs(os.path.join(args.work, d), exist_ok=True)
        link = os.path.join(args.work, "scripts", "addons", "glint_blender")
        if not os.path.islink(link):
            os.symlink(ADDON, link)
        wrapper = os.path.join(args.work, "bin", "glint")
        with open(wrapper, "w") as f:
            f.write('#!/bin/sh\n# blender_scale.py: glint under /usr/bin/time -v, with -v; '
                    'first the RSS of Blender (the parent) as glint starts\n'
                    'grep VmRSS /proc/$PPID/status > "$GLINT_SCALE_TIME.parent"\n'
                    'exec /usr/bin/time -v -o "$GLINT_SCALE_TIME" %s "$@" -v\n'
                    % args.glint)
        os.chmod(wrapper, 0o755)

        with open("/proc/loadavg") as f:
            print("blender_scale: load %s; %d cores; glint %s" % (
                f.read().split(" ")[:3], os.cpu_count(), args.glint), flush=True)
        if not args.no_build:
            t0 = time.perf_counter()
            p = subprocess.run([args.blender, "-b", "--factory-startup", "--python-exit-code",
                                "1", "--python", THIS],
                               env=blender_env({"GLINT_SCALE_MODE": "build",
                                                "GLINT_SCALE_OUT": args.work,
                                                "GLINT_SCALE_SCENES": args.scenes}),
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            for line in p.stdout.splitlines():
                if line.startswith("blender_scale:"):
                    print(line)
            if p.returncode != 0:
                print(p.stdout[-3000:])
                sys.exit("building the scenes failed")
            print("blender_scale: scenes built in %.1f s" % (time.perf_counter() - t0))

        results = []
        for i in range(args.runs):
            for scene in scenes:
                for engine in (engines if i % 2 == 0 else engines[::-1]):
                    with open("/proc/loadavg") as f:
                        load = f.read().split(" ")[0]
                    r = run_one(args, scene, engine, i)
                    r["loadavg_before"] = load
                    results.append(r)
                    with open(os.path.join(args.work, "results.json"), "w") as f:
                        json.dump({"runs": results}, f, indent=1)
        rows = summarize(results, scenes)
        with open(os.path.join(args.work, "results.json"), "w") as f:
            json.dump({"runs": results, "medians": rows}, f, indent=1)
        print_table(rows)
        for scene in scenes:
            gl = [r for r in results if r["scene"] == scene and r["engine"] == "glint"]
            if gl:
                print("\n%s glint -v (run 0):" % scene)
                for line in gl[0].get("glint_timing_lines", [])[:40]:
                    print("   " + line)
            cy = [r for r in results if r["scene"] == scene and r["engine"] == "cycles"]
            if cy:
                print("%s Cycles phases (run 0, seconds since the render began):" % scene)
                print("   " + ", ".join("%s %.2f" % (k, t) for k, t in cy[0]["cycles"]["phases"]))
        for r in rows:
            print("  %s CPU seconds (process tree): Cycles %s, glint %s (%s x)" % (
                r["scene"], fmt(r["cycles_cpu_s"], 2), fmt(r["glint_cpu_s"], 2),
                fmt(r["glint_cpu_s"] / r["cycles_cpu_s"] if r["cycles_cpu_s"] and
                    r["glint_cpu_s"] else None, 2)))
        print("\nMedian phases (s): Cycles session = device update + sampling; glint -v time "
              "line; Blender's VmHWM before the export; export file sizes")
        for r in rows:
            print("  %s: Cycles session %s, sampling %s | glint export %s, parse %s, prepare %s, "
                  "render %s, write %s, total %s (process wall %s) | Blender peak before "
                  "export %s MB, after %s MB, while glint runs %s MB (+ glint = %s MB, %s x "
                  "Cycles' peak) | scene.json %s MB, scene.bin %s MB" % (
                      r["scene"], fmt(r["cycles_session_s"], 2), fmt(r["cycles_sampling_s"], 2),
                      fmt(r["glint_export_s"], 2), fmt(r["glint_parse_phase_s"], 2),
                      fmt(r["glint_prepare_phase_s"], 2), fmt(r["glint_render_phase_s"], 2),
                      fmt(r["glint_write_phase_s"], 2), fmt(r["glint_total_phase_s"], 2),
                      fmt(r["glint_proc_wall_s"], 2), fmt(r["blender_peak_before_export_mb"], 0),
                      fmt(r["blender_peak_mb"], 0), fmt(r["blender_rss_during_glint_mb"], 0),
                      fmt(r["concurrent_peak_mb"], 0), fmt(r.get("mem_ratio_concurrent"), 2),
                      fmt(r["export_json_mb"], 1),
                      fmt(r["export_bin_mb"], 1)))
        print("\nresults: %s" % os.path.join(args.work, "results.json"))

    main()
