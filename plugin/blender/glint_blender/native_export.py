"""Blender scene -> glint's native exchange (formats/blender/FORMAT.md), one frame.

    export_frame_native(depsgraph, out_dir, warn, engine=None) -> exporter.Export

writes into out_dir:
    scene.json    render settings, camera, world, meshes, materials (shader graphs), objects,
                  lights
    scene.bin     every array the JSON's buffer views point into
    textures/     images that exist only inside Blender (packed, generated, edited)
    command.txt   the glint command line that renders it

Meshes are read with numpy and foreach_get, each evaluated mesh once however many objects (linked
duplicates, collection / particle / geometry-node instances) use it; curves, text, surfaces and
metaballs are the meshes the depsgraph evaluated them to (listed as instances of their object,
as Cycles renders them). Each instance is an object entry with its matrix, materials, ray
visibility and Object Info values as Cycles 3.4 sets them (intern/cycles/blender/object.cpp).
Shader graphs are flattened in node_graphs.py.

With motion blur on, the frame is set to the shutter's sample times (engine.frame_set when an
engine is given, else the scene's frame_set) and set back afterwards, as Cycles' sync does.
Must run on Blender's main thread. What the exchange cannot carry is reported through warn(msg),
never a node type (glint's importer reports the nodes it lacks).
"""

import json
import math
import os
import shlex

import bpy
import numpy as np

from . import exporter, images, node_graphs, smoke
from .mesh_data import Buffer, add_tangents, mesh_entry, mesh_motion_arrays, tangent_maps

FORMAT_VERSION = 1
JSON_NAME = "scene.json"
BIN_NAME = "scene.bin"
SURFACE_TYPES = frozenset({"MESH", "CURVE", "SURFACE", "FONT", "META"})
MAX_MOTION_STEPS = 129  # Cycles' Object::MAX_MOTION_STEPS

# ----------------------------------------------------------------------------- Cycles' hashes

_U32 = 0xFFFFFFFF


def _rot(x, k):
    return ((x << k) | (x >> (32 - k))) & _U32


def hash_uint2(kx, ky):
    """Cycles' util/hash.h hash_uint2 (Jenkins lookup3 final mix)."""
    a = b = c = (0xdeadbeef + (2 << 2) + 13) & _U32
    b = (b + ky) & _U32
    a = (a + kx) & _U32
    c ^= b
    c = (c - _rot(b, 14)) & _U32
    a ^= c
    a = (a - _rot(c, 11)) & _U32
    b ^= a
    b = (b - _rot(a, 25)) & _U32
    c ^= b
    c = (c - _rot(b, 16)) & _U32
    a ^= c
    a = (a - _rot(c, 4)) & _U32
    b ^= a
    b = (b - _rot(a, 14)) & _U32
    c ^= b
    c = (c - _rot(b, 24)) & _U32
    return c


def hash_string(s):
    """Cycles' hash_string: i = i * 37 + c over the UTF-8 bytes, c a signed char (x86)."""
    i = 0
    for byte in s.encode("utf-8"):
        i = (i * 37 + (byte if byte < 128 else byte - 256)) & _U32
    return i


def random_float(random_id):
    """Object Info > Random as Cycles computes it: (float)id * (1.0f / (float)0xFFFFFFFF), in
    float (2^-32 exactly)."""
    return float(np.float32(random_id) * np.float32(2.0 ** -32))


# ----------------------------------------------------------------------------- buffers


def _matrix(m):
    """A Matrix as 16 numbers, row-major."""
    out = [*m[0], *m[1], *m[2], *m[3]]
    if not math.isfinite(sum(out)):
        out = [node_graphs.finite(x) for x in out]
    return out


# ----------------------------------------------------------------------------- meshes


def _original(idb):
    return idb.original if idb is not None and idb.original is not None else idb


def _bounds(ob):
    """The object-space box of an (evaluated) object's geometry: min and max corners."""
    lo = [min(c[k] for c in ob.bound_box) for k in range(3)]
    hi = [max(c[k] for c in ob.bound_box) for k in range(3)]
    return lo, hi


def _visibility(ob):
    return {"camera": ob.visible_camera, "diffuse": ob.visible_diffuse,
            "glossy": ob.visible_glossy, "transmission": ob.visible_transmission,
            "shadow": ob.visible_shadow, "volume_scatter": ob.visible_volume_scatter}


def _group(pg):
    """A property group (Cycles' settings of a datablock) as a dict of its plain values."""
    out = {}
    if pg is None:
        return out
    for p in pg.bl_rna.properties:
        if p.identifier in {"rna_type", "name"} or p.type in {'POINTER', 'COLLECTION'}:
            continue
        v = getattr(pg, p.identifier)
        out[p.identifier] = (sorted(v) if p.type == 'ENUM' and p.is_enum_flag
                             else node_graphs.value(v))
    return out


def _motion_steps(parent, ob):
    """Cycles' object_motion_steps(b_parent, b_ob): 0 without motion blur for the object."""
    c = _original(ob).cycles
    if not c.use_motion_blur:
        return 0
    steps = max(1, c.motion_steps)
    if parent is not None and _original(parent) != _original(ob):
        pc = _original(parent).cycles
        if not pc.use_motion_blur:
            return 0
        steps = max(steps, pc.motion_steps)
    return min((2 << (steps - 1)) + 1, MAX_MOTION_STEPS)


def _flat_shutter(curve):
    """Whether the shutter curve (a CurveMapping) is flat: every point at one height, the box
    Cycles' default is (any flat height gives the same times)."""
    try:
        points = curve.curves[0].points
    except (AttributeError, IndexError):
        return True
    ys = [p.location[1] for p in points]
    return not ys or max(ys) - min(ys) < 1e-6


def _instance_key(inst, ob):
    """Identifies an instance across frame changes (Cycles' ObjectKey)."""
    if inst.is_instance:
        return ("i", _original(inst.parent).as_pointer(), tuple(inst.persistent_id),
                _original(ob).as_pointer())
    return ("o", _original(ob).as_pointer())


class _Images:
    """The "image" entries of texture nodes: one file per image, missing ones collected."""

    def __init__(self, out_dir, warn):
        self.out_dir = out_dir
        self.warn = warn
        self.missing = images.MissingImages()
        self.done = {}

    def __call__(self, image, user):
        image = _original(image)
        key = (image.name, image.library.filepath if image.library else "")
        entry = self.done.get(key)
        if entry is None:
            entry = {"name": image.name_full, "source": image.source,
                     "colorspace": image.colorspace_settings.name,
                     "alpha_mode": image.alpha_mode, "is_float": image.is_float}
            if image.source in {'SEQUENCE', 'MOVIE', 'TILED'}:
                entry["path"] = images.image_path(image)  # glint resolves frames and tiles
            else:
                problem = images.image_problem(image)
                if problem:  # no "path": Cycles' magenta
                    entry["missing"] = problem
                else:
                    entry["path"] = exporter.image_file(image, self.out_dir, self.warn)
            self.done[key] = entry
        if entry.get("missing"):
            self.missing.add(image, entry["missing"], user)
        return entry


# ----------------------------------------------------------------------------- the export


class _Exporter:
    def __init__(self, depsgraph, out_dir, warn, engine):
        self.dg = depsgraph
        self.scene = depsgraph.scene_eval
        self.out_dir = out_dir
        self.warn = warn
        self.engine = engine
        self.images = _Images(out_dir, warn)
        self.buf = None
        self.meshes, self.mesh_index = [], {}   # mesh key -> index (None: no triangles)
        self.materials, self.material_index = [], {}
        self.material_tangents = {}             # material index -> UV maps of its Normal Maps
        self.objects, self.lights = [], []
        self.object_info = {}                   # per instanced object: the shared parts
        self.parent_info = {}                   # per parent: visibility, holdout, ...
        self.names = {"object": {}, "material": {}}
        self.smoke_files = {}  # smoke domain (evaluated object's name) -> its .vdb ("": none)
        vl = depsgraph.view_layer_eval
        self.view_layer = vl
        self.override = vl.material_override
        self.motion = (self.scene.render.use_motion_blur and vl.use_motion_blur)
        self.motion_keys = {}                   # instance key -> (entry, steps)
        self.deform_keys = {}                   # instance key -> (mesh index, steps, counts)

    # -- materials ----------------------------------------------------------------------

    def material(self, mat):
        if mat is None:
            return -1
        key = _original(mat).as_pointer()
        idx = self.material_index.get(key)
        if idx is not None:
            return idx
        name = _original(mat).name_full
        user = "material '%s'" % name
        if mat.use_nodes and mat.node_tree is not None:
            graph = node_graphs.flatten(mat.node_tree, self.images, user)
        else:
            graph = node_graphs.diffuse_graph(mat.diffuse_color)
        entry = {"name": name, "graph": graph, "pass_index": mat.pass_index,
                 "cycles": _group(getattr(_original(mat), "cycles", None))}
        idx = self.material_index[key] = len(self.materials)
        self.materials.append(entry)
        self.names["material"][name] = user
        return idx

    # -- meshes and objects -------------------------------------------------------------

    def mesh(self, ob):
        """The mesh index of an evaluated object's mesh, None when it has no triangles. Curves,
        text, surfaces and metaballs reach here as the meshes Blender evaluated them to: the
        depsgraph lists those as instances of their object (and, as Cycles does, the curve
        object itself is skipped: its data is not a mesh)."""
        key = ob.data.as_pointer()
        if key not in self.mesh_index:
            entry = mesh_entry(ob.data, ob.data.name, self.buf)
            self.mesh_index[key] = None if entry is None else len(self.meshes)
            if entry is not None:
                self.meshes.append(entry)
        return self.mesh_index[key]

    def parent(self, p):
        key = p.as_pointer()
        info = self.parent_info.get(key)
        if info is None:
            try:
                holdout = p.holdout_get(view_layer=self.view_layer)
                indirect = p.indirect_only_get(view_layer=self.view_layer)
            except (RuntimeError, TypeError):
                holdout, indirect = p.is_holdout, False
            info = self.parent_info[key] = (_visibility(p), holdout, indirect,
                                            p.is_shadow_catcher, p.name)
        return info

    def instanced(self, ob):
        """The parts of an object entry shared by all instances of one object."""
        key = (_original(ob).as_pointer(), ob.data.as_pointer() if ob.data else 0)
        info = self.object_info.get(key)
        if info is None:
            mesh = self.mesh(ob)
            if self.override is not None:
                mats = [self.material(self.override)] * max(1, len(ob.material_slots))
            else:
                mats = [self.material(s.material) for s in ob.material_slots] or [-1]
            orig = _original(ob)
            label = "object '%s'" % orig.name
            data = orig.data
            if data is not None and data.name != orig.name:
                label += " (%s '%s')" % ("mesh" if orig.type == 'MESH' else orig.type.lower(),
                                         data.name)
            self.names["object"].setdefault(ob.name, label)
            need = set()
            for m in mats:
                if m >= 0:
                    need |= self.material_tangents.setdefault(
                        m, tangent_maps(self.materials[m]["graph"]))
            if need and mesh is not None:
                add_tangents(self.meshes[mesh], ob.data, need, self.buf)
            info = self.object_info[key] = (mesh, mats, _visibility(ob), ob.is_shadow_catcher,
                                            list(ob.color), ob.pass_index)
        return info

    def add_object(self, inst, ob):
        mesh, mats, vis, catcher, color, pass_index = self.instanced(ob)
        if mesh is None:
            return
        parent = inst.parent if inst.is_instance else ob
        pvis, holdout, indirect, pcatcher, pname = self.parent(parent)
        if inst.is_instance:
            vis = {k: v and pvis[k] for k, v in vis.items()}
            random_id = inst.random_id & _U32
        else:
            random_id = hash_uint2(hash_string(ob.name), 0)
        if indirect and not holdout:
            vis = dict(vis, camera=False)
        if not any(vis.values()):
            return  # Cycles leaves out objects no ray sees
        entry = {"name": ob.name, "mesh": mesh, "matrix": _matrix(inst.matrix_world),
                 "materials": mats, "visibility": vis, "holdout": holdout,
                 "shadow_catcher": catcher or pcatcher, "color": color,
                 "pass_index": pass_index, "random": random_float(random_id),
                 "random_id": random_id}
        if inst.is_instance:
            entry["instancer"] = pname
            entry["instance_orco"] = list(inst.orco)
            entry["instance_uv"] = list(inst.uv)
        self.objects.append(entry)
        if self.motion:
            steps = _motion_steps(parent, ob)
            if steps:
                key = _instance_key(inst, ob)
                self.motion_keys[key] = (entry, steps)
                if self._deforms(parent, ob) and \
                        all(m != mesh for m, _, _ in self.deform_keys.values()):
                    me = ob.data
                    self.deform_keys[key] = (mesh, steps, (len(me.vertices), len(me.loops),
                                                           len(me.loop_triangles)))

    def add_volume(self, inst, ob):
        """A Volume object: the box of its grids (Blender's bounds of them, in object space)
        as a mesh, its OpenVDB file and its render step settings, its materials or Cycles'
        default volume. Grids made by geometry nodes or modifiers have no file to read."""
        vol = ob.data
        orig = _original(ob)
        path = exporter.volume_file(ob)
        if path is None:
            return  # named by left_out()
        if any(m.show_render for m in orig.modifiers):
            self.warn("volume object '%s': its modifiers are not applied (the file's grids "
                      "are rendered)" % orig.name)
        self._volume_object(inst, ob, _bounds(ob), "volume object '%s'" % orig.name,
                            {"file": path, "step_size": vol.render.step_size,
                             "space": vol.render.space})

    def add_smoke(self, inst, ob, domain):
        """A smoke or fire domain (smoke.py): the frame's grids written to an OpenVDB file
        over the evaluated domain mesh's texture space, rendered as a Volume object stepping
        by its voxels; as in Cycles, its density does not scale with the object."""
        orig = _original(ob)
        what = "smoke domain '%s'" % orig.name
        vdb = smoke.openvdb_module()
        if vdb is None:
            self.warn("%s left out: writing its grids needs pyopenvdb (Debian: python3-openvdb)"
                      % what)
            return
        lo, hi = smoke.texture_space(ob)
        path = self.smoke_files.get(ob.name)
        if path is None:
            path = os.path.join(self.out_dir, "smoke_%d.vdb" % len(self.smoke_files))
            if smoke.write_grids(vdb, domain, lo, hi, path) == 0:
                self.warn("%s has no smoke at frame %d (bake the simulation, or play the "
                          "timeline up to the frame): left out" % (what, self.scene.frame_current))
                path = ""
            self.smoke_files[ob.name] = path
        if path:
            self._volume_object(inst, ob, (lo, hi), what,
                                {"file": os.path.basename(path), "space": "WORLD",
                                 "step_size": 0.0})

    def _volume_object(self, inst, ob, bounds, what, volume):
        lo, hi = bounds
        if not all(h > l for l, h in zip(lo, hi)):
            return  # no active voxels
        key = ("volume box",) + tuple(lo) + tuple(hi)
        if key not in self.mesh_index:
            me = bpy.data.meshes.new("glint volume box")
            try:
                corners = [(x, y, z) for z in (lo[2], hi[2]) for y in (lo[1], hi[1])
                           for x in (lo[0], hi[0])]
                faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2),
                         (1, 3, 7, 5)]
                me.from_pydata(corners, [], faces)
                entry = mesh_entry(me, "volume box", self.buf)
            finally:
                bpy.data.meshes.remove(me)
            self.mesh_index[key] = len(self.meshes)
            self.meshes.append(entry)
        if self.override is not None:
            mats = [self.material(self.override)]
        else:
            mats = [self.material(s.material) for s in ob.material_slots if s.material]
        if not mats:
            mats = [self._default_volume()]
        vis = _visibility(ob)
        if not any(vis.values()):
            return
        self.names["object"].setdefault(ob.name, what)
        random_id = (inst.random_id & _U32) if inst.is_instance else \
            hash_uint2(hash_string(ob.name), 0)
        self.objects.append({
            "name": ob.name, "mesh": self.mesh_index[key], "matrix": _matrix(inst.matrix_world),
            "materials": mats[:1], "visibility": vis, "holdout": False, "shadow_catcher": False,
            "color": list(ob.color), "pass_index": ob.pass_index,
            "random": random_float(random_id), "random_id": random_id, "volume": volume})

    def _default_volume(self):
        idx = self.material_index.get("default volume")
        if idx is None:
            idx = self.material_index["default volume"] = len(self.materials)
            self.materials.append({"name": "glint default volume",
                                   "graph": node_graphs.volume_graph(), "pass_index": 0,
                                   "cycles": {}})
        return idx

    def _deforms(self, parent, ob):
        """Whether Cycles blurs the object's deformation: its (and its instancer's) Deformation
        motion blur on and its mesh deformed by modifiers, shape keys or an armature."""
        orig = _original(ob)
        if not (orig.cycles.use_deform_motion and
                orig.is_deform_modified(_original(self.scene), 'RENDER')):
            return False
        p = _original(parent)
        return p is None or p == orig or p.cycles.use_deform_motion

    # -- lights -------------------------------------------------------------------------

    def add_light(self, inst, ob):
        light = ob.data
        orig = _original(light)
        name = _original(ob).name
        cyc = orig.cycles
        if cyc.is_portal:
            self.warn("light '%s': portals are not supported by glint: left out" % name)
            return
        real = _original(ob)
        entry = {"name": name, "type": light.type, "matrix": _matrix(inst.matrix_world),
                 "color": list(light.color), "energy": light.energy,
                 "cast_shadow": cyc.cast_shadow,
                 "use_mis": cyc.use_multiple_importance_sampling,
                 "max_bounces": cyc.max_bounces, "is_caustics_light": cyc.is_caustics_light,
                 "visibility": _visibility(real), "shadow_catcher": real.is_shadow_catcher}
        if light.type in {'POINT', 'SPOT'}:
            entry["shadow_soft_size"] = light.shadow_soft_size
        if light.type == 'SPOT':
            entry["spot_size"] = light.spot_size
            entry["spot_blend"] = light.spot_blend
        if light.type == 'SUN':
            entry["angle"] = light.angle
        if light.type == 'AREA':
            entry.update(shape=light.shape, size=light.size, size_y=light.size_y,
                         spread=light.spread)
        if light.use_nodes and light.node_tree is not None:
            graph = node_graphs.flatten(light.node_tree, self.images, "light '%s'" % name)
            if graph is not None:
                entry["graph"] = graph
        self.lights.append(entry)

    # -- camera, world, render ----------------------------------------------------------

    def camera(self, width, height):
        scene = self.scene
        cam_ob = scene.camera
        if cam_ob is None:
            raise exporter.ExportError("the scene has no camera")
        cam = cam_ob.data
        cyc = _original(cam).cycles
        r = scene.render
        if r.use_multiview:
            self.warn("stereoscopy/multiview is not supported by glint: only the scene camera "
                      "is rendered")
        dof = cam.dof
        focus = dof.focus_distance
        if dof.focus_object is not None:
            # Cycles' blender_camera_focal_distance: the distance along the camera axis.
            fm = dof.focus_object.matrix_world
            pose = dof.focus_object.pose
            if pose is not None and dof.focus_subtarget:
                bone = pose.bones.get(dof.focus_subtarget)
                if bone is not None:
                    fm = fm @ bone.matrix
            cm = cam_ob.matrix_world
            view_dir = cm.col[2].to_3d().normalized()
            focus = abs(view_dir.dot(cm.col[3].to_3d() - fm.col[3].to_3d()))
        proj = cam_ob.calc_matrix_camera(self.dg, x=width, y=height, scale_x=r.pixel_aspect_x,
                                         scale_y=r.pixel_aspect_y)
        entry = {"name": _original(cam_ob).name, "type": cam.type,
                 "matrix": _matrix(cam_ob.matrix_world), "lens": cam.lens,
                 "sensor_width": cam.sensor_width, "sensor_height": cam.sensor_height,
                 "sensor_fit": cam.sensor_fit, "shift_x": cam.shift_x, "shift_y": cam.shift_y,
                 "ortho_scale": cam.ortho_scale, "clip_start": cam.clip_start,
                 "clip_end": cam.clip_end, "pixel_aspect": [r.pixel_aspect_x, r.pixel_aspect_y],
                 "projection": _matrix(proj),
                 "dof": {"use": dof.use_dof, "focus_distance": focus,
                         "fstop": dof.aperture_fstop, "blades": dof.aperture_blades,
                         "rotation": dof.aperture_rotation, "ratio": dof.aperture_ratio}}
        for k in ("panorama_type", "fisheye_fov", "fisheye_lens", "latitude_min",
                  "latitude_max", "longitude_min", "longitude_max", "fisheye_polynomial_k0",
                  "fisheye_polynomial_k1", "fisheye_polynomial_k2", "fisheye_polynomial_k3",
                  "fisheye_polynomial_k4"):
            if hasattr(cyc, k):
                entry[k] = getattr(cyc, k)
        return entry

    def world(self):
        world = self.scene.world
        if world is None:
            return {"color": [0.0, 0.0, 0.0],
                    "visibility": {"camera": True, "diffuse": True, "glossy": True,
                                   "transmission": True, "shadow": True, "scatter": True}}
        v = world.cycles_visibility
        entry = {"name": _original(world).name, "color": list(world.color),
                 "visibility": {"camera": v.camera, "diffuse": v.diffuse, "glossy": v.glossy,
                                "transmission": v.transmission, "shadow": v.shadow,
                                "scatter": v.scatter},
                 "cycles": _group(getattr(_original(world), "cycles", None))}
        if world.use_nodes and world.node_tree is not None:
            graph = node_graphs.flatten(world.node_tree, self.images, "the world")
            if graph is not None:
                entry["graph"] = graph
        return entry

    def render(self, width, height):
        scene = self.scene
        r, c = scene.render, _original(scene).cycles
        seed = c.seed
        if c.use_animated_seed:  # Cycles' blender/sync.cpp
            seed = hash_uint2(scene.frame_current & _U32, c.seed & _U32)
            if scene.frame_subframe != 0.0:
                seed += hash_uint2(int(scene.frame_subframe * 2147483647) & _U32,
                                   c.seed & _U32)
            seed &= _U32
        return {
            "width": width, "height": height, "frame": scene.frame_current,
            "samples": c.samples, "seed": seed, "time_limit": c.time_limit,
            "adaptive_sampling": {"use": c.use_adaptive_sampling,
                                  "threshold": c.adaptive_threshold,
                                  "min_samples": c.adaptive_min_samples},
            "max_bounces": {"total": c.max_bounces, "diffuse": c.diffuse_bounces,
                            "glossy": c.glossy_bounces,
                            "transmission": c.transmission_bounces,
                            "transparent": c.transparent_max_bounces,
                            "volume": c.volume_bounces},
            "film_transparent": r.film_transparent,
            "film_transparent_glass": c.film_transparent_glass,
            "volume_step_rate": c.volume_step_rate, "volume_max_steps": c.volume_max_steps,
            "film_transparent_roughness": c.film_transparent_roughness,
            "exposure": c.film_exposure, "pixel_filter": c.pixel_filter_type,
            "filter_width": c.filter_width, "clamp_direct": c.sample_clamp_direct,
            "clamp_indirect": c.sample_clamp_indirect, "filter_glossy": c.blur_glossy,
            "caustics_reflective": c.caustics_reflective,
            "caustics_refractive": c.caustics_refractive,
            "light_sampling_threshold": c.light_sampling_threshold,
            "motion_blur": {"use": bool(self.motion), "position": c.motion_blur_position,
                            "shutter": r.motion_blur_shutter},
        }

    # -- warnings -----------------------------------------------------------------------

    def left_out(self):
        exporter.left_out_warnings(self.dg, self.warn)
        if self.motion and _original(self.scene).cycles.rolling_shutter_type != 'NONE':
            self.warn("rolling shutter is not supported by glint: the whole frame is exposed "
                      "at once")
        if self.motion and not _flat_shutter(
                _original(self.scene).render.motion_blur_shutter_curve):
            self.warn("a shaped shutter curve is not supported by glint: the shutter opens and "
                      "closes at once (Cycles' default curve)")
        hair, adaptive, seen = [], [], set()
        experimental = _original(self.scene).cycles.feature_set == 'EXPERIMENTAL'
        for inst in self.dg.object_instances:
            ob = _original(inst.object)
            if ob is None or ob.as_pointer() in seen:
                continue
            seen.add(ob.as_pointer())
            if any(ps.settings.type == 'HAIR' and ps.settings.render_type == 'PATH'
                   for ps in getattr(ob, "particle_systems", ())):
                hair.append(ob.name)
            if experimental and ob.type in SURFACE_TYPES and ob.cycles.use_adaptive_subdivision \
                    and ob.modifiers and ob.modifiers[-1].type == 'SUBSURF':
                adaptive.append(ob.name)
        for names, what in ((hair, "hair particles are not supported by glint: the hair of %s "
                             "is left out"),
                            (adaptive, "adaptive subdivision is not supported by glint: %s "
                             "rendered with the subdivision modifier's render level")):
            if names:
                shown = ", ".join("'%s'" % n for n in names[:5])
                if len(names) > 5:
                    shown += " and %d more" % (len(names) - 5)
                self.warn(what % shown)

    # -- motion -------------------------------------------------------------------------

    def frame_set(self, time):
        frame = int(math.floor(time))
        sub = time - frame
        if self.engine is not None:
            self.engine.frame_set(frame, subframe=sub)
        else:
            _original(self.scene).frame_set(frame, subframe=sub)

    def sample_motion(self, camera_entry, center, shutter):
        """Matrices at Cycles' motion times (center + t * shutter / 2, t from -1 to 1) for the
        camera and every moving object; the frame is left at `center`."""
        cam_ob = self.scene.camera
        cam_steps = _motion_steps(cam_ob, cam_ob)
        n = max([cam_steps] + [s for _, s in self.motion_keys.values()])
        if n < 2:
            return
        times = [-1.0 + 2.0 * i / (n - 1) for i in range(n)]
        cam_mats, obj_mats = [], {k: [] for k in self.motion_keys}
        shapes = {k: [] for k in self.deform_keys}
        try:
            for t in times:
                self.frame_set(center + t * shutter * 0.5)
                scene = self.dg.scene_eval
                cam_mats.append(_matrix(scene.camera.matrix_world))
                for inst in self.dg.object_instances:
                    ob = inst.object
                    if not isinstance(ob.data, bpy.types.Mesh):
                        continue
                    key = _instance_key(inst, ob)
                    mats = obj_mats.get(key)
                    if mats is not None:
                        mats.append(_matrix(inst.matrix_world))
                    got = shapes.get(key)
                    if got is not None and len(got) < len(cam_mats):
                        got.append(mesh_motion_arrays(ob.data, self.deform_keys[key][2]))
        finally:
            self.frame_set(center)

        def pick(mats, steps):
            if steps < 2 or len(mats) != n:
                return None
            stride = (n - 1) // (steps - 1)
            picked = mats[::stride]
            return picked if any(m != picked[0] for m in picked) else None

        m = pick(cam_mats, cam_steps)
        if m:
            camera_entry["motion"] = m
        for key, (entry, steps) in self.motion_keys.items():
            m = pick(obj_mats[key], steps)
            if m:
                entry["motion"] = m
        for key, (mesh, steps, _) in self.deform_keys.items():
            got = shapes[key]
            if steps < 2 or len(got) != n:
                continue
            if any(g is None for g in got):
                name = self.meshes[mesh]["name"]
                self.warn("mesh '%s' changes its topology within the shutter: its deformation "
                          "is not blurred (as in Cycles)" % name)
                continue
            picked = got[::(n - 1) // (steps - 1)]
            if all(np.array_equal(g[0], picked[0][0]) for g in picked):
                continue  # deform-modified, but not moving over the shutter
            self.meshes[mesh]["motion"] = [
                {"positions": self.buf.view(pos, "f32", 3), "normals": self.buf.view(nor, "f32", 3)}
                for pos, nor in picked]

    # -- all ----------------------------------------------------------------------------

    def run(self):
        os.makedirs(self.out_dir, exist_ok=True)
        scene = self.scene
        width, height = exporter.render_size(scene)
        start_time = scene.frame_current + scene.frame_subframe
        center = start_time
        shutter = scene.render.motion_blur_shutter
        position = _original(scene).cycles.motion_blur_position
        if self.motion and position != 'CENTER':  # Cycles syncs at the shutter's middle
            center += shutter * 0.5 if position == 'START' else -shutter * 0.5
            self.frame_set(center)
        try:
            camera = self.camera(width, height)  # first: a camera error stops early
            self.left_out()
            self.buf = Buffer(os.path.join(self.out_dir, BIN_NAME))
            try:
                for inst in self.dg.object_instances:
                    ob = inst.object
                    if ob.type == 'LIGHT':
                        self.add_light(inst, ob)
                    elif inst.show_self and smoke.gas_domain(ob) is not None:
                        self.add_smoke(inst, ob, smoke.gas_domain(ob))
                    elif inst.show_self and isinstance(ob.data, bpy.types.Mesh):
                        self.add_object(inst, ob)
                    elif inst.show_self and ob.type == 'VOLUME':
                        self.add_volume(inst, ob)
                world = self.world()
                if self.motion:
                    self.sample_motion(camera, center, shutter)  # deforming meshes' steps too
            finally:
                self.buf.close()
        finally:
            if center != start_time:
                self.frame_set(start_time)
        self.images.missing.report(self.warn)
        doc = {"format": "glint-blender", "version": FORMAT_VERSION,
               "generator": "glint_blender 1, Blender %s" % bpy.app.version_string,
               "buffers": BIN_NAME, "render": self.render(width, height), "camera": camera,
               "world": world, "meshes": self.meshes, "materials": self.materials,
               "objects": self.objects, "lights": self.lights}
        json_path = os.path.join(self.out_dir, JSON_NAME)
        text = json.dumps(doc, separators=(",", ":"), allow_nan=False)  # C encoder: json.dump
        with open(json_path, "w", encoding="utf-8") as f:                # is pure Python
            f.write(text)
        # What makes glint's image RGBA (its render.cpp): a transparent film or a holdout.
        self.alpha = (doc["render"]["film_transparent"] or
                      any(o["holdout"] for o in self.objects) or
                      '"ShaderNodeHoldout"' in text)
        return json_path, width, height


def export_frame_native(depsgraph, out_dir, warn, engine=None):
    """Writes scene.json and scene.bin for depsgraph's current frame into out_dir (see the
    module doc) and returns the exporter.Export that renders them. Raises
    exporter.ExportError for a scene glint cannot render; calls warn(msg) for what the exchange
    cannot carry (the caller de-duplicates). `engine`: the RenderEngine whose frame_set moves
    the depsgraph to motion blur's sample times (default: the scene's frame_set)."""
    ex = _Exporter(depsgraph, out_dir, warn, engine)
    json_path, width, height = ex.run()
    output_path = os.path.join(out_dir, "out.exr")
    settings = getattr(depsgraph.scene_eval, "glint", None)
    argv = exporter.glint_argv(settings, json_path, output_path, width, height)
    with open(os.path.join(out_dir, "command.txt"), "w", encoding="utf-8") as f:
        f.write(shlex.join(["glint"] + argv) + "\n")
    export = exporter.Export(out_dir, json_path, output_path, width, height, argv, ex.names)
    export.alpha = ex.alpha
    return export
