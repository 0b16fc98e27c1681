"""Reference values for tests/unit/shader_math_test.cpp, rendered by Cycles itself.

    blender -b --factory-startup --python tests/shader/make_math_refs.py -- \
        --out tests/unit/shader_math_refs.inc [--only GROUP[,GROUP...]] [--fold]

Every test case is one face of a grid of unit squares that fills an orthographic camera's view
pixel for pixel. A face's material holds the node under test, with an Emission shader
(strength 1) fed by the node's output; the node's inputs come from Attribute nodes reading
face-domain attributes, so that no input is a constant and Cycles runs its SVM kernel for the
node rather than its compile-time constant folding. The image is rendered with 1 sample, a
pixel filter 0.01 px wide, the 'Standard' view (look None, exposure 0, gamma 1) and written
as a 32-bit float OpenEXR, whose pixels are read back.

The output is C++ (tests/unit/shader_math_refs.inc, included by shader_math_test.cpp): one
struct and one table per group of cases, and the XYZ -> RGB matrix solved from the Wavelength
node. Floats print with 9 significant digits, so that float32 inputs and outputs round-trip.
The script also checks that the ramps and curves Blender bakes are within 2e-7 of the straight
lines the test rebuilds them from.

--fold gives the inputs as socket values instead, so that Cycles folds the nodes at compile
time: used once to check that folding agrees with the kernel (it does, up to Blender clamping
color and factor socket values to their UI ranges); not what the test holds.
"""

import argparse
import os
import sys
import tempfile

import bpy

# --------------------------------------------------------------------------------------------
# Case registry
# --------------------------------------------------------------------------------------------


class Spec:
    """A node under test: its type, properties, inputs fed by attributes, and output(s)."""

    def __init__(self, node, props=None, ins=None, outs=("Result",), setup=None):
        self.node = node
        self.props = props or {}
        self.ins = ins or {}  # socket identifier -> input name of the case
        self.outs = outs  # one output identifier, or three float outputs combined as XYZ
        self.setup = setup  # callable(node) for ramps and curves

    def key(self):
        return (self.node, tuple(sorted(self.props.items())), tuple(sorted(self.ins.items())),
                tuple(self.outs), self.setup.__name__ if self.setup else "")


GROUPS = {}  # group -> list of (row, spec, inputs dict, expect)


def add(group, row, spec, inputs, expect="v"):
    """row: the C++ fields before the expected value; expect: 'f' (the red channel of a float
    output) or 'v' (the RGB triple)."""
    GROUPS.setdefault(group, []).append((row, spec, inputs, expect))


# --------------------------------------------------------------------------------------------
# Scene
# --------------------------------------------------------------------------------------------


def attr_type(value):
    return "FLOAT" if isinstance(value, (int, float)) else "FLOAT_VECTOR"


def build_material(spec, input_types, constants=None):
    mat = bpy.data.materials.new("m")
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    emit = nt.nodes.new("ShaderNodeEmission")
    emit.inputs["Strength"].default_value = 1.0
    nt.links.new(emit.outputs["Emission"], out.inputs["Surface"])
    node = nt.nodes.new(spec.node)
    for k, v in spec.props.items():
        setattr(node, k, v)
    if spec.setup:
        spec.setup(node)
    for ident, name in spec.ins.items():
        sock = next(s for s in node.inputs if s.identifier == ident)
        if constants is not None:
            # The socket's own value: Cycles then folds the node at compile time.
            v = constants[name]
            if sock.type == "RGBA":
                v = tuple(v) + (1.0,)
            sock.default_value = v
            continue
        attr = nt.nodes.new("ShaderNodeAttribute")
        attr.attribute_type = "GEOMETRY"
        attr.attribute_name = "in_" + name
        src = attr.outputs["Fac"] if input_types[name] == "FLOAT" else attr.outputs["Vector"]
        nt.links.new(src, sock)
    if len(spec.outs) == 1:
        res = next(s for s in node.outputs if s.identifier == spec.outs[0])
    else:
        comb = nt.nodes.new("ShaderNodeCombineXYZ")
        for i, ident in enumerate(spec.outs):
            nt.links.new(next(s for s in node.outputs if s.identifier == ident), comb.inputs[i])
        res = comb.outputs["Vector"]
    nt.links.new(res, emit.inputs["Color"])
    return mat


def render_cases(cases, workdir, fold=False):
    """cases: list of (spec, inputs). Returns one RGB triple per case."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    n = len(cases)
    # Blender renders at least 4 x 4 pixels; faces past the last case stay empty.
    w = max(min(n, 64), 4)
    h = max((n + w - 1) // w, 4)

    input_types = {}
    for _, inputs in cases:
        for k, v in inputs.items():
            t = attr_type(v)
            assert input_types.setdefault(k, t) == t, k

    mesh = bpy.data.meshes.new("grid")
    verts, faces = [], []
    for k in range(n):
        i, j = k % w, k // w
        x0, y0 = i - w / 2.0, j - h / 2.0
        b = len(verts)
        verts += [(x0, y0, 0.0), (x0 + 1, y0, 0.0), (x0 + 1, y0 + 1, 0.0), (x0, y0 + 1, 0.0)]
        faces.append((b, b + 1, b + 2, b + 3))
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    for name, t in input_types.items():
        a = mesh.attributes.new("in_" + name, t, "FACE")
        for k, (_, inputs) in enumerate(cases):
            v = inputs.get(name, 0.0 if t == "FLOAT" else (0.0, 0.0, 0.0))
            if t == "FLOAT":
                a.data[k].value = v
            else:
                a.data[k].vector = v

    materials = {}
    for k, (spec, inputs) in enumerate(cases):
        if fold:  # one material per case, its inputs constants
            mesh.polygons[k].material_index = len(mesh.materials)
            mesh.materials.append(build_material(spec, input_types, inputs))
            continue
        key = spec.key()
        if key not in materials:
            materials[key] = len(mesh.materials)
            mesh.materials.append(build_material(spec, input_types))
        mesh.polygons[k].material_index = materials[key]

    obj = bpy.data.objects.new("grid", mesh)
    scene.collection.objects.link(obj)
    cam_data = bpy.data.cameras.new("cam")
    cam_data.type = "ORTHO"
    cam_data.ortho_scale = float(max(w, h))
    cam = bpy.data.objects.new("cam", cam_data)
    cam.location = (0.0, 0.0, 10.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    world = bpy.data.worlds.new("w")
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 1
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.filter_width = 0.01
    scene.cycles.max_bounces = 0
    scene.render.resolution_x = w
    scene.render.resolution_y = h
    scene.render.resolution_percentage = 100
    scene.render.dither_intensity = 0.0
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    path = os.path.join(workdir, "refs.exr")
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)

    img = bpy.data.images.load(path)
    px = list(img.pixels)
    out = []
    for k in range(n):
        i, j = k % w, k // w
        o = (j * w + i) * 4
        out.append((px[o], px[o + 1], px[o + 2]))
    return out


# --------------------------------------------------------------------------------------------
# Formatting
# --------------------------------------------------------------------------------------------


def f(x):
    s = "%.9g" % x
    if "inf" in s or "nan" in s:
        return "std::numeric_limits<float>::quiet_NaN()" if "nan" in s else (
            "-kInf" if s.startswith("-") else "kInf")
    if "e" not in s and "." not in s:
        s += ".0"
    return s + "f"


def fmt(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return f(v)
    if isinstance(v, str):
        return '"%s"' % v
    return "{" + ", ".join(f(c) for c in v) + "}"


# Per group: the struct of its rows (C++ fields, the expected value last) and its array.
TABLES = [
    ("math", "MathRef", "kMathRefs",
     ["const char* op;", "float a, b, c;", "bool clamp;", "float expected;"]),
    ("vector_math", "VectorMathRef", "kVectorMathRefs",
     ["const char* op;", "float3 a, b, c;", "float scale;",
      "float3 expected;  // (v, v, v) for the operations with a Value output"]),
    ("mix_rgb", "MixRgbRef", "kMixRgbRefs",
     ["const char* blend;", "float fac;", "float3 c1, c2;", "bool clamp;", "float3 expected;"]),
    ("mix_color", "MixColorRef", "kMixColorRefs",
     ["const char* blend;", "float fac;", "float3 a, b;", "bool clamp_factor, clamp_result;",
      "float3 expected;"]),
    ("mix_other", "MixOtherRef", "kMixOtherRefs",
     ["const char* kind;  // FLOAT (x components), VECTOR (uniform: fac.x) or NON_UNIFORM",
      "float3 fac, a, b;", "bool clamp_factor;", "float3 expected;"]),
    ("hsv", "HsvRef", "kHsvRefs",
     ["float hue, saturation, value, fac;", "float3 color, expected;"]),
    ("bright_contrast", "BrightContrastRef", "kBrightContrastRefs",
     ["float3 color;", "float bright, contrast;", "float3 expected;"]),
    ("gamma", "GammaRef", "kGammaRefs", ["float3 color;", "float gamma;", "float3 expected;"]),
    ("invert", "InvertRef", "kInvertRefs", ["float fac;", "float3 color, expected;"]),
    ("rgb_to_bw", "RgbToBwRef", "kRgbToBwRefs", ["float3 color;", "float expected;"]),
    ("sepcomb", "SepCombRef", "kSepCombRefs",
     ["const char* mode;  // a ColorMode, or LEGACY_HSV (Separate/Combine HSV)",
      "const char* direction;  // SEPARATE or COMBINE", "float3 in, expected;"]),
    ("map_range", "MapRangeRef", "kMapRangeRefs",
     ["const char* type;", "const char* data_type;  // FLOAT uses the x components",
      "float3 value, from_min, from_max, to_min, to_max, steps;", "bool clamp;",
      "float3 expected;"]),
    ("clamp", "ClampRef", "kClampRefs", ["const char* type;", "float value, min, max;",
                                         "float expected;"]),
    ("blackbody", "SpectrumRef", "kBlackbodyRefs",
     ["float x;  // kelvin, or nanometres", "float3 expected;"]),
    ("wavelength", "SpectrumRef", "kWavelengthRefs", None),
    ("mapping", "MappingRef", "kMappingRefs",
     ["const char* type;", "float3 vector, location, rotation, scale, expected;"]),
    ("vector_rotate", "VectorRotateRef", "kVectorRotateRefs",
     ["const char* type;", "float3 vector, center, axis;", "float angle;", "float3 rotation;",
      "bool invert;", "float3 expected;"]),
    ("ramps", "RampRef", "kRampRefs",
     ["const char* name;  // a ramp or curve of make_math_refs.py", "const char* output;",
      "float fac;", "float3 in, expected;"]),
]

HEADER = """\
// Generated by tests/shader/make_math_refs.py (Blender %s, Cycles): do not edit. Remake with
//     blender -b --factory-startup --python tests/shader/make_math_refs.py
//         -- --out tests/unit/shader_math_refs.inc
// Cycles' outputs for the shader node cases of shader_math_test.cpp, included inside its
// namespace (float3 from render/shader/float3.h). Each case was one pixel of an Emission
// shader fed by the node, the node's inputs read from face attributes (so Cycles ran its SVM
// kernel, not its constant folding). Floats have 9 significant digits: exact float32.
"""


def wrap_row(items, width=100):
    """One initializer {a, b, ...}, broken after commas to fit width (continuations under the
    first item, as clang-format aligns them)."""
    lines, cur = [], "    {"
    for i, item in enumerate(items):
        piece = item + ("}," if i == len(items) - 1 else ",")
        if len(cur) + len(piece) + (0 if cur.endswith("{") else 1) > width and not \
                cur.endswith("{"):
            lines.append(cur)
            cur = "     " + piece
        else:
            cur += ("" if cur.endswith("{") else " ") + piece
    lines.append(cur)
    return lines


def emit(group, rows, results):
    lines = []
    for (row, _, _, expect), rgb in zip(rows, results):
        exp = fmt(rgb[0]) if expect == "f" else fmt(rgb)
        lines += wrap_row([fmt(v) for v in row] + [exp])
    return lines


def write_tables(groups, results_by_group):
    out = [HEADER % bpy.app.version_string]
    declared = set()
    for group, struct, array, fields in TABLES:
        if group not in groups:
            continue
        if struct not in declared:
            declared.add(struct)
            out.append("struct %s {" % struct)
            out += ["    " + fld for fld in fields]
            out.append("};\n")
        rows = GROUPS[group]
        out.append("constexpr %s %s[] = {" % (struct, array))
        out += emit(group, rows, results_by_group[group])
        out.append("};\n")
    if "xyz_matrix" in groups:
        out.append(solve_xyz_matrix(GROUPS["xyz_matrix"], results_by_group["xyz_matrix"]))
    return "\n".join(out)


# --------------------------------------------------------------------------------------------
# Cases
# --------------------------------------------------------------------------------------------

MATH_OPS = ["ADD", "SUBTRACT", "MULTIPLY", "DIVIDE", "MULTIPLY_ADD", "POWER", "LOGARITHM",
            "SQRT", "INVERSE_SQRT", "ABSOLUTE", "EXPONENT", "MINIMUM", "MAXIMUM", "LESS_THAN",
            "GREATER_THAN", "SIGN", "COMPARE", "SMOOTH_MIN", "SMOOTH_MAX", "ROUND", "FLOOR",
            "CEIL", "TRUNC", "FRACT", "MODULO", "WRAP", "SNAP", "PINGPONG", "SINE", "COSINE",
            "TANGENT", "ARCSINE", "ARCCOSINE", "ARCTANGENT", "ARCTAN2", "SINH", "COSH", "TANH",
            "RADIANS", "DEGREES"]
MATH_ARGS = [(0.5, 0.25, 0.1), (-1.7, 3.2, 0.5), (2.5, -0.75, 2.0), (3.0, 0.0, -1.0),
             (-0.3, -2.2, 0.3), (7.25, 2.5, 1.5), (1.0, 1.05, 0.1), (0.4, 0.6, 0.5),
             (-2.0, 3.0, 0.0)]

VMATH_OPS = ["ADD", "SUBTRACT", "MULTIPLY", "DIVIDE", "MULTIPLY_ADD", "CROSS_PRODUCT", "PROJECT",
             "REFLECT", "REFRACT", "FACEFORWARD", "DOT_PRODUCT", "DISTANCE", "LENGTH", "SCALE",
             "NORMALIZE", "ABSOLUTE", "MINIMUM", "MAXIMUM", "FLOOR", "CEIL", "FRACTION",
             "MODULO", "WRAP", "SNAP", "SINE", "COSINE", "TANGENT"]
VMATH_VALUE_OPS = {"DOT_PRODUCT", "DISTANCE", "LENGTH"}
VMATH_ARGS = [((0.5, -1.25, 2.0), (1.5, 0.25, -0.5), (0.3, 0.6, -0.9), 1.5),
              ((-3.3, 0.7, 1.1), (0.0, 2.0, -0.8), (1.0, -2.0, 0.5), -0.7),
              ((0.5, -1.25, 2.0), (0.0, 2.0, -0.8), (1.0, -2.0, 0.5), 0.7),
              ((0.2, 0.1, -0.9), (0.0, 0.0, 1.0), (-0.4, 0.9, 0.0), 1.45)]

BLENDS = ["MIX", "DARKEN", "MULTIPLY", "BURN", "LIGHTEN", "SCREEN", "DODGE", "ADD", "OVERLAY",
          "SOFT_LIGHT", "LINEAR_LIGHT", "DIFFERENCE", "SUBTRACT", "DIVIDE", "HUE", "SATURATION",
          "COLOR", "VALUE"]
C1A, C2A = (0.2, 0.6, 0.9), (0.7, 0.1, 0.5)
C1B, C2B = (0.8, 0.35, 0.05), (0.3, 0.0, 0.95)
C1C, C2C = (1.4, -0.2, 0.5), (0.5, 0.5, 2.0)
GRAY = (0.4, 0.4, 0.4)
MIXRGB_ARGS = [(0.3, C1A, C2A, False), (1.0, C1B, C2B, False), (1.7, C1A, C2B, False),
               (-0.4, C1B, C2A, False), (0.6, C1C, C2C, True), (0.6, C1C, C2C, False),
               (0.8, C1A, GRAY, False)]
MIX_ARGS = [(0.3, C1A, C2A, True, False), (1.7, C1B, C2B, False, False),
            (-0.4, C1A, C2B, False, True), (0.6, C1C, C2C, True, True),
            (0.6, C1C, C2C, False, False), (0.8, GRAY, C1B, True, False)]


def define_cases():
    for op in MATH_OPS:
        spec = Spec("ShaderNodeMath", {"operation": op, "use_clamp": False},
                    {"Value": "fa", "Value_001": "fb", "Value_002": "fc"}, ("Value",))
        cspec = Spec("ShaderNodeMath", {"operation": op, "use_clamp": True},
                     {"Value": "fa", "Value_001": "fb", "Value_002": "fc"}, ("Value",))
        for i, (a, b, c) in enumerate(MATH_ARGS):
            add("math", [op, a, b, c, False], spec, {"fa": a, "fb": b, "fc": c}, "f")
            if i in (1, 2):
                add("math", [op, a, b, c, True], cspec, {"fa": a, "fb": b, "fc": c}, "f")

    for op in VMATH_OPS:
        out = "Value" if op in VMATH_VALUE_OPS else "Vector"
        spec = Spec("ShaderNodeVectorMath", {"operation": op},
                    {"Vector": "va", "Vector_001": "vb", "Vector_002": "vc", "Scale": "fs"},
                    (out,))
        for a, b, c, s in VMATH_ARGS:
            add("vector_math", [op, a, b, c, s], spec, {"va": a, "vb": b, "vc": c, "fs": s})

    for blend in BLENDS:
        for clamp in (False, True):
            spec = Spec("ShaderNodeMixRGB", {"blend_type": blend, "use_clamp": clamp},
                        {"Fac": "fa", "Color1": "va", "Color2": "vb"}, ("Color",))
            for fac, c1, c2, cl in MIXRGB_ARGS:
                if cl == clamp:
                    add("mix_rgb", [blend, fac, c1, c2, clamp], spec,
                        {"fa": fac, "va": c1, "vb": c2})
        for fac, a, b, cf, cr in MIX_ARGS:
            spec = Spec("ShaderNodeMix", {"data_type": "RGBA", "blend_type": blend,
                                          "clamp_factor": cf, "clamp_result": cr},
                        {"Factor_Float": "fa", "A_Color": "va", "B_Color": "vb"},
                        ("Result_Color",))
            add("mix_color", [blend, fac, a, b, cf, cr], spec, {"fa": fac, "va": a, "vb": b})
    for cf in (False, True):
        for fac in (0.3, 1.7, -0.4):
            spec = Spec("ShaderNodeMix", {"data_type": "FLOAT", "clamp_factor": cf},
                        {"Factor_Float": "fa", "A_Float": "fb", "B_Float": "fc"},
                        ("Result_Float",))
            add("mix_other", ["FLOAT", (fac, fac, fac), (0.25, 0, 0), (-1.5, 0, 0), cf], spec,
                {"fa": fac, "fb": 0.25, "fc": -1.5})
            spec = Spec("ShaderNodeMix", {"data_type": "VECTOR", "clamp_factor": cf},
                        {"Factor_Float": "fa", "A_Vector": "va", "B_Vector": "vb"},
                        ("Result_Vector",))
            add("mix_other", ["VECTOR", (fac, fac, fac), C1C, C2B, cf], spec,
                {"fa": fac, "va": C1C, "vb": C2B})
        spec = Spec("ShaderNodeMix", {"data_type": "VECTOR", "factor_mode": "NON_UNIFORM",
                                      "clamp_factor": cf},
                    {"Factor_Vector": "vc", "A_Vector": "va", "B_Vector": "vb"},
                    ("Result_Vector",))
        add("mix_other", ["NON_UNIFORM", (0.3, 1.7, -0.4), C1C, C2B, cf], spec,
            {"vc": (0.3, 1.7, -0.4), "va": C1C, "vb": C2B})

    spec = Spec("ShaderNodeHueSaturation", {},
                {"Hue": "fa", "Saturation": "fb", "Value": "fc", "Fac": "fd", "Color": "va"},
                ("Color",))
    for h, s, v, fac, col in [(0.5, 1.0, 1.0, 1.0, (0.8, 0.3, 0.1)),
                              (0.25, 1.5, 0.8, 1.0, (0.2, 0.6, 0.9)),
                              (0.9, 0.5, 1.2, 0.6, (0.7, 0.1, 0.5)),
                              (0.1, 2.0, 1.0, 1.0, (0.3, 0.3, 0.3)),
                              (-0.8, 1.0, 1.0, 1.0, (0.9, 0.5, 0.1)),
                              (0.5, 1.0, 1.0, 1.5, (1.2, 0.5, -0.1)),
                              (0.62, 3.0, 0.7, 0.8, (0.1, 0.8, 0.3))]:
        add("hsv", [h, s, v, fac, col], spec,
            {"fa": h, "fb": s, "fc": v, "fd": fac, "va": col})

    spec = Spec("ShaderNodeBrightContrast", {},
                {"Color": "va", "Bright": "fa", "Contrast": "fb"}, ("Color",))
    for col, br, co in [((0.2, 0.6, 0.9), 0.1, 0.5), ((0.8, 0.3, 0.05), -0.3, -0.4),
                        ((1.5, 0.0, 0.5), 0.0, 2.0)]:
        add("bright_contrast", [col, br, co], spec, {"va": col, "fa": br, "fb": co})
    spec = Spec("ShaderNodeGamma", {}, {"Color": "va", "Gamma": "fa"}, ("Color",))
    for col, g in [((0.2, 0.6, 0.9), 2.2), ((0.5, -0.3, 0.0), 0.45), ((0.7, 0.1, 0.5), 0.0),
                   ((1.5, 2.0, 0.25), -1.0)]:
        add("gamma", [col, g], spec, {"va": col, "fa": g})
    spec = Spec("ShaderNodeInvert", {}, {"Fac": "fa", "Color": "va"}, ("Color",))
    for fac, col in [(1.0, (0.2, 0.6, 0.9)), (0.3, (0.8, -0.5, 1.5)), (-0.5, (0.1, 0.2, 0.3))]:
        add("invert", [fac, col], spec, {"fa": fac, "va": col})
    spec = Spec("ShaderNodeRGBToBW", {}, {"Color": "va"}, ("Val",))
    for col in [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (0.2, 0.6, 0.9),
                (1.5, -0.3, 0.7)]:
        add("rgb_to_bw", [col], spec, {"va": col}, "f")

    sep_in = [(0.2, 0.6, 0.9), (0.8, 0.3, 0.05), (0.5, 0.5, 0.5), (0.9, 0.1, 0.4),
              (1.3, 0.2, 0.6), (0.0, 0.0, 0.0), (0.1, 0.8, 0.3), (0.4, 0.9, 0.9),
              (-0.2, 0.5, 0.3)]
    comb_in = [(0.3, 0.7, 0.4), (0.95, 0.5, 0.8), (0.0, 1.0, 0.5), (0.55, 0.2, 1.3),
               (1.0, 0.6, 0.6), (0.5, 0.0, 0.7), (1.4, 0.5, 0.5), (0.75, 0.9, 0.3),
               (0.1, 1.0, 0.2)]
    for mode in ("RGB", "HSV", "HSL"):
        spec = Spec("ShaderNodeSeparateColor", {"mode": mode}, {"Color": "va"},
                    ("Red", "Green", "Blue"))
        for col in sep_in:
            add("sepcomb", [mode, "SEPARATE", col], spec, {"va": col})
        spec = Spec("ShaderNodeCombineColor", {"mode": mode},
                    {"Red": "fa", "Green": "fb", "Blue": "fc"}, ("Color",))
        for col in comb_in:
            add("sepcomb", [mode, "COMBINE", col], spec,
                {"fa": col[0], "fb": col[1], "fc": col[2]})
    spec = Spec("ShaderNodeSeparateHSV", {}, {"Color": "va"}, ("H", "S", "V"))
    for col in sep_in[:4]:
        add("sepcomb", ["LEGACY_HSV", "SEPARATE", col], spec, {"va": col})
    spec = Spec("ShaderNodeCombineHSV", {}, {"H": "fa", "S": "fb", "V": "fc"}, ("Color",))
    for col in comb_in[:4]:
        add("sepcomb", ["LEGACY_HSV", "COMBINE", col], spec,
            {"fa": col[0], "fb": col[1], "fc": col[2]})

    mr_float = [(0.3, 0.0, 1.0, 0.0, 1.0, 4.0, True), (1.7, 0.0, 1.0, -1.0, 2.0, 4.0, True),
                (1.7, 0.0, 1.0, -1.0, 2.0, 4.0, False), (0.35, 1.0, 0.0, 2.0, -1.0, 3.0, True),
                (0.35, 1.0, 0.0, 2.0, -1.0, 3.0, False),
                (-0.2, 0.2, 0.8, 0.0, 10.0, 5.0, False), (0.5, 0.5, 0.5, 0.2, 1.0, 4.0, True),
                (0.5, 0.5, 0.5, 0.2, 1.0, 4.0, False), (0.45, 0.1, 0.9, 3.0, 5.0, 0.0, True),
                (0.45, 0.1, 0.9, 3.0, 5.0, -2.0, False), (0.62, 0.1, 0.9, 5.0, 3.0, 2.5, True)]
    mr_vec = [((0.3, 1.7, -0.2), (0.0, 0.0, 0.2), (1.0, 1.0, 0.8), (0.0, -1.0, 0.0),
               (1.0, 2.0, 10.0), (4.0, 3.0, 0.0)),
              ((0.5, 0.35, 2.5), (0.5, 1.0, 0.0), (0.5, 0.0, 2.0), (0.2, 2.0, -1.0),
               (1.0, -1.0, 1.0), (2.0, 2.0, -2.0))]
    for typ in ("LINEAR", "STEPPED", "SMOOTHSTEP", "SMOOTHERSTEP"):
        for clamp in (False, True):
            spec = Spec("ShaderNodeMapRange",
                        {"data_type": "FLOAT", "interpolation_type": typ, "clamp": clamp},
                        {"Value": "fa", "From Min": "fb", "From Max": "fc", "To Min": "fd",
                         "To Max": "fe", "Steps": "ff"}, ("Result",))
            for v, a, b, c, d, s, cl in mr_float:
                if cl == clamp:
                    add("map_range", [typ, "FLOAT", (v, 0, 0), (a, 0, 0), (b, 0, 0),
                                      (c, 0, 0), (d, 0, 0), (s, 0, 0), clamp], spec,
                        {"fa": v, "fb": a, "fc": b, "fd": c, "fe": d, "ff": s})
            spec = Spec("ShaderNodeMapRange",
                        {"data_type": "FLOAT_VECTOR", "interpolation_type": typ,
                         "clamp": clamp},
                        {"Vector": "va", "From_Min_FLOAT3": "vb", "From_Max_FLOAT3": "vc",
                         "To_Min_FLOAT3": "vd", "To_Max_FLOAT3": "ve", "Steps_FLOAT3": "vf"},
                        ("Vector",))
            for v, a, b, c, d, s in mr_vec:
                add("map_range", [typ, "FLOAT_VECTOR", v, a, b, c, d, s, clamp], spec,
                    {"va": v, "vb": a, "vc": b, "vd": c, "ve": d, "vf": s})

    for typ in ("MINMAX", "RANGE"):
        spec = Spec("ShaderNodeClamp", {"clamp_type": typ},
                    {"Value": "fa", "Min": "fb", "Max": "fc"}, ("Result",))
        for v, a, b in [(0.5, 0.0, 1.0), (1.5, 0.0, 1.0), (0.5, 1.0, 0.0), (-0.5, 0.8, 0.2),
                        (0.5, 0.8, 0.2), (0.1, 0.8, 0.2)]:
            add("clamp", [typ, v, a, b], spec, {"fa": v, "fb": a, "fc": b}, "f")

    spec = Spec("ShaderNodeBlackbody", {}, {"Temperature": "fa"}, ("Color",))
    for t in [0.0, 500.0, 799.0, 800.0, 900.0, 965.0, 1000.0, 1167.0, 1300.0, 1449.0, 1500.0,
              1902.0, 2500.0, 3315.0, 5000.0, 6365.0, 6500.0, 10000.0, 11999.0, 12000.0,
              20000.0]:
        add("blackbody", [t], spec, {"fa": t})
    spec = Spec("ShaderNodeWavelength", {}, {"Wavelength": "fa"}, ("Color",))
    for wl in [300.0, 379.0, 380.0, 381.5, 400.0, 447.3, 500.0, 555.0, 600.0, 650.0, 700.0,
               750.0, 779.0, 779.9, 780.0, 800.0]:
        add("wavelength", [wl], spec, {"fa": wl})
    # Wavelengths on the CIE table's nodes, from which solve_xyz_matrix() recovers Cycles'
    # XYZ -> scene linear matrix.
    for k in range(81):
        add("xyz_matrix", [380.0 + 5.0 * k], spec, {"fa": 380.0 + 5.0 * k})

    map_in = [((0.3, -1.2, 2.5), (0.5, 1.0, -0.25), (0.3, -0.7, 1.2), (1.5, 0.5, -2.0)),
              ((1.0, 2.0, 3.0), (0.0, 0.0, 0.0), (1.5708, 0.0, 0.0), (0.0, 2.0, 1.0)),
              ((-0.8, 0.4, 0.1), (2.0, -1.0, 0.5), (-2.0, 0.9, 3.0), (1.0, 1.0, 1.0))]
    for typ in ("POINT", "TEXTURE", "VECTOR", "NORMAL"):
        ins = {"Vector": "va", "Rotation": "vc", "Scale": "vd"}
        if typ in ("POINT", "TEXTURE"):
            ins["Location"] = "vb"
        spec = Spec("ShaderNodeMapping", {"vector_type": typ}, ins, ("Vector",))
        for v, loc, rot, sc in map_in:
            add("mapping", [typ, v, loc, rot, sc], spec,
                {"va": v, "vb": loc, "vc": rot, "vd": sc})

    rot_in = [((0.3, -1.2, 2.5), (0.5, 0.2, -0.1), (1.0, 2.0, 0.5), 0.8, (0.3, -0.7, 1.2)),
              ((1.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), 1.1, (1.5, 0.2, -0.4))]
    for typ in ("AXIS_ANGLE", "X_AXIS", "Y_AXIS", "Z_AXIS", "EULER_XYZ"):
        for inv in (False, True):
            ins = {"Vector": "va", "Center": "vb"}
            if typ == "EULER_XYZ":
                ins["Rotation"] = "vd"
            else:
                ins["Angle"] = "fa"
                if typ == "AXIS_ANGLE":
                    ins["Axis"] = "vc"
            spec = Spec("ShaderNodeVectorRotate", {"rotation_type": typ, "invert": inv}, ins,
                        ("Vector",))
            for v, cen, axis, ang, rot in rot_in:
                add("vector_rotate", [typ, v, cen, axis, ang, rot, inv], spec,
                    {"va": v, "vb": cen, "vc": axis, "fa": ang, "vd": rot})

    # Ramps and curves: tables the test rebuilds analytically (see check_tables()).
    ramp_facs = [-0.5, 0.0, 0.1, 0.3333, 0.41, 0.5, 0.7, 0.999, 1.0, 1.5]
    for name, setup in (("RAMP_LINEAR", setup_ramp_linear),
                        ("RAMP_CONSTANT", setup_ramp_constant)):
        for out in ("Color", "Alpha"):
            spec = Spec("ShaderNodeValToRGB", {}, {"Fac": "fa"}, (out,), setup)
            for fac in ramp_facs:
                add("ramps", [name, out, fac, (0.0, 0.0, 0.0)], spec, {"fa": fac})
    spec = Spec("ShaderNodeRGBCurve", {}, {"Fac": "fa", "Color": "va"}, ("Color",),
                setup_rgb_curves)
    for fac, col in [(1.0, (0.2, 0.6, 0.9)), (1.0, (-0.7, 0.0, 1.0)), (1.0, (1.3, 2.5, -0.1)),
                     (0.5, (0.2, 0.6, 0.9)), (1.3, (0.45, -0.2, 1.6))]:
        add("ramps", ["RGB_CURVES", "Color", fac, col], spec, {"fa": fac, "va": col})
    for setup in (setup_vector_curves_extrapolated, setup_vector_curves_horizontal):
        spec = Spec("ShaderNodeVectorCurve", {}, {"Fac": "fa", "Vector": "va"}, ("Vector",),
                    setup)
        name = "VECTOR_CURVES_" + ("EXTRAPOLATED" if "extra" in setup.__name__ else
                                   "HORIZONTAL")
        for fac, v in [(1.0, (0.2, -0.6, 0.9)), (1.0, (-1.7, 1.5, 0.75)),
                       (0.4, (0.3, 2.0, -3.0))]:
            add("ramps", [name, "Vector", fac, v], spec, {"fa": fac, "va": v})
    spec = Spec("ShaderNodeFloatCurve", {}, {"Factor": "fa", "Value": "fb"}, ("Value",),
                setup_float_curve)
    for fac, v in [(1.0, 0.3), (1.0, -1.0), (1.0, 3.0), (0.4, 1.2), (1.0, 2.0), (1.0, -0.5)]:
        add("ramps", ["FLOAT_CURVE", "Value", fac, (v, 0.0, 0.0)], spec, {"fa": fac, "fb": v})


# Cycles' CIE 1931 colour matching table (kernel/tables.h): 380 nm to 780 nm by 5 nm.
CIE_XYZ = [
    (0.0014, 0.0000, 0.0065), (0.0022, 0.0001, 0.0105), (0.0042, 0.0001, 0.0201),
    (0.0076, 0.0002, 0.0362), (0.0143, 0.0004, 0.0679), (0.0232, 0.0006, 0.1102),
    (0.0435, 0.0012, 0.2074), (0.0776, 0.0022, 0.3713), (0.1344, 0.0040, 0.6456),
    (0.2148, 0.0073, 1.0391), (0.2839, 0.0116, 1.3856), (0.3285, 0.0168, 1.6230),
    (0.3483, 0.0230, 1.7471), (0.3481, 0.0298, 1.7826), (0.3362, 0.0380, 1.7721),
    (0.3187, 0.0480, 1.7441), (0.2908, 0.0600, 1.6692), (0.2511, 0.0739, 1.5281),
    (0.1954, 0.0910, 1.2876), (0.1421, 0.1126, 1.0419), (0.0956, 0.1390, 0.8130),
    (0.0580, 0.1693, 0.6162), (0.0320, 0.2080, 0.4652), (0.0147, 0.2586, 0.3533),
    (0.0049, 0.3230, 0.2720), (0.0024, 0.4073, 0.2123), (0.0093, 0.5030, 0.1582),
    (0.0291, 0.6082, 0.1117), (0.0633, 0.7100, 0.0782), (0.1096, 0.7932, 0.0573),
    (0.1655, 0.8620, 0.0422), (0.2257, 0.9149, 0.0298), (0.2904, 0.9540, 0.0203),
    (0.3597, 0.9803, 0.0134), (0.4334, 0.9950, 0.0087), (0.5121, 1.0000, 0.0057),
    (0.5945, 0.9950, 0.0039), (0.6784, 0.9786, 0.0027), (0.7621, 0.9520, 0.0021),
    (0.8425, 0.9154, 0.0018), (0.9163, 0.8700, 0.0017), (0.9786, 0.8163, 0.0014),
    (1.0263, 0.7570, 0.0011), (1.0567, 0.6949, 0.0010), (1.0622, 0.6310, 0.0008),
    (1.0456, 0.5668, 0.0006), (1.0026, 0.5030, 0.0003), (0.9384, 0.4412, 0.0002),
    (0.8544, 0.3810, 0.0002), (0.7514, 0.3210, 0.0001), (0.6424, 0.2650, 0.0000),
    (0.5419, 0.2170, 0.0000), (0.4479, 0.1750, 0.0000), (0.3608, 0.1382, 0.0000),
    (0.2835, 0.1070, 0.0000), (0.2187, 0.0816, 0.0000), (0.1649, 0.0610, 0.0000),
    (0.1212, 0.0446, 0.0000), (0.0874, 0.0320, 0.0000), (0.0636, 0.0232, 0.0000),
    (0.0468, 0.0170, 0.0000), (0.0329, 0.0119, 0.0000), (0.0227, 0.0082, 0.0000),
    (0.0158, 0.0057, 0.0000), (0.0114, 0.0041, 0.0000), (0.0081, 0.0029, 0.0000),
    (0.0058, 0.0021, 0.0000), (0.0041, 0.0015, 0.0000), (0.0029, 0.0010, 0.0000),
    (0.0020, 0.0007, 0.0000), (0.0014, 0.0005, 0.0000), (0.0010, 0.0004, 0.0000),
    (0.0007, 0.0002, 0.0000), (0.0005, 0.0002, 0.0000), (0.0003, 0.0001, 0.0000),
    (0.0002, 0.0001, 0.0000), (0.0002, 0.0001, 0.0000), (0.0001, 0.0000, 0.0000),
    (0.0001, 0.0000, 0.0000), (0.0001, 0.0000, 0.0000), (0.0000, 0.0000, 0.0000),
]


def solve_xyz_matrix(rows, results):
    """Each row of Cycles' XYZ -> RGB matrix by least squares over the node wavelengths where
    that channel of the Wavelength output is not clamped: there out = M_row . xyz / 2.52."""
    import numpy as np
    scale = float(np.float32(1.0) / np.float32(2.52))
    lines = ["// Cycles' XYZ -> scene linear matrix by rows, solved by least squares from its",
             "// Wavelength output at the CIE table's nodes (converter_nodes.h kCyclesXyzToRgb).",
             "constexpr float3 kSolvedXyzToRgb[3] = {"]
    for ch in range(3):
        a, y = [], []
        for (row, _, _, _), rgb in zip(rows, results):
            k = int(round((row[0] - 380.0) / 5.0))
            if k < 80 and rgb[ch] > 1e-3:
                a.append([float(np.float32(c)) for c in CIE_XYZ[k]])
                y.append(rgb[ch] / scale)
        m, *_ = np.linalg.lstsq(np.array(a), np.array(y), rcond=None)
        resid = max(abs(np.array(a) @ m - np.array(y)) / np.array(y))
        lines.append("    {%s},  // %d samples, largest relative residual %.2g" % (
            ", ".join(f(v) for v in m), len(y), resid))
    lines.append("};")
    return "\n".join(lines) + "\n"


def setup_ramp_linear(node):
    r = node.color_ramp
    r.interpolation = "LINEAR"
    r.elements[0].position = 0.0
    r.elements[0].color = (0.1, 0.2, 0.9, 0.5)
    r.elements[1].position = 1.0
    r.elements[1].color = (0.9, 0.6, 0.1, 1.0)


def setup_ramp_constant(node):
    r = node.color_ramp
    r.interpolation = "CONSTANT"
    r.elements[0].position = 0.0
    r.elements[0].color = (0.1, 0.2, 0.3, 1.0)
    r.elements[1].position = 0.41
    r.elements[1].color = (0.5, 0.6, 0.7, 0.8)
    e = r.elements.new(0.69)
    e.color = (0.9, 0.1, 0.2, 0.3)


def set_line(curve, p0, p1):
    curve.points[0].location = p0
    curve.points[1].location = p1


def setup_rgb_curves(node):
    m = node.mapping
    set_line(m.curves[0], (0.0, 0.0), (1.0, 0.5))  # R
    set_line(m.curves[1], (0.0, 1.0), (1.0, 0.0))  # G
    set_line(m.curves[3], (-0.5, 0.1), (1.0, 0.9))  # combined
    m.extend = "EXTRAPOLATED"
    m.update()


def setup_vector_curves(node, extend):
    m = node.mapping
    set_line(m.curves[0], (-1.0, -1.0), (1.0, 0.0))
    set_line(m.curves[2], (-1.0, 0.5), (0.5, -1.0))
    m.extend = extend
    m.update()


def setup_vector_curves_extrapolated(node):
    setup_vector_curves(node, "EXTRAPOLATED")


def setup_vector_curves_horizontal(node):
    setup_vector_curves(node, "HORIZONTAL")


def setup_float_curve(node):
    m = node.mapping
    set_line(m.curves[0], (-0.5, 1.0), (2.0, 0.0))
    m.update()


def check_tables():
    """How far Blender's own curve evaluation is from the straight lines the test assumes."""
    mat = bpy.data.materials.new("t")
    mat.use_nodes = True
    nt = mat.node_tree
    worst = 0.0
    n = nt.nodes.new("ShaderNodeRGBCurve")
    setup_rgb_curves(n)
    m = n.mapping
    for i in range(256):
        t = -0.5 + i / 255.0 * 1.5
        c = m.evaluate(m.curves[3], t)
        want_c = 0.1 + (t + 0.5) / 1.5 * 0.8
        worst = max(worst, abs(c - want_c))
        worst = max(worst, abs(m.evaluate(m.curves[0], c) - 0.5 * c))
        worst = max(worst, abs(m.evaluate(m.curves[1], c) - (1.0 - c)))
        worst = max(worst, abs(m.evaluate(m.curves[2], c) - c))
    n = nt.nodes.new("ShaderNodeVectorCurve")
    for ext in ("EXTRAPOLATED", "HORIZONTAL"):
        setup_vector_curves(n, ext)
        m = n.mapping
        for i in range(256):
            t = -1.0 + i / 255.0 * 2.0
            worst = max(worst, abs(m.evaluate(m.curves[0], t) - (t - 1.0) * 0.5))
            worst = max(worst, abs(m.evaluate(m.curves[1], t) - t))
            z = 0.5 - (t + 1.0) if ext == "EXTRAPOLATED" else max(-1.0, 0.5 - (t + 1.0))
            worst = max(worst, abs(m.evaluate(m.curves[2], t) - z))
    n = nt.nodes.new("ShaderNodeFloatCurve")
    setup_float_curve(n)
    m = n.mapping
    for i in range(256):
        t = -0.5 + i / 255.0 * 2.5
        worst = max(worst, abs(m.evaluate(m.curves[0], t) - (1.0 - (t + 0.5) / 2.5)))
    n = nt.nodes.new("ShaderNodeValToRGB")
    setup_ramp_linear(n)
    for i in range(256):
        t = i / 255.0
        c = n.color_ramp.evaluate(t)
        want = [a + (b - a) * t for a, b in zip((0.1, 0.2, 0.9, 0.5), (0.9, 0.6, 0.1, 1.0))]
        worst = max(worst, max(abs(x - y) for x, y in zip(c, want)))
    n = nt.nodes.new("ShaderNodeValToRGB")
    setup_ramp_constant(n)
    for i in range(256):
        t = i / 255.0
        c = n.color_ramp.evaluate(t)
        want = ((0.1, 0.2, 0.3, 1.0) if t < 0.41 else
                (0.5, 0.6, 0.7, 0.8) if t < 0.69 else (0.9, 0.1, 0.2, 0.3))
        worst = max(worst, max(abs(x - y) for x, y in zip(c, want)))
    sys.stderr.write("largest distance of Blender's tables from the test's: %g\n" % worst)
    bpy.data.materials.remove(mat)


def main(argv):
    ap = argparse.ArgumentParser(prog="make_math_refs.py")
    ap.add_argument("--out")
    ap.add_argument("--only")
    # Inputs as constants instead of attributes, to compare Cycles' constant folding with its
    # kernel (not what the test's tables hold).
    ap.add_argument("--fold", action="store_true")
    args = ap.parse_args(argv)
    only = set(args.only.split(",")) if args.only else None
    define_cases()
    check_tables()
    groups = [g for g in GROUPS if only is None or g in only]
    cases, spans = [], {}
    for g in groups:
        spans[g] = (len(cases), len(cases) + len(GROUPS[g]))
        cases += [(spec, inputs) for _, spec, inputs, _ in GROUPS[g]]
    with tempfile.TemporaryDirectory() as tmp:
        results = render_cases(cases, tmp, args.fold)
    text = write_tables(groups, {g: results[a:b] for g, (a, b) in spans.items()})
    if args.out:
        with open(args.out, "w") as fh:
            fh.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
