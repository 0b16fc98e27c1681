"""The texture families of the node scenes (make_node_scenes.py): procedural noises, Voronoi,
patterns, Sky, Image and Environment textures."""

import math
import os

import bpy

from node_graph import C, Family


DIMS = ["1D", "2D", "3D", "4D"]


def tex_inputs(g, u, n, span=2.0, w=True, tilt=True):
    """Links a texture node's Vector (a slice of 3D space `span` wide, tilted unless `tilt` is
    False: a rotation's sines and cosines may round differently in the last bit, which White
    Noise, a hash of the bits, turns into another value) and W."""
    v = g.mapping(u, loc=(-0.37 * span, 0.21 - 0.5 * span, 0.43),
                  rot=(0.45, -0.3, 0.25) if tilt else (0, 0, 0), scale=(span, span, span))
    g.set(n, "Vector", v)
    if w and "W" in [s.identifier for s in n.inputs]:
        g.set(n, "W", g.lin(u, 1.1 * span, -0.6 * span, 0.35))


def tex_case(name, type_, props, ins, output, span=2.0, tilt=True):
    def fn(g, u):
        n = g.node(type_, props, ins)
        tex_inputs(g, u, n, span, tilt=tilt)
        if isinstance(output, tuple):  # unavailable outputs as 0
            return g.combine(*[g.out(n, o) if g.out(n, o).enabled else 0.0 for o in output])
        return g.out(n, output)
    return C(name, fn)


def family_textures_noise():
    cases = []
    for dim in DIMS:
        for tag, ins in [("default", {}),
                         ("rough", {"Scale": 3.0, "Detail": 6.5, "Roughness": 0.7,
                                    "Distortion": 1.3})]:
            for out in ["Fac", "Color"]:
                cases.append(tex_case("noise_%s_%s_%s" % (dim, tag, out.lower()),
                                      "ShaderNodeTexNoise", {"noise_dimensions": dim}, ins, out))
    for dim in DIMS:
        for out in ["Value", "Color"]:
            cases.append(tex_case("white_noise_%s_%s" % (dim, out.lower()),
                                  "ShaderNodeTexWhiteNoise", {"noise_dimensions": dim}, {}, out,
                                  span=20.0, tilt=False))
    settings = {"default": {}, "b": {"Scale": 3.0, "Detail": 5.5, "Dimension": 1.2,
                                     "Lacunarity": 2.3, "Offset": 0.8, "Gain": 1.6}}
    for mtype in ["FBM", "MULTIFRACTAL", "RIDGED_MULTIFRACTAL", "HYBRID_MULTIFRACTAL",
                  "HETERO_TERRAIN"]:
        for dim in DIMS:
            for tag, ins in settings.items():
                if tag == "b" and dim in ("1D", "2D"):
                    continue
                cases.append(tex_case("musgrave_%s_%s_%s" % (mtype.lower(), dim, tag),
                                      "ShaderNodeTexMusgrave",
                                      {"musgrave_dimensions": dim, "musgrave_type": mtype}, ins,
                                      "Fac"))
    return Family("textures_noise", 8, 16, cases,
                  "Noise (1D-4D; Fac, Color; default and detailed/distorted), White Noise "
                  "(1D-4D; Value, Color), Musgrave (5 types x 1D-4D, two settings)")


def family_textures_voronoi():
    cases = []
    for dim in DIMS:
        metrics = ["EUCLIDEAN"] if dim == "1D" else ["EUCLIDEAN", "MANHATTAN", "CHEBYCHEV",
                                                     "MINKOWSKI"]
        for metric in metrics:
            for feature in ["F1", "F2", "SMOOTH_F1"]:
                props = {"voronoi_dimensions": dim, "feature": feature, "distance": metric}
                ins = {"Scale": 3.0, "Smoothness": 0.6, "Exponent": 1.5, "Randomness": 0.85}
                base = "voronoi_%s_%s_%s" % (dim, feature.lower(), metric.lower())
                cases.append(tex_case(base + "_dist_w_radius", "ShaderNodeTexVoronoi", props,
                                      ins, ("Distance", "W", "Radius")))
                cases.append(tex_case(base + "_color", "ShaderNodeTexVoronoi", props, ins,
                                      "Color"))
                if dim != "1D" and metric == "EUCLIDEAN":  # (the others' cells: Color)
                    cases.append(tex_case(base + "_position", "ShaderNodeTexVoronoi", props,
                                          ins, "Position"))
        for feature in ["DISTANCE_TO_EDGE", "N_SPHERE_RADIUS"]:
            props = {"voronoi_dimensions": dim, "feature": feature}
            out = "Distance" if feature == "DISTANCE_TO_EDGE" else "Radius"
            cases.append(tex_case("voronoi_%s_%s" % (dim, feature.lower()),
                                  "ShaderNodeTexVoronoi", props,
                                  {"Scale": 3.0, "Randomness": 0.85}, out))
    # default randomness and scale, and randomness 0 (a regular grid)
    for rnd in [1.0, 0.0]:
        cases.append(tex_case("voronoi_3D_f1_euclidean_rand%g_color" % rnd,
                              "ShaderNodeTexVoronoi", {"voronoi_dimensions": "3D"},
                              {"Randomness": rnd}, "Color"))
    return Family("textures_voronoi", 8, 16, cases,
                  "Voronoi: 1D-4D x F1/F2/Smooth F1 x the four metrics (Distance+W+Radius, "
                  "Color; Position with Euclidean), Distance to Edge and N-Sphere Radius in 1D-4D, "
                  "randomness 1 and 0")


def family_textures_pattern():
    cases = []
    shapes = [("BANDS", d, "X") for d in ["X", "Y", "Z", "DIAGONAL"]] + [
        ("RINGS", "X", d) for d in ["X", "Y", "Z", "SPHERICAL"]]
    for k, (wtype, bands, rings) in enumerate(shapes):
        for j, profile in enumerate(["SIN", "SAW", "TRI"]):
            ins = ({"Scale": 2.0, "Distortion": 0.0, "Detail": 2.0}
                   if (k + j) % 2 == 0 else
                   {"Scale": 1.5, "Distortion": 3.5, "Detail": 4.5, "Detail Scale": 1.5,
                    "Detail Roughness": 0.7, "Phase Offset": 1.25})
            d = bands if wtype == "BANDS" else rings
            cases.append(tex_case("wave_%s_%s_%s" % (wtype.lower(), d.lower(), profile.lower()),
                                  "ShaderNodeTexWave",
                                  {"wave_type": wtype, "bands_direction": bands,
                                   "rings_direction": rings, "wave_profile": profile},
                                  ins, "Fac" if j != 1 else "Color"))
    for depth in [0, 1, 2, 3, 5, 10]:
        cases.append(tex_case("magic_depth%d" % depth, "ShaderNodeTexMagic",
                              {"turbulence_depth": depth}, {"Scale": 1.5, "Distortion": 1.7},
                              "Color"))
    cases.append(tex_case("magic_fac", "ShaderNodeTexMagic", {"turbulence_depth": 2}, {},
                          "Fac"))
    for gtype in ["LINEAR", "QUADRATIC", "EASING", "DIAGONAL", "SPHERICAL", "QUADRATIC_SPHERE",
                  "RADIAL"]:
        cases.append(tex_case("gradient_%s" % gtype.lower(), "ShaderNodeTexGradient",
                              {"gradient_type": gtype}, {}, "Fac"))
    cases.append(tex_case("gradient_color", "ShaderNodeTexGradient", {"gradient_type": "RADIAL"},
                          {}, "Color"))
    c1, c2 = (0.9, 0.35, 0.1, 1.0), (0.05, 0.4, 0.75, 1.0)
    for scale in [5.0, 1.7]:
        for out in ["Color", "Fac"]:
            cases.append(tex_case("checker_s%g_%s" % (scale, out.lower()),
                                  "ShaderNodeTexChecker", {},
                                  {"Scale": scale, "Color1": c1, "Color2": c2}, out))
    bricks = [  # offset, offset freq, squash, squash freq, scale, mortar, smooth, bias, w, h
        (0.5, 2, 1.0, 2, 5.0, 0.02, 0.1, 0.0, 0.5, 0.25),
        (0.3, 3, 1.6, 2, 3.0, 0.05, 0.6, 0.2, 0.7, 0.3),
        (0.7, 1, 0.5, 3, 2.0, 0.1, 0.0, -0.3, 0.4, 0.2),
        (0.25, 2, 1.0, 1, 4.0, 0.08, 1.0, 0.5, 0.9, 0.45)]
    for k, b in enumerate(bricks):
        props = {"offset": b[0], "offset_frequency": b[1], "squash": b[2],
                 "squash_frequency": b[3]}
        ins = dict(zip(["Scale", "Mortar Size", "Mortar Smooth", "Bias", "Brick Width",
                        "Row Height"], b[4:]),
                   Color1=c1, Color2=c2, Mortar=(0.2, 0.25, 0.3, 1.0))
        for out in ["Color", "Fac"]:
            cases.append(tex_case("brick_%d_%s" % (k, out.lower()), "ShaderNodeTexBrick", props,
                                  ins, out))
    return Family("textures_pattern", 8, 12, cases,
                  "Wave (bands X/Y/Z/diagonal, rings X/Y/Z/spherical x sine/saw/triangle), "
                  "Magic (depths 0-10), Gradient (7 types), Checker, Brick (4 settings; Color, "
                  "Fac)")


def sky_dir(g, u, z):
    """normalize((2x - 1, 2y - 1, z)): directions around the zenith down to the horizon."""
    v = g.vm("MULTIPLY_ADD", u, (2.0, 2.0, 0.0), (-1.0, -1.0, z))
    return g.vm("NORMALIZE", v)


def family_textures_sky():
    cases = []

    def sky(name, props, z=0.35):
        def fn(g, u):
            n = g.node("ShaderNodeTexSky", props)
            g.set(n, "Vector", sky_dir(g, u, z))
            return g.out(n, "Color")
        cases.append(C(name, fn))

    sky("preetham", {"sky_type": "PREETHAM", "turbidity": 2.5})
    sky("preetham_low_sun", {"sky_type": "PREETHAM", "turbidity": 6.0,
                             "sun_direction": (0.3, 0.8, 0.2)}, z=0.15)
    sky("hosek", {"sky_type": "HOSEK_WILKIE", "turbidity": 3.0, "ground_albedo": 0.3})
    sky("hosek_low_sun", {"sky_type": "HOSEK_WILKIE", "turbidity": 8.0,
                          "sun_direction": (-0.5, 0.6, 0.15)}, z=0.1)
    sky("nishita", {"sky_type": "NISHITA", "sun_disc": False})
    sky("nishita_sunset", {"sky_type": "NISHITA", "sun_disc": False,
                           "sun_elevation": math.radians(3.0), "sun_rotation": 1.2,
                           "altitude": 1200.0, "air_density": 1.4, "dust_density": 3.0,
                           "ozone_density": 0.5}, z=0.05)
    sky("nishita_below", {"sky_type": "NISHITA", "sun_disc": False}, z=-0.2)
    sky("nishita_disc", {"sky_type": "NISHITA", "sun_disc": True, "sun_size": math.radians(8),
                         "sun_elevation": math.radians(40), "sun_rotation": 0.6}, z=1.2)
    return Family("textures_sky", 16, 4, cases,
                  "Sky: Preetham, Hosek-Wilkie, Nishita (sun disc off/on, sunset and altitude, "
                  "below the horizon), directions normalize((2x-1, 2y-1, z))")


def make_images(folder):
    """A small sRGB 8-bit PNG with alpha and a small Non-Color float OpenEXR, written into
    `folder` and loaded from there (Blender regenerates a generated image, pixels set by a
    script are not what a render reads)."""
    os.makedirs(folder, exist_ok=True)
    px = []
    for j in range(8):
        for i in range(8):
            px += [((i * 37 + j * 11) % 8) / 7.0, ((i * 5 + j * 29) % 8) / 7.0,
                   ((i + j) % 2) * 0.6 + 0.2, 1.0 if (i + j) % 3 else 0.5]
    png = save_image("bytes8", 8, px, os.path.join(folder, "bytes8.png"), False)
    png.colorspace_settings.name = "sRGB"
    px = []
    for j in range(4):
        for i in range(4):
            px += [i / 4.0 + 0.125, j / 4.0 + 0.25, ((i * 3 + j) % 4) * 0.5, 1.0]
    exr = save_image("float4", 4, px, os.path.join(folder, "float4.exr"), True)
    exr.colorspace_settings.name = "Non-Color"
    return png, exr


def save_image(name, size, pixels, path, is_float):
    im = bpy.data.images.new(name + "_gen", size, size, alpha=True, float_buffer=is_float)
    im.pixels = pixels
    im.filepath_raw = path
    im.file_format = "OPEN_EXR" if is_float else "PNG"
    im.save()
    bpy.data.images.remove(im)
    loaded = bpy.data.images.load(path)
    loaded.name = name
    return loaded


def family_textures_image():
    cases = []
    images = {}

    def image(name, which, interp, ext, out="Color", span=2.2):
        def fn(g, u):
            n = g.node("ShaderNodeTexImage", {"interpolation": interp, "extension": ext})
            n.image = images[which]
            g.set(n, "Vector", g.mapping(u, loc=(-0.6, -0.55, 0), scale=(span, span * 0.93, 1)))
            return g.out(n, out)
        cases.append(C(name, fn))

    for which in ["bytes8", "float4"]:
        for interp in ["Linear", "Closest"]:
            for ext in ["REPEAT", "EXTEND", "CLIP"]:
                image("%s_%s_%s" % (which, interp.lower(), ext.lower()), which, interp, ext)
    image("bytes8_linear_alpha", "bytes8", "Linear", "REPEAT", "Alpha")
    image("bytes8_closest_clip_alpha", "bytes8", "Closest", "CLIP", "Alpha")

    def color_and_alpha(interp):
        def fn(g, u):
            n = g.node("ShaderNodeTexImage", {"interpolation": interp, "extension": "REPEAT"})
            n.image = images["bytes8"]
            g.set(n, "Vector", g.mapping(u, loc=(-0.6, -0.55, 0), scale=(2.2, 2.046, 1)))
            # Alpha linked too: Cycles unpremultiplies Color
            return g.vm("MULTIPLY_ADD", g.out(n, "Alpha"), (0.2, 0.2, 0.2), g.out(n, "Color"))
        cases.append(C("bytes8_%s_color_with_alpha_linked" % interp.lower(), fn))
    color_and_alpha("Linear")
    color_and_alpha("Closest")

    def uv_default(g, u):
        n = g.node("ShaderNodeTexImage", {"interpolation": "Closest"})
        n.image = images["bytes8"]
        return g.out(n, "Color")
    cases.append(C("bytes8_closest_default_uv", uv_default, quantized=False))

    def env(name, which, interp):
        def fn(g, u):
            n = g.node("ShaderNodeTexEnvironment", {"interpolation": interp})
            n.image = images[which]
            g.set(n, "Vector", g.mapping(u, loc=(-1, -1, -0.4), scale=(2, 2, 1)))
            return g.out(n, "Color")
        cases.append(C(name, fn))
    env("environment_bytes8_linear", "bytes8", "Linear")
    env("environment_float4_closest", "float4", "Closest")

    def setup_images(case_dir):
        images["bytes8"], images["float4"] = make_images(os.path.join(case_dir, "textures"))
    fam = Family("textures_image", 16, 6, cases,
                 "Image Texture: an 8x8 sRGB byte image with alpha and a 4x4 Non-Color float "
                 "image, Linear/Closest x Repeat/Extend/Clip, Alpha output, Color with Alpha linked "
                 "(unpremultiplied), the default (UV) "
                 "vector; Environment Texture (equirectangular)")
    fam.before = setup_images
    return fam
