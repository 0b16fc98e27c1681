"""Rewrites the MTL file Blender's OBJ exporter wrote into glint's MTL dialect.

The exporter (exporter.py) calls

    rewrite_mtl(mtl_path, depsgraph, out_dir, warn)

right after bpy.ops.wm.obj_export(export_materials=True, export_pbr_extensions=True, ...).
Blender's exporter reads only a Principled BSDF linked straight to the output and skips packed
and never-saved images; here every material block is written again from the material's node
tree as glint reads MTL (formats/obj/MTL.md): Principled BSDF, Emission, Diffuse, Glossy and
Glass BSDFs, Mix/Add shaders of them, image textures on their colour/value inputs, normal and
bump maps. Whatever cannot be carried is named in ONE warning per material (warn(msg)), never
dropped silently. The mapping table is plugin/blender/MATERIALS.md.

Images glint can read as they are (a saved file whose colour space agrees with how glint reads
that map) are referenced by absolute path; any other image (packed, generated, painted and
unsaved, a colour space glint would misread, a colour height map, an emission map with a
strength) is written to out_dir/textures as a float PFM holding the linear values Cycles sees,
which glint reads as they are whatever the map. The user's image datablocks are only read.
"""

import os

from .images import ImageWriter, MissingImages

# ----------------------------------------------------------------------------- pure helpers


def mtl_name(blender_name):
    """The name Blender 3.4's OBJ exporter writes for a material: spaces become underscores
    (measured; other characters, dots included, are kept)."""
    return blender_name.replace(" ", "_")


def parse_mtl(text):
    """Splits an MTL file into (header lines, [(name, block lines)]). Header: the lines before
    the first newmtl (Blender's `# Blender 3.4.1 MTL File` first line, which glint's reader uses
    to recognise Blender's files). Block lines exclude the newmtl line itself."""
    header, blocks = [], []
    for line in text.splitlines():
        s = line.strip()
        if s.split(None, 1)[:1] == ["newmtl"]:
            name = line.lstrip()[len("newmtl"):].strip()
            blocks.append((name, []))
        elif blocks:
            if s:
                blocks[-1][1].append(line.rstrip())
        else:
            header.append(line.rstrip())
    return header, blocks


def fmt_num(x):
    return "%.6f" % x


def fmt_rgb(c):
    return " ".join(fmt_num(v) for v in c[:3])


def srgb_decode(v):
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


class Block:
    """One material's statements, in the order they are set (a statement set twice keeps its
    first place and its last value)."""

    def __init__(self, name):
        self.name = name
        self.statements = {}

    def set(self, key, value):
        self.statements[key] = value

    def drop(self, key):
        self.statements.pop(key, None)

    def get(self, key):
        return self.statements.get(key)

    def lines(self):
        out = ["newmtl " + self.name]
        for k, v in self.statements.items():
            out.append(k + " " + v)
        return out


def map_statement(path, offset=None, scale=None, bm=None):
    """A map's arguments: options first (tinyobjloader reads the file name to the line's end,
    spaces included)."""
    opts = []
    if bm is not None:
        opts.append("-bm " + fmt_num(bm))
    if offset is not None and any(abs(v) > 1e-9 for v in offset):
        opts.append("-o %s %s 0" % (fmt_num(offset[0]), fmt_num(offset[1])))
    if scale is not None and any(abs(v - 1) > 1e-9 for v in scale[:2]):
        opts.append("-s %s %s 1" % (fmt_num(scale[0]), fmt_num(scale[1])))
    return " ".join(opts + [path])


class Issues:
    """What one material cannot carry; reported in one warning."""

    def __init__(self, material):
        self.material = material
        self.items = []

    def add(self, msg):
        if msg not in self.items:
            self.items.append(msg)

    def report(self, warn):
        if self.items:
            warn("material '%s': %s" % (self.material, "; ".join(self.items)))


# ----------------------------------------------------------------------------- node graph


def linked_from(socket):
    """(node, output socket) feeding an input, through reroutes; None if unlinked or muted."""
    if not socket.is_linked:
        return None
    link = socket.links[0]
    if getattr(link, "is_muted", False) or not link.is_valid:
        return None
    node, out = link.from_node, link.from_socket
    while node.type == "REROUTE":
        inp = node.inputs[0]
        if not inp.is_linked:
            return None
        link = inp.links[0]
        node, out = link.from_node, link.from_socket
    return node, out


def default_of(socket):
    v = socket.default_value
    try:
        return tuple(v)[:3]
    except TypeError:
        return float(v)


class Converter:
    """Converts one material into a Block, noting what cannot be carried."""

    def __init__(self, material, block, images, issues):
        self.mat = material
        self.block = block
        self.images = images
        self.issues = issues

    # -- inputs -------------------------------------------------------------------------

    def image_source(self, socket, label):
        """If the socket is fed by an Image Texture (uv mapped, optionally through a Mapping
        node), returns (image, output name, offset, scale); otherwise notes the problem and
        returns None (the socket's own value is used)."""
        src = linked_from(socket)
        if src is None:
            return None
        node, out = src
        if node.type != "TEX_IMAGE":
            self.issues.add("%s is linked to a %s node glint cannot follow (its value %s is "
                            "used)" % (label, node.bl_label, self.describe(socket)))
            return None
        if node.mute:
            self.issues.add("%s: muted Image Texture '%s'" % (label, node.name))
            return None
        if node.image is None:  # Cycles renders the node magenta, as a missing image
            self.issues.add("%s: Image Texture '%s' has no image (magenta, as in Cycles)"
                            % (label, node.name))
        if node.projection != "FLAT":
            self.issues.add("%s: Image Texture projection %s (glint: flat)" %
                            (label, node.projection))
        if node.extension != "REPEAT":
            self.issues.add("%s: Image Texture extension %s (glint: repeat)" %
                            (label, node.extension))
        if node.interpolation not in ("Linear", "Smart"):
            self.issues.add("%s: Image Texture interpolation %s (glint: linear)" %
                            (label, node.interpolation))
        offset, scale = (0.0, 0.0), (1.0, 1.0)
        vsrc = linked_from(node.inputs["Vector"])
        if vsrc is not None:
            vnode, vout = vsrc
            if vnode.type == "MAPPING":
                m = vnode
                ok = m.vector_type == "POINT"
                for name in ("Location", "Rotation", "Scale"):
                    if m.inputs[name].is_linked:
                        ok = False
                rot = m.inputs["Rotation"].default_value
                if any(abs(r) > 1e-6 for r in rot):
                    ok = False
                if ok:
                    loc, sc = m.inputs["Location"].default_value, m.inputs["Scale"].default_value
                    offset, scale = (loc[0], loc[1]), (sc[0], sc[1])
                else:
                    self.issues.add("%s: Mapping node other than Point location/scale (not "
                                    "applied)" % label)
                vsrc = linked_from(m.inputs["Vector"])
                vnode, vout = vsrc if vsrc is not None else (None, None)
            if vnode is not None and not (
                    (vnode.type == "TEX_COORD" and vout.name == "UV") or vnode.type == "UVMAP"):
                self.issues.add("%s: texture coordinates from %s (glint: the UV map)" %
                                (label, vnode.bl_label + (" " + vout.name
                                                          if vnode.type == "TEX_COORD" else "")))
            elif vnode is not None and vnode.type == "UVMAP" and vnode.uv_map:
                self.issues.add("%s: UV Map node '%s' (glint uses the mesh's active UV map)" %
                                (label, vnode.uv_map))
        return node.image, out.name, offset, scale

    def describe(self, socket):
        v = default_of(socket)
        return "(%s)" % ", ".join("%.3g" % x for x in v) if isinstance(v, tuple) else "%.3g" % v

    def value(self, socket, label):
        """A float input that must not be linked (linked: its value and a note)."""
        if socket.is_linked:
            src = linked_from(socket)
            if src is not None:
                self.issues.add("%s is linked to a %s node glint cannot follow (its value %s "
                                "is used)" % (label, src[0].bl_label, self.describe(socket)))
        return default_of(socket)

    def color_or_map(self, socket, label, const_key, map_key, scale=1.0):
        """An RGB input: the constant statement, or the map (the constant left out)."""
        src = self.image_source(socket, label)
        if src is not None:
            image, out, offset, sc = src
            kind = "alpha" if out == "Alpha" else "color"  # Alpha into a colour: gray
            path = self.images.file_for(image, map_key, self.issues, kind, scale)
            if path:
                self.block.drop(const_key)
                self.block.set(map_key, map_statement(self.images.rel(path), offset, sc))
                return True
        c = default_of(socket)
        self.block.set(const_key, fmt_rgb(tuple(x * scale for x in c)))
        return False

    def float_or_map(self, socket, label, const_key, map_key, const_fmt=fmt_num):
        src = self.image_source(socket, label)
        if src is not None:
            image, out, offset, sc = src
            # glint takes the luminance of a colour map (Blender's colour -> float); map_d
            # is the image's alpha channel where the file has one, so it gets a gray file.
            if out == "Alpha":
                kind = "alpha"
            else:
                kind = "gray" if map_key == "map_d" else "color"
            path = self.images.file_for(image, map_key, self.issues, kind)
            if path:
                self.block.drop(const_key)
                self.block.set(map_key, map_statement(self.images.rel(path), offset, sc))
                return True
        self.block.set(const_key, const_fmt(float(default_of(socket))))
        return False

    def normal(self, socket, label):
        """Normal input: Normal Map node (tangent space) or Bump node with an image."""
        src = linked_from(socket)
        if src is None:
            return
        node, _ = src
        if node.type == "NORMAL_MAP":
            if node.space != "TANGENT":
                self.issues.add("%s: Normal Map in %s space (glint: tangent space only)" %
                                (label, node.space.lower()))
                return
            if node.uv_map:
                self.issues.add("%s: Normal Map UV map '%s' (glint uses the active one)" %
                                (label, node.uv_map))
            strength = self.value(node.inputs["Strength"], label + " Normal Map Strength")
            img = self.image_source(node.inputs["Color"], label + " Normal Map Color")
            if img is None:
                if not node.inputs["Color"].is_linked:
                    self.issues.add("%s: Normal Map without an image (ignored)" % label)
                return
            image, out, offset, sc = img
            path = self.images.file_for(image, "map_Bump", self.issues, "color")
            if path:
                self.block.set("map_Bump", map_statement(self.images.rel(path), offset, sc,
                                                         bm=strength))
        elif node.type == "BUMP":
            strength = self.value(node.inputs["Strength"], label + " Bump Strength")
            distance = self.value(node.inputs["Distance"], label + " Bump Distance")
            if node.inputs["Normal"].is_linked:
                self.issues.add("%s: Bump node's own Normal input (not chained)" % label)
            img = self.image_source(node.inputs["Height"], label + " Bump Height")
            if img is None:
                if not node.inputs["Height"].is_linked:
                    self.issues.add("%s: Bump without a height image (ignored)" % label)
                return
            image, out, offset, sc = img
            kind = "alpha" if out == "Alpha" else "gray"
            path = self.images.file_for(image, "map_Bump", self.issues, kind)
            bm = strength * distance * (-1.0 if node.invert else 1.0)
            if path:
                self.block.set("map_Bump", map_statement(self.images.rel(path), offset, sc,
                                                         bm=bm))
        else:
            self.issues.add("%s is linked to a %s node (no normal perturbation)" %
                            (label, node.bl_label))

    def note_if(self, cond, what):
        if cond:
            self.issues.add(what)

    # -- shaders ------------------------------------------------------------------------

    def principled(self, n):
        i = n.inputs
        b = self.block
        self.color_or_map(i["Base Color"], "Base Color", "Kd", "map_Kd")
        self.float_or_map(i["Specular"], "Specular", "Ks", "map_Ks",
                          const_fmt=lambda s: fmt_rgb((s, s, s)))
        emission_strength = float(self.value(i["Emission Strength"], "Emission Strength"))
        self.color_or_map(i["Emission"], "Emission", "Ke", "map_Ke", scale=emission_strength)
        b.set("Ni", fmt_num(self.value(i["IOR"], "IOR")))
        self.float_or_map(i["Alpha"], "Alpha", "d", "map_d")
        b.set("illum", "2")
        self.float_or_map(i["Roughness"], "Roughness", "Pr", "map_Pr")
        self.float_or_map(i["Metallic"], "Metallic", "Pm", "map_Pm")
        # Written (glint stores them and, seeing them, uses Principled's Burley diffuse);
        # not shaded, so non-zero values are noted below.
        sheen = self.value(i["Sheen"], "Sheen")
        clearcoat = self.value(i["Clearcoat"], "Clearcoat")
        aniso = self.value(i["Anisotropic"], "Anisotropic")
        b.set("Ps", fmt_num(sheen))
        b.set("Pc", fmt_num(clearcoat))
        b.set("Pcr", fmt_num(self.value(i["Clearcoat Roughness"], "Clearcoat Roughness")))
        b.set("aniso", fmt_num(aniso))
        b.set("anisor", fmt_num(self.value(i["Anisotropic Rotation"], "Anisotropic Rotation")))
        t = float(self.value(i["Transmission"], "Transmission"))
        b.set("Tf", fmt_rgb((t, t, t)))
        self.normal(i["Normal"], "Normal")
        self.note_if(sheen > 0, "Sheen %.3g (not shaded)" % sheen)
        self.note_if(clearcoat > 0, "Clearcoat %.3g (not shaded)" % clearcoat)
        self.note_if(aniso > 0, "Anisotropic %.3g (glint: isotropic)" % aniso)
        sub = self.value(i["Subsurface"], "Subsurface")
        self.note_if(sub > 0, "Subsurface %.3g (glint: no subsurface scattering)" % sub)
        st = self.value(i["Specular Tint"], "Specular Tint")
        self.note_if(st > 0, "Specular Tint %.3g (glint: untinted)" % st)
        tr = self.value(i["Transmission Roughness"], "Transmission Roughness")
        self.note_if(t > 0 and tr > 0,
                     "Transmission Roughness %.3g (glint refracts with Roughness)" % tr)
        self.note_if(i["Clearcoat Normal"].is_linked and clearcoat > 0, "Clearcoat Normal")
        self.note_if(i["Tangent"].is_linked and aniso > 0, "Tangent")
        self.note_if(n.distribution != "GGX",
                     "distribution %s (glint: GGX)" % n.distribution)

    def lambert(self, color_socket, label="Color", emission=None):
        """No PBR statements: glint's Lambert diffuse, no highlight (Ks 0, no Ns)."""
        self.color_or_map(color_socket, label, "Kd", "map_Kd")
        b = self.block
        b.set("Ks", "0.000000 0.000000 0.000000")
        b.set("Ke", fmt_rgb(emission or (0, 0, 0)))
        b.set("Ni", "1.450000")
        b.set("d", "1.000000")
        b.set("illum", "1")

    def diffuse(self, n):
        self.lambert(n.inputs["Color"])
        r = self.value(n.inputs["Roughness"], "Roughness")
        self.note_if(r > 0, "Diffuse Roughness %.3g (Oren-Nayar; glint: Lambert)" % r)
        self.normal(n.inputs["Normal"], "Normal")

    def glossy(self, n, label="Glossy BSDF"):
        b = self.block
        self.color_or_map(n.inputs["Color"], "Color", "Kd", "map_Kd")
        b.set("Ks", "0.500000 0.500000 0.500000")
        b.set("Ke", "0.000000 0.000000 0.000000")
        b.set("Ni", "1.450000")
        b.set("d", "1.000000")
        b.set("illum", "3")
        self.float_or_map(n.inputs["Roughness"], "Roughness", "Pr", "map_Pr")
        b.set("Pm", "1.000000")
        self.normal(n.inputs["Normal"], "Normal")
        d = n.distribution
        self.note_if(d not in ("GGX", "SHARP"), "%s distribution %s (glint: GGX)" % (label, d))

    def glass(self, n, label="Glass BSDF"):
        b = self.block
        self.color_or_map(n.inputs["Color"], "Color", "Kd", "map_Kd")
        c = default_of(n.inputs["Color"])
        self.note_if(not n.inputs["Color"].is_linked and min(c) < 0.999,
                     "%s Color tints its reflection in Cycles (glint: refraction only)" % label)
        b.set("Ks", "0.500000 0.500000 0.500000")
        b.set("Ke", "0.000000 0.000000 0.000000")
        b.set("Ni", fmt_num(self.value(n.inputs["IOR"], "IOR")))
        b.set("d", "1.000000")
        b.set("illum", "2")
        self.float_or_map(n.inputs["Roughness"], "Roughness", "Pr", "map_Pr")
        b.set("Pm", "0.000000")
        b.set("Tf", "1.000000 1.000000 1.000000")
        self.normal(n.inputs["Normal"], "Normal")
        d = n.distribution
        r = default_of(n.inputs["Roughness"])
        self.note_if(d not in ("GGX", "SHARP") and (r > 0 or n.inputs["Roughness"].is_linked),
                     "%s distribution %s (glint: GGX)" % (label, d))

    def emission_only(self, color, strength, color_socket=None):
        b = self.block
        b.set("Kd", "0.000000 0.000000 0.000000")
        b.set("Ks", "0.000000 0.000000 0.000000")
        if color_socket is not None:
            self.color_or_map(color_socket, "Emission Color", "Ke", "map_Ke", scale=strength)
        else:
            b.set("Ke", fmt_rgb(tuple(x * strength for x in color)))
        b.set("Ni", "1.450000")
        b.set("d", "1.000000")
        b.set("illum", "1")

    # -- graph ----------------------------------------------------------------------------

    def flatten(self, socket, weight, out):
        """Shader nodes reaching `socket` with their mix weights: [(weight, node)]."""
        src = linked_from(socket)
        if src is None:
            return
        node, _ = src
        if node.mute:
            self.issues.add("muted %s node" % node.bl_label)
            return
        if node.type == "MIX_SHADER":
            fac = node.inputs["Fac"]
            f = float(default_of(fac))
            if fac.is_linked:
                self.issues.add("Mix Shader Fac is linked (taken as %.3g)" % f)
            f = min(max(f, 0.0), 1.0)
            self.flatten(node.inputs[1], weight * (1 - f), out)
            self.flatten(node.inputs[2], weight * f, out)
        elif node.type == "ADD_SHADER":
            self.flatten(node.inputs[0], weight, out)
            self.flatten(node.inputs[1], weight, out)
        elif weight > 0:
            out.append((weight, node))

    def convert(self, output_node):
        b = self.block
        surface = output_node.inputs["Surface"]
        parts = []
        self.flatten(surface, 1.0, parts)
        if output_node.inputs["Volume"].is_linked:
            self.issues.add("Volume output (glint: surfaces only)")
        if output_node.inputs["Displacement"].is_linked:
            self.issues.add("Displacement output (not applied)")
        emit = [(w, n) for w, n in parts if n.type == "EMISSION"]
        transparent = [(w, n) for w, n in parts if n.type == "BSDF_TRANSPARENT"]
        rest = [(w, n) for w, n in parts if n.type not in ("EMISSION", "BSDF_TRANSPARENT")]
        if not parts:
            if not surface.is_linked:
                self.issues.add("nothing linked to the Surface output (black)")
            self.emission_only((0, 0, 0), 0.0)
            return
        if not rest:
            if emit:
                w, n = max(emit, key=lambda p: p[0])
                strength = float(self.value(n.inputs["Strength"], "Emission Strength")) * w
                self.emission_only(None, strength, n.inputs["Color"])
                if len(emit) > 1:
                    self.issues.add("%d Emission shaders mixed (the strongest kept)" %
                                    len(emit))
            else:
                self.emission_only((0, 0, 0), 0.0)
                b.set("d", "0.000000")
        else:
            rest.sort(key=lambda p: -p[0])
            w, n = rest[0]
            if len(rest) > 1:
                self.issues.add("Mix/Add of %s: only the %s (weight %.3g) is converted" % (
                    ", ".join(x.bl_label for _, x in rest), n.bl_label, w))
            elif w < 0.999 and not transparent:
                self.issues.add("%s at weight %.3g (converted at full weight)" %
                                (n.bl_label, w))
            self.shader(n)
            if emit:
                we, e = max(emit, key=lambda p: p[0])
                strength = float(self.value(e.inputs["Strength"], "Emission Strength")) * we
                if b.get("map_Ke") is None and not e.inputs["Color"].is_linked:
                    c = default_of(e.inputs["Color"])
                    own = [float(x) for x in (b.get("Ke") or "0 0 0").split()]
                    b.set("Ke", fmt_rgb(tuple(k + x * strength for k, x in zip(own, c))))
                else:
                    self.issues.add("Emission shader added to a shader with its own emission")
                if len(emit) > 1:
                    self.issues.add("%d Emission shaders mixed (the strongest kept)" %
                                    len(emit))
        if transparent:
            wt = sum(w for w, _ in transparent)
            for _, t in transparent:
                c = default_of(t.inputs["Color"])
                if min(c) < 0.999 or t.inputs["Color"].is_linked:
                    self.issues.add("Transparent BSDF Color %s (glint: untinted coverage)" %
                                    self.describe(t.inputs["Color"]))
            alpha = max(0.0, 1.0 - wt)
            if b.get("map_d") is not None:
                self.issues.add("Transparent BSDF mixed with an alpha map (map kept)")
            else:
                d = b.get("d")
                b.set("d", fmt_num(alpha * (float(d) if d else 1.0)))

    def shader(self, n):
        t = n.type
        if t == "BSDF_PRINCIPLED":
            self.principled(n)
        elif t == "BSDF_DIFFUSE":
            self.diffuse(n)
        elif t == "BSDF_GLOSSY":
            self.glossy(n)
        elif t == "BSDF_ANISOTROPIC":
            self.glossy(n, "Anisotropic BSDF")
            a = self.value(n.inputs["Anisotropy"], "Anisotropy")
            self.note_if(a != 0, "Anisotropic BSDF Anisotropy %.3g (glint: isotropic)" % a)
        elif t == "BSDF_GLASS":
            self.glass(n)
        elif t == "BSDF_REFRACTION":
            self.glass(n, "Refraction BSDF")
            self.issues.add("Refraction BSDF converted as glass (reflection added)")
        elif t in ("BSDF_TRANSLUCENT", "SUBSURFACE_SCATTERING", "BSDF_TOON", "BSDF_VELVET",
                   "BSDF_SHEEN"):
            self.issues.add("%s converted as a Lambert diffuse of its color" % n.bl_label)
            self.lambert(n.inputs["Color"])
            if "Normal" in n.inputs:
                self.normal(n.inputs["Normal"], "Normal")
        elif t == "HOLDOUT":
            self.issues.add("Holdout rendered black")
            self.emission_only((0, 0, 0), 0.0)
        else:
            self.issues.add("%s shader not supported (rendered as a gray diffuse)" %
                            n.bl_label)
            self.no_nodes((0.8, 0.8, 0.8))

    def no_nodes(self, color=None):
        """A material without nodes: Cycles renders a Diffuse BSDF of its viewport color."""
        self.block.set("Kd", fmt_rgb(color or tuple(self.mat.diffuse_color)[:3]))
        b = self.block
        b.set("Ks", "0.000000 0.000000 0.000000")
        b.set("Ke", "0.000000 0.000000 0.000000")
        b.set("Ni", "1.450000")
        b.set("d", "1.000000")
        b.set("illum", "1")


def convert_material(material, name, images, issues):
    """The glint MTL block for one (evaluated) Blender material."""
    block = Block(name)
    conv = Converter(material, block, images, issues)
    nt = material.node_tree if material.use_nodes else None
    if nt is None:
        conv.no_nodes()
        return block
    out = None
    try:
        out = nt.get_output_node("CYCLES")
    except (AttributeError, TypeError):
        pass
    if out is None:
        outs = [n for n in nt.nodes if n.type == "OUTPUT_MATERIAL"]
        out = next((n for n in outs if n.is_active_output), outs[0] if outs else None)
    if out is None:
        issues.add("no Material Output node (black)")
        conv.emission_only((0, 0, 0), 0.0)
        return block
    conv.convert(out)
    return block


# ----------------------------------------------------------------------------- entry point


# The object types whose surfaces Blender's OBJ exporter writes (each as a mesh): only these
# have materials in the MTL file. Other objects are never asked for theirs: reading
# material_slots of an evaluated Empty (a depsgraph instance) crashes Blender 3.4.
SURFACE_TYPES = frozenset({"MESH", "CURVE", "SURFACE", "FONT", "META"})


def scene_materials(depsgraph):
    """Evaluated materials of the depsgraph's objects, by the name the OBJ exporter writes."""
    found = {}
    collisions = set()
    for inst in depsgraph.object_instances:
        ob = inst.object
        if ob.type not in SURFACE_TYPES:
            continue
        mats = [slot.material for slot in ob.material_slots]
        # Materials a geometry node tree set live on the evaluated data.
        mats += list(getattr(ob.data, "materials", None) or [])
        for m in mats:
            if m is None:
                continue
            key = mtl_name(m.name)
            prev = found.get(key)
            if prev is not None and prev.original != m.original:
                collisions.add(key)
                continue
            found[key] = m
    return found, collisions


def rewrite_mtl(mtl_path, depsgraph, out_dir, warn, missing=None):
    """Rewrites mtl_path in place (see the module doc). Images without pixels are collected in
    `missing` (a MissingImages) when given, for the caller to report with the world's; else
    they are reported here."""
    if not os.path.isfile(mtl_path):
        return
    with open(mtl_path, encoding="utf-8", errors="surrogateescape") as f:
        header, blocks = parse_mtl(f.read())
    materials, collisions = scene_materials(depsgraph)
    images = ImageWriter(out_dir, os.path.dirname(os.path.abspath(mtl_path)), missing)
    out = list(header) or ["# Blender MTL File"]
    out.append("# material blocks rewritten by glint_blender (plugin/blender/MATERIALS.md)")
    written = set()
    for name, lines in blocks:
        if name in written:
            continue  # a second material exported under the same name (warned once below)
        written.add(name)
        out.append("")
        m = materials.get(name)
        if m is None:
            warn("material '%s' of the MTL file not found in the scene: kept as Blender "
                 "wrote it" % name)
            out.append("newmtl " + name)
            out.extend(lines)
            continue
        issues = Issues(m.name)
        if name in collisions:
            issues.add("several materials are exported as '%s' (Blender writes spaces as "
                       "underscores); all use this one" % name)
        try:
            block = convert_material(m, name, images, issues)
        except Exception as e:  # a node layout this code did not expect: keep Blender's
            issues.add("could not be converted (%s: %s); Blender's export kept" %
                       (type(e).__name__, e))
            out.append("newmtl " + name)
            out.extend(lines)
            issues.report(warn)
            continue
        out.extend(block.lines())
        issues.report(warn)
    with open(mtl_path, "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write("\n".join(out) + "\n")
    if missing is None:
        images.missing.report(warn)
