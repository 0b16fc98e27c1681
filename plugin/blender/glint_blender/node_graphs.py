"""Blender shader node trees -> the exchange's flattened shader graphs (formats/blender/FORMAT.md,
"materials and shader graphs").

    flatten(node_tree, images) -> {"output": 0, "nodes": [...]} or None (no Cycles output node)

`images(image, user)` gives the "image" entry of an Image/Environment texture (native_export.py
writes the file). The graph is what Cycles 3.4 builds from the tree (intern/cycles/blender/
shader.cpp, add_nodes): node groups inlined (Group Input / Group Output joined through), reroutes
and muted nodes replaced by their internal links, muted and invalid links dropped, frames and
inactive output nodes left out. Only the nodes the active output (and AOV outputs) reach are
written, the output node first.

Values that reach an input through a group socket or a muted node (Cycles' proxy nodes):
  - a group node's unlinked input gives its value to what the Group Input feeds, an unlinked input
    of the active Group Output its value to what the group node's output feeds;
  - a muted node's (or reroute's) internal link whose input is unlinked gives ZERO (Cycles' proxy
    keeps its zero default: measured with Cycles 3.4, a muted Mix with an unlinked red Color1
    renders black), and an output with no internal link leaves its consumer unlinked (its own
    value is used).
A value of the consumer's socket type is written as the consumer's "value"; a value of another
type becomes a constant node (ShaderNodeValue / ShaderNodeRGB / ShaderNodeCombineXYZ) linked to the
consumer, so that glint converts it as it converts links.

Nothing here warns: glint's importer reports the node types it lacks.
"""

import math

import bpy
import numpy as np

RAMP_TABLE_SIZE = 256  # Cycles 3.4's RAMP_TABLE_SIZE: tables of 256 entries at i / 255

_GENERIC_NODE_PROPS = frozenset(bpy.types.Node.bl_rna.properties.keys()) | {
    "is_active_output", "color_ramp", "mapping"}  # the last two have their own entries
_GROUP_TYPES = frozenset({"ShaderNodeGroup", "NodeCustomGroup", "ShaderNodeCustomGroup"})
_OUTPUT_VALUE_TYPES = frozenset({"ShaderNodeValue", "ShaderNodeRGB", "ShaderNodeNormal"})
_ZERO = ("zero",)
_FLT_MAX = 3.4028234663852886e38


def finite(x):
    """JSON (and nlohmann-json) has no NaN or infinity: NaN -> 0, +-inf -> +-FLT_MAX."""
    if math.isfinite(x):
        return x
    return 0.0 if math.isnan(x) else math.copysign(_FLT_MAX, x)


def value(v):
    """A socket's or property's value as JSON: numbers, booleans, strings, lists."""
    if isinstance(v, float):
        return finite(v)
    if isinstance(v, (bool, int, str)) or v is None:
        return v
    try:
        return [value(x) for x in v]
    except TypeError:
        return None


def _zero_like(v):
    if isinstance(v, list):
        return [0.0] * 3 + [1.0] if len(v) == 4 else [0.0] * len(v)
    if isinstance(v, bool):
        return False
    if isinstance(v, (int, float)):
        return type(v)(0)
    return v


_prop_cache = {}


def _node_props(node):
    """(identifier, rna property) of a node's own settings, by node type (cached)."""
    key = node.bl_idname
    props = _prop_cache.get(key)
    if props is None:
        props = [(p.identifier, p) for p in node.bl_rna.properties
                 if p.identifier not in _GENERIC_NODE_PROPS and not p.identifier.startswith("bl_")]
        _prop_cache[key] = props
    return props


def _prop(owner, ident, prop, images, user, depth=0):
    """One RNA property as JSON; None to leave it out."""
    t = prop.type
    v = getattr(owner, ident, None)
    if t == 'ENUM':
        return sorted(v) if prop.is_enum_flag else v
    if t in {'BOOLEAN', 'INT', 'FLOAT', 'STRING'}:
        return value(v)
    if t != 'POINTER' or v is None:
        return None
    if isinstance(v, bpy.types.Image):
        return images(v, user)
    if isinstance(v, bpy.types.Object):
        return {"name": v.name, "matrix": [finite(x) for row in v.matrix_world for x in row]}
    if isinstance(v, bpy.types.ID):
        return {"name": v.name_full, "id_type": type(v).__name__}
    if depth > 0:
        return None
    out = {}  # a settings struct: TexMapping, ColorMapping, ImageUser, ...
    for p in v.bl_rna.properties:
        if p.identifier == "rna_type":
            continue
        pv = _prop(v, p.identifier, p, images, user, depth + 1)
        if pv is not None:
            out[p.identifier] = pv
    return out


def color_ramp(ramp):
    """ColorRamp as Cycles bakes it (colorramp_to_array: evaluate at i / 255)."""
    return {
        "interpolation": ramp.interpolation, "color_mode": ramp.color_mode,
        "hue_interpolation": ramp.hue_interpolation,
        "elements": [[finite(e.position)] + value(e.color) for e in ramp.elements],
        "table": [value(ramp.evaluate(i / (RAMP_TABLE_SIZE - 1)))
                  for i in range(RAMP_TABLE_SIZE)],
    }


def curve_mapping(mapping, kind):
    """RGB / Vector / Float curves baked as Cycles 3.4 bakes them (blender/util.h,
    curvemapping_color_to_array / curvemapping_float_to_array with curvemapping_minmax): the
    range spans the first to the last point of the curves used (4 for RGB, 3 for vector, 1 for
    float), t = min + i / 255 * (max - min) in float, RGB entries are (R(C(t)), G(C(t)),
    B(C(t))). Cycles extrapolates past the range only when the mapping extends EXTRAPOLATED
    (measured with Cycles 3.4)."""
    n = {"RGB": 4, "VECTOR": 3, "FLOAT": 1}[kind]
    mapping.initialize()
    mapping.update()
    curves = mapping.curves
    lo = np.float32(min(curves[i].points[0].location[0] for i in range(n)))
    hi = np.float32(max(curves[i].points[len(curves[i].points) - 1].location[0]
                        for i in range(n)))
    span = np.float32(hi - lo)
    steps = np.arange(RAMP_TABLE_SIZE, dtype=np.float32) / np.float32(RAMP_TABLE_SIZE - 1)
    ts = (lo + steps * span).astype(np.float32).tolist()
    ev = mapping.evaluate
    if kind == "RGB":
        c = curves[3]
        ts = [ev(c, t) for t in ts]
        tables = [[finite(ev(curves[i], t)) for t in ts] for i in range(3)]
    else:
        tables = [[finite(ev(curves[i], t)) for t in ts] for i in range(n)]
    return {"range": [float(lo), float(hi)], "tables": tables,
            "extrapolate": mapping.extend == 'EXTRAPOLATED', "extend": mapping.extend}


_CURVE_KINDS = {"ShaderNodeRGBCurve": "RGB", "ShaderNodeVectorCurve": "VECTOR",
                "ShaderNodeFloatCurve": "FLOAT"}


def node_props(node, images, user):
    props = {}
    for ident, p in _node_props(node):
        v = _prop(node, ident, p, images, user)
        if v is not None:
            props[ident] = v
    ramp = getattr(node, "color_ramp", None)
    if ramp is not None:
        props["ramp"] = color_ramp(ramp)
    kind = _CURVE_KINDS.get(node.bl_idname)
    if kind is not None:
        props["curves"] = curve_mapping(node.mapping, kind)
    return props


def _socket_by_id(sockets, identifier):
    for s in sockets:
        if s.identifier == identifier:
            return s
    return None


def _group_output(tree):
    outs = [n for n in tree.nodes if n.bl_idname == "NodeGroupOutput"]
    for n in outs:
        if n.is_active_output:
            return n
    return outs[0] if outs else None


class _Flattener:
    def __init__(self, images, user):
        self.images = images
        self.user = user
        self.nodes = []
        self.index = {}

    # -- sources ------------------------------------------------------------------------

    def source(self, sock, path):
        """What feeds an input in the group path: ("link", node index, output id), ("const",
        socket) (that socket's value), _ZERO, or None (unlinked: the input's own value)."""
        if not sock.is_linked:
            return None
        link = sock.links[0]
        # Cycles 3.4 drops muted and invalid links and those that start or end at an
        # unavailable socket (the input keeps its own default: a Nishita Sky Texture with its
        # sun disc on reads Generated whatever is linked to its hidden Vector).
        if link.is_muted or not link.is_valid or not link.from_socket.enabled or \
                not sock.enabled:
            return None
        return self.from_output(link.from_node, link.from_socket, path)

    def from_output(self, node, out, path):
        idname = node.bl_idname
        if node.mute or idname == "NodeReroute":
            ptr = out.as_pointer()
            for il in node.internal_links:
                if il.to_socket.as_pointer() == ptr:
                    src = self.source(il.from_socket, path)
                    return _ZERO if src is None else src
            return None
        if idname == "NodeGroupInput":
            if not path:
                return None
            gin = _socket_by_id(path[-1].inputs, out.identifier)
            if gin is None:
                return None
            src = self.source(gin, path[:-1])
            return ("const", gin) if src is None else src
        if idname in _GROUP_TYPES:
            tree = getattr(node, "node_tree", None)
            gout = _group_output(tree) if tree is not None else None
            sock = _socket_by_id(gout.inputs, out.identifier) if gout is not None else None
            if sock is None:
                return _ZERO
            src = self.source(sock, path + (node,))
            return ("const", sock) if src is None else src
        if idname in {"NodeGroupOutput", "NodeFrame"}:
            return None
        return ("link", self.add(node, path), out.identifier)

    # -- nodes --------------------------------------------------------------------------

    def add(self, node, path):
        key = (tuple(g.as_pointer() for g in path), node.as_pointer())
        idx = self.index.get(key)
        if idx is not None:
            return idx
        idx = len(self.nodes)
        self.index[key] = idx
        name = "/".join([g.name for g in path] + [node.name])
        entry = {"type": node.bl_idname, "name": name}
        self.nodes.append(entry)
        entry["props"] = node_props(node, self.images, self.user)
        entry["inputs"] = [self.input(s, path) for s in node.inputs]
        outs = []
        for s in node.outputs:
            o = {"id": s.identifier, "type": s.type}
            if not s.enabled:
                o["enabled"] = False
            if node.bl_idname in _OUTPUT_VALUE_TYPES and hasattr(s, "default_value"):
                o["value"] = value(s.default_value)
            outs.append(o)
        entry["outputs"] = outs
        return idx

    def input(self, sock, path):
        e = {"id": sock.identifier, "type": sock.type}
        if hasattr(sock, "default_value"):
            e["value"] = value(sock.default_value)
        if not sock.enabled:
            e["enabled"] = False
        src = self.source(sock, path)
        if src is None:
            pass
        elif src[0] == "link":
            e["link"] = [src[1], src[2]]
        elif src is _ZERO:
            if "value" in e:
                e["value"] = _zero_like(e["value"])
        else:
            c = src[1]
            if not hasattr(c, "default_value"):
                pass  # a shader socket: nothing flows
            elif c.type == sock.type and "value" in e:
                e["value"] = value(c.default_value)
            else:
                e["link"] = list(self.constant(c))
        return e

    def constant(self, sock):
        """A constant node holding an unlinked socket's value (of the socket's type)."""
        v = value(sock.default_value)
        name = "constant: %s" % sock.name
        if sock.type == 'RGBA':
            entry = {"type": "ShaderNodeRGB", "name": name, "props": {}, "inputs": [],
                     "outputs": [{"id": "Color", "type": "RGBA", "value": v}]}
            out = "Color"
        elif sock.type == 'VECTOR':
            entry = {"type": "ShaderNodeCombineXYZ", "name": name, "props": {},
                     "inputs": [{"id": k, "type": "VALUE", "value": x}
                                for k, x in zip("XYZ", v)],
                     "outputs": [{"id": "Vector", "type": "VECTOR"}]}
            out = "Vector"
        else:
            f = float(v) if isinstance(v, (int, float)) else 0.0
            entry = {"type": "ShaderNodeValue", "name": name, "props": {}, "inputs": [],
                     "outputs": [{"id": "Value", "type": "VALUE", "value": f}]}
            out = "Value"
        self.nodes.append(entry)
        return len(self.nodes) - 1, out


def flatten(tree, images, user):
    """The graph of a material / world / light node tree (see the module doc); None when the
    tree has no output node for Cycles."""
    if tree is None:
        return None
    out = tree.get_output_node('CYCLES')
    if out is None:
        return None
    f = _Flattener(images, user)
    f.add(out, ())
    for n in tree.nodes:
        if n.bl_idname == "ShaderNodeOutputAOV" and not n.mute:
            f.add(n, ())
    return {"output": 0, "nodes": f.nodes}


def diffuse_graph(color):
    """What Cycles 3.4 renders for a material without nodes (blender/shader.cpp,
    sync_materials): a Diffuse BSDF of the material's viewport colour into the output."""
    rgb = [finite(c) for c in color[:3]] + [1.0]
    return {"output": 0, "nodes": [
        {"type": "ShaderNodeOutputMaterial", "name": "Material Output",
         "props": {"target": "ALL"},
         "inputs": [{"id": "Surface", "type": "SHADER", "link": [1, "BSDF"]},
                    {"id": "Volume", "type": "SHADER"},
                    {"id": "Displacement", "type": "VECTOR", "value": [0.0, 0.0, 0.0]}],
         "outputs": []},
        {"type": "ShaderNodeBsdfDiffuse", "name": "Diffuse BSDF", "props": {},
         "inputs": [{"id": "Color", "type": "RGBA", "value": rgb},
                    {"id": "Roughness", "type": "VALUE", "value": 0.0},
                    {"id": "Normal", "type": "VECTOR", "value": [0.0, 0.0, 0.0]}],
         "outputs": [{"id": "BSDF", "type": "SHADER"}]}]}


def volume_graph():
    """What Cycles 3.4 renders for a Volume object without a material (its default volume
    shader): a Principled Volume, its defaults reading the density grid, into Volume."""
    return {"output": 0, "nodes": [
        {"type": "ShaderNodeOutputMaterial", "name": "Material Output",
         "props": {"target": "ALL"},
         "inputs": [{"id": "Surface", "type": "SHADER"},
                    {"id": "Volume", "type": "SHADER", "link": [1, "Volume"]},
                    {"id": "Displacement", "type": "VECTOR", "value": [0.0, 0.0, 0.0]}],
         "outputs": []},
        {"type": "ShaderNodeVolumePrincipled", "name": "Principled Volume", "props": {},
         "inputs": [{"id": "Color", "type": "RGBA", "value": [0.5, 0.5, 0.5, 1.0]},
                    {"id": "Color Attribute", "type": "STRING", "value": ""},
                    {"id": "Density", "type": "VALUE", "value": 1.0},
                    {"id": "Density Attribute", "type": "STRING", "value": "density"},
                    {"id": "Anisotropy", "type": "VALUE", "value": 0.0},
                    {"id": "Absorption Color", "type": "RGBA", "value": [0.0, 0.0, 0.0, 1.0]},
                    {"id": "Emission Strength", "type": "VALUE", "value": 0.0},
                    {"id": "Emission Color", "type": "RGBA", "value": [1.0, 1.0, 1.0, 1.0]},
                    {"id": "Blackbody Intensity", "type": "VALUE", "value": 0.0},
                    {"id": "Blackbody Tint", "type": "RGBA", "value": [1.0, 1.0, 1.0, 1.0]},
                    {"id": "Temperature", "type": "VALUE", "value": 1000.0},
                    {"id": "Temperature Attribute", "type": "STRING", "value": "temperature"}],
         "outputs": [{"id": "Volume", "type": "SHADER"}]}]}
