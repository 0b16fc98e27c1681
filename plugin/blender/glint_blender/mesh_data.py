"""The meshes of the native exchange (formats/blender/FORMAT.md "meshes"): scene.bin's writer,
Blender's evaluated meshes read with foreach_get into numpy arrays, the MikkTSpace tangents
a Normal Map reads and a deforming mesh's motion steps. Used by native_export."""

import math

import bpy
import numpy as np

class Buffer:
    """scene.bin, written as views are added (each 4-byte aligned). (A writer thread that
    overlapped the writes with the reads measured slower: the GIL hand-overs cost more.)"""
    _DTYPES = {"f32": "<f4", "u32": "<u4", "u16": "<u2", "u8": "u1"}

    def __init__(self, path):
        self.f = open(path, "wb")
        self.offset = 0

    def view(self, arr, kind, components=1):
        a = np.ascontiguousarray(arr, dtype=self._DTYPES[kind]).reshape(-1)
        start = self.offset
        self.f.write(a.data)
        self.offset += a.nbytes
        pad = -self.offset % 4
        if pad:
            self.f.write(b"\0" * pad)
            self.offset += pad
        view = {"offset": start, "count": a.size // components, "type": kind}
        if components != 1:
            view["components"] = components
        return view

    def close(self):
        self.f.close()


def _get(collection, attr, n, dtype):
    out = np.empty(n, dtype=dtype)
    if n:
        collection.foreach_get(attr, out)
    return out


def _rows(a, k=3):
    """An (n, k) float32 array seen as n opaque rows: fancy indexing moves whole rows at once
    (several times faster than indexing the 2-D array)."""
    return np.ascontiguousarray(a, dtype=np.float32).reshape(-1).view(
        np.dtype((np.void, 4 * k)))


class _Polys:
    """Per-triangle polygon data, read only when needed."""

    def __init__(self, me, nt):
        self.me, self.nt, self._index = me, nt, None

    def index(self):
        if self._index is None:
            self._index = _get(self.me.loop_triangles, "polygon_index", self.nt, np.uint32)
        return self._index

    def per_triangle(self, values):
        """values per polygon -> per triangle (no read when they are all equal)."""
        if len(values) and (values == values[0]).all():
            return np.full(self.nt, values[0], dtype=values.dtype)
        return values[self.index()]


def _corner_normals(me, nl, tris, polys, smooth, loop_vertex):
    """Blender's split normals per corner. Without Auto Smooth (so without custom normals) they
    are the vertex normals on smooth faces and the face normal on flat ones, read raw and
    gathered (several times faster); else the triangles' split_normals scattered to their
    corners (every corner belongs to a triangle)."""
    nv, npoly = len(me.vertices), len(me.polygons)
    if not me.use_auto_smooth:
        vn = _get(me.vertex_normals, "vector", nv * 3, np.float32)
        normals = _rows(vn)[loop_vertex]
        flat = ~smooth
        if flat.any():
            pn = _rows(_get(me.polygon_normals, "vector", npoly * 3, np.float32))
            corners = tris.reshape(-1, 3)[flat]
            per_tri = pn[polys.index()[flat]]
            for k in range(3):
                normals[corners[:, k]] = per_tri
        return normals.view(np.float32)
    me.calc_normals_split()
    normals = np.zeros(nl, dtype=np.dtype((np.void, 12)))
    normals[tris] = _rows(_get(me.loop_triangles, "split_normals", len(tris) * 3, np.float32))
    return normals.view(np.float32)


def mesh_entry(me, name, buf):
    """One evaluated mesh as FORMAT.md's mesh entry (arrays into buf); None without
    triangles. Unsigned Blender fields are read into uint32 arrays (foreach_get's raw path:
    about ten times faster than into int32)."""
    me.calc_loop_triangles()
    nt = len(me.loop_triangles)
    if nt == 0:
        return None
    nv, nl, npoly = len(me.vertices), len(me.loops), len(me.polygons)
    polys = _Polys(me, nt)
    tris = _get(me.loop_triangles, "loops", nt * 3, np.uint32)
    smooth = polys.per_triangle(_get(me.polygons, "use_smooth", npoly, bool))
    attr = me.attributes.get("material_index")
    if attr is not None and attr.domain == 'FACE' and attr.data_type == 'INT':
        mat = polys.per_triangle(np.clip(_get(attr.data, "value", npoly, np.int32), 0,
                                         0xFFFF).astype(np.uint16))
    else:
        mat = np.zeros(nt, dtype=np.uint16)
    loop_vertex = _get(me.loops, "vertex_index", nl, np.uint32)
    entry = {
        "name": name,
        "positions": buf.view(_get(me.vertices, "co", nv * 3, np.float32), "f32", 3),
        "loop_vertex": buf.view(loop_vertex, "u32"),
        "triangles": buf.view(tris, "u32", 3),
        "normals": buf.view(_corner_normals(me, nl, tris, polys, smooth, loop_vertex), "f32",
                            3),
        "smooth": buf.view(smooth, "u8"),
        "material_index": buf.view(mat, "u16"),
        "uv_layers": [{"name": uv.name, "active_render": uv.active_render,
                       "data": buf.view(_get(uv.data, "uv", nl * 2, np.float32), "f32", 2)}
                      for uv in me.uv_layers],
        "texspace": {"location": list(me.texspace_location), "size": list(me.texspace_size)},
    }
    colors = []
    cattrs = me.color_attributes
    render_index = cattrs.render_color_index
    for i, ca in enumerate(cattrs):
        if ca.domain not in {'POINT', 'CORNER'}:
            continue
        n = nv if ca.domain == 'POINT' else nl
        colors.append({"name": ca.name, "domain": ca.domain, "active_render": i == render_index,
                       "data": buf.view(_get(ca.data, "color", n * 4, np.float32), "f32", 4)})
    entry["colors"] = colors
    return entry


def tangent_maps(graph):
    """The UV maps ("" = the active render one) whose tangents a material's Normal Map nodes
    read in tangent space."""
    return {n.get("props", {}).get("uv_map", "") for n in (graph or {}).get("nodes", ())
            if n.get("type") == "ShaderNodeNormalMap" and
            n.get("props", {}).get("space", "TANGENT") == "TANGENT"}


def add_tangents(entry, me, names, buf):
    """MikkTSpace tangents and bitangent signs per triangle corner of the UV maps `names` (""
    = active render), added to the mesh entry's "tangents" once each. Cycles 3.4 runs
    MikkTSpace over its triangles (blender/mesh.cpp, mikk_compute_tangents), not over
    Blender's quads and n-gons, and the two differ; so Blender's calc_tangents runs here on a
    temporary mesh of the loop triangles, with the mesh's split normals on its smooth faces
    and each triangle's own normal on flat ones, as Cycles gives them to MikkTSpace."""
    have = entry.setdefault("tangents", [])
    render = next((uv.name for uv in me.uv_layers if uv.active_render), "")
    wanted = [n or render for n in sorted(names)]
    wanted = [n for i, n in enumerate(wanted) if n and n in me.uv_layers and n not in wanted[:i]
              and all(t["uv_map"] != n for t in have)]
    if not wanted:
        if not have:
            del entry["tangents"]
        return
    nv, nl, nt = len(me.vertices), len(me.loops), len(me.loop_triangles)
    tris = _get(me.loop_triangles, "loops", nt * 3, np.uint32)
    polys = _Polys(me, nt)
    smooth = polys.per_triangle(_get(me.polygons, "use_smooth", len(me.polygons), bool))
    loop_vertex = _get(me.loops, "vertex_index", nl, np.uint32)
    normals = np.array(_corner_normals(me, nl, tris, polys, smooth, loop_vertex)).reshape(-1, 3)
    tmp = bpy.data.meshes.new("glint_tangents")
    try:
        tmp.vertices.add(nv)
        tmp.vertices.foreach_set("co", _get(me.vertices, "co", nv * 3, np.float32))
        tmp.loops.add(nt * 3)
        tmp.loops.foreach_set("vertex_index", loop_vertex[tris].astype(np.int32))
        tmp.polygons.add(nt)
        tmp.polygons.foreach_set("loop_start", np.arange(0, nt * 3, 3, dtype=np.int32))
        tmp.polygons.foreach_set("loop_total", np.full(nt, 3, dtype=np.int32))
        tmp.polygons.foreach_set("use_smooth", smooth)
        for name in wanted:
            uv = _get(me.uv_layers[name].data, "uv", nl * 2, np.float32).reshape(-1, 2)
            tmp.uv_layers.new(name=name).data.foreach_set("uv", uv[tris].reshape(-1))
        tmp.update()
        tmp.use_auto_smooth = True
        tmp.auto_smooth_angle = math.pi
        tmp.normals_split_custom_set(normals[tris].tolist())
        for name in wanted:
            tmp.calc_tangents(uvmap=name)
            have.append({"uv_map": name, "active_render": name == render,
                         "tangent": buf.view(_get(tmp.loops, "tangent", nt * 9, np.float32),
                                             "f32", 3),
                         "sign": buf.view(_get(tmp.loops, "bitangent_sign", nt * 3, np.float32),
                                          "f32")})
            tmp.free_tangents()
    finally:
        bpy.data.meshes.remove(tmp)


def mesh_motion_arrays(me, counts):
    """A deforming mesh at one motion time: (positions, split normals) as float32 arrays, None
    when its topology (vertex, corner and triangle counts) differs from `counts`, the centre's
    (Cycles then drops the object's deformation blur too)."""
    me.calc_loop_triangles()
    nv, nl, nt = len(me.vertices), len(me.loops), len(me.loop_triangles)
    if (nv, nl, nt) != counts:
        return None
    polys = _Polys(me, nt)
    tris = _get(me.loop_triangles, "loops", nt * 3, np.uint32)
    smooth = polys.per_triangle(_get(me.polygons, "use_smooth", len(me.polygons), bool))
    loop_vertex = _get(me.loops, "vertex_index", nl, np.uint32)
    return (_get(me.vertices, "co", nv * 3, np.float32),
            np.array(_corner_normals(me, nl, tris, polys, smooth, loop_vertex), copy=True))


# ----------------------------------------------------------------------------- helpers
