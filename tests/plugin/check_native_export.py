"""Checks a folder written by the add-on's native export (formats/blender/FORMAT.md): the JSON
is valid (no NaN / infinity), every buffer view lies inside the .bin, counts agree, indices are
in range, every graph link names a node and one of its outputs.

    python3 tests/plugin/check_native_export.py DIR            (or DIR/scene.json)
    blender -b --factory-startup --python tests/plugin/check_native_export.py -- DIR

As a module: check(path) -> the loaded document; raises AssertionError naming the JSON path.
numpy is used when there is one (Blender's Python), else the array module.
"""

import array
import json
import math
import os
import sys

try:
    import numpy as np
except ImportError:  # plain python3: slower, same checks
    np = None

TYPES = {"f32": ("<f4", "f", 4), "u32": ("<u4", "I", 4), "u16": ("<u2", "H", 2),
         "u8": ("u1", "B", 1)}
VIS_OBJECT = {"camera", "diffuse", "glossy", "transmission", "shadow", "volume_scatter"}
SOCKET_TYPES = {"VALUE", "RGBA", "VECTOR", "SHADER", "INT", "BOOLEAN", "STRING", "CUSTOM"}


def _no_constant(name):
    raise AssertionError("the JSON holds %s (not JSON; nlohmann-json rejects it)" % name)


class Checker:
    def __init__(self, json_path):
        with open(json_path, encoding="utf-8") as f:
            self.doc = json.load(f, parse_constant=_no_constant)
        d = self.doc
        assert d.get("format") == "glint-blender", "format: %r" % d.get("format")
        assert d.get("version") == 1, "version: %r" % d.get("version")
        self.bin_path = os.path.join(os.path.dirname(os.path.abspath(json_path)),
                                     d["buffers"])
        with open(self.bin_path, "rb") as f:
            self.data = f.read()

    # -- buffers ------------------------------------------------------------------------

    def view(self, v, where, kind=None, components=1, count=None):
        """The array a view names (flat), after checking it against the file."""
        assert isinstance(v, dict), "%s: not a buffer view" % where
        for k in ("offset", "count", "type"):
            assert k in v, "%s.%s missing" % (where, k)
        assert v["type"] in TYPES, "%s.type: %r" % (where, v["type"])
        if kind is not None:
            assert v["type"] == kind, "%s.type: %s, expected %s" % (where, v["type"], kind)
        comps = v.get("components", 1)
        assert comps == components, "%s.components: %s, expected %s" % (where, comps,
                                                                        components)
        off, n = v["offset"], v["count"]
        assert isinstance(off, int) and off >= 0 and off % 4 == 0, "%s.offset: %r" % (where, off)
        assert isinstance(n, int) and n >= 0, "%s.count: %r" % (where, n)
        if count is not None:
            assert n == count, "%s.count: %d, expected %d" % (where, n, count)
        dt, code, size = TYPES[v["type"]]
        end = off + n * comps * size
        assert end <= len(self.data), "%s: bytes %d..%d outside %s (%d bytes)" % (
            where, off, end, os.path.basename(self.bin_path), len(self.data))
        if np is not None:
            a = np.frombuffer(self.data, dtype=dt, count=n * comps, offset=off)
            if v["type"] == "f32":
                assert np.isfinite(a).all(), "%s: not finite" % where
            return a
        a = array.array(code)
        a.frombytes(self.data[off:end])
        if sys.byteorder != "little":
            a.byteswap()
        if v["type"] == "f32":
            assert all(math.isfinite(x) for x in a), "%s: not finite" % where
        return a

    @staticmethod
    def below(a, limit, where):
        if len(a):
            m = int(a.max()) if np is not None else max(a)
            assert m < limit, "%s: index %d >= %d" % (where, m, limit)

    # -- parts --------------------------------------------------------------------------

    def matrix(self, m, where):
        assert isinstance(m, list) and len(m) == 16 and all(
            isinstance(x, (int, float)) for x in m), "%s: not 16 numbers" % where

    def mesh(self, m, where):
        assert isinstance(m.get("name"), str), "%s.name" % where
        pos = self.view(m["positions"], where + ".positions", "f32", 3)
        nv = len(pos) // 3
        lv = self.view(m["loop_vertex"], where + ".loop_vertex", "u32")
        nl = len(lv)
        self.below(lv, nv, where + ".loop_vertex")
        tris = self.view(m["triangles"], where + ".triangles", "u32", 3)
        nt = len(tris) // 3
        assert nt > 0, "%s: no triangles" % where
        self.below(tris, nl, where + ".triangles")
        self.view(m["normals"], where + ".normals", "f32", 3, nl)
        sm = self.view(m["smooth"], where + ".smooth", "u8", 1, nt)
        self.below(sm, 2, where + ".smooth")
        self.view(m["material_index"], where + ".material_index", "u16", 1, nt)
        for i, uv in enumerate(m.get("uv_layers", [])):
            w = "%s.uv_layers[%d]" % (where, i)
            assert isinstance(uv.get("name"), str) and isinstance(uv.get("active_render"),
                                                                  bool), w
            self.view(uv["data"], w + ".data", "f32", 2, nl)
        for i, c in enumerate(m.get("colors", [])):
            w = "%s.colors[%d]" % (where, i)
            assert c.get("domain") in {"POINT", "CORNER"}, w + ".domain"
            self.view(c["data"], w + ".data", "f32", 4, nv if c["domain"] == "POINT" else nl)
        return nt

    def graph(self, g, where):
        assert isinstance(g, dict) and isinstance(g.get("nodes"), list), where
        nodes = g["nodes"]
        assert 0 <= g.get("output", -1) < len(nodes), "%s.output" % where
        outputs = [{o["id"] for o in n.get("outputs", [])} for n in nodes]
        for i, n in enumerate(nodes):
            w = "%s.nodes[%d]" % (where, i)
            assert isinstance(n.get("type"), str) and isinstance(n.get("name"), str), w
            assert isinstance(n.get("props"), dict), w + ".props"
            ids = set()
            for j, s in enumerate(n.get("inputs", [])):
                ws = "%s.inputs[%d]" % (w, j)
                assert isinstance(s.get("id"), str) and s.get("type") in SOCKET_TYPES, ws
                assert s["id"] not in ids, ws + ": duplicate id " + s["id"]
                ids.add(s["id"])
                if "link" in s:
                    k, out = s["link"]
                    assert isinstance(k, int) and 0 <= k < len(nodes), ws + ".link: node"
                    assert k != i, ws + ".link: to itself"
                    assert out in outputs[k], "%s.link: node %d has no output %r" % (ws, k,
                                                                                      out)
            for j, o in enumerate(n.get("outputs", [])):
                assert o.get("type") in SOCKET_TYPES, "%s.outputs[%d]" % (w, j)
            ramp = n["props"].get("ramp")
            if ramp is not None:
                assert len(ramp["table"]) == 256 and all(len(e) == 4 for e in ramp["table"]), \
                    w + ".props.ramp.table"
            curves = n["props"].get("curves")
            if curves is not None:
                lo, hi = curves["range"]
                assert lo <= hi and curves["tables"] and all(
                    len(t) == 256 for t in curves["tables"]), w + ".props.curves"
            image = n["props"].get("image")
            if image is not None:
                assert isinstance(image.get("path"), str) or "missing" in image, \
                    w + ".props.image: neither a path nor missing"

    def check(self):
        d = self.doc
        r = d["render"]
        assert isinstance(r["width"], int) and r["width"] > 0, "render.width"
        assert isinstance(r["height"], int) and r["height"] > 0, "render.height"
        c = d["camera"]
        assert c["type"] in {"PERSP", "ORTHO", "PANO"}, "camera.type"
        self.matrix(c["matrix"], "camera.matrix")
        for i, m in enumerate(c.get("motion", [])):
            self.matrix(m, "camera.motion[%d]" % i)
        for k in ("lens", "sensor_width", "sensor_height", "clip_start", "clip_end"):
            assert isinstance(c[k], (int, float)), "camera." + k
        assert isinstance(c["dof"]["focus_distance"], (int, float)), "camera.dof"
        w = d["world"]
        assert len(w["color"]) == 3, "world.color"
        if "graph" in w:
            self.graph(w["graph"], "world.graph")
        tri_counts = [self.mesh(m, "meshes[%d]" % i) for i, m in enumerate(d["meshes"])]
        for i, m in enumerate(d["materials"]):
            assert isinstance(m.get("name"), str), "materials[%d].name" % i
            self.graph(m["graph"], "materials[%d].graph" % i)
        used = set()
        for i, o in enumerate(d["objects"]):
            w = "objects[%d]" % i
            assert isinstance(o.get("mesh"), int) and 0 <= o["mesh"] < len(d["meshes"]), \
                w + ".mesh"
            used.add(o["mesh"])
            self.matrix(o["matrix"], w + ".matrix")
            for j, m in enumerate(o.get("motion", [])):
                self.matrix(m, "%s.motion[%d]" % (w, j))
            mats = o["materials"]
            assert mats and all(isinstance(k, int) and -1 <= k < len(d["materials"])
                                for k in mats), w + ".materials"
            assert set(o["visibility"]) == VIS_OBJECT, w + ".visibility"
            assert 0.0 <= o["random"] <= 1.0, w + ".random"
            assert len(o["color"]) == 4, w + ".color"
        assert used == set(range(len(d["meshes"]))), "meshes no object uses: %s" % sorted(
            set(range(len(d["meshes"]))) - used)
        for i, l in enumerate(d["lights"]):
            w = "lights[%d]" % i
            assert l["type"] in {"POINT", "SPOT", "SUN", "AREA"}, w + ".type"
            self.matrix(l["matrix"], w + ".matrix")
            assert len(l["color"]) == 3, w + ".color"
            if "graph" in l:
                self.graph(l["graph"], w + ".graph")
        return {"meshes": len(d["meshes"]), "triangles": sum(tri_counts),
                "objects": len(d["objects"]), "materials": len(d["materials"]),
                "lights": len(d["lights"]), "bin_bytes": len(self.data)}


def check(path):
    """Checks DIR or DIR/scene.json; returns (document, summary)."""
    if os.path.isdir(path):
        path = os.path.join(path, "scene.json")
    c = Checker(path)
    return c.doc, c.check()


def main(argv):
    if "--" in argv:
        argv = argv[argv.index("--") + 1:]
    else:
        argv = argv[1:]
    if not argv:
        print(__doc__)
        return 2
    status = 0
    for p in argv:
        try:
            _, summary = check(p)
            print("%s: ok %s" % (p, summary))
        except (AssertionError, KeyError, ValueError, TypeError) as e:
            print("%s: FAILED: %s: %s" % (p, type(e).__name__, e))
            status = 1
    return status


if __name__ == "__main__":
    code = main(sys.argv)
    if code:
        sys.exit(code)
