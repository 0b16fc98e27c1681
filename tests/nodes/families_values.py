"""The colour, converter and vector families of the node scenes (make_node_scenes.py)."""

from node_graph import C, Family


def family_color():
    cases = []
    blends = ["MIX", "DARKEN", "MULTIPLY", "BURN", "LIGHTEN", "SCREEN", "DODGE", "ADD",
              "OVERLAY", "SOFT_LIGHT", "LINEAR_LIGHT", "DIFFERENCE", "SUBTRACT", "DIVIDE", "HUE",
              "SATURATION", "COLOR", "VALUE"]

    def mix_color(name, blend, clamp_result=False, clamp_factor=True, fac_scale=1.0):
        def fn(g, u):
            n = g.node("ShaderNodeMix", {"data_type": "RGBA", "blend_type": blend,
                                         "clamp_result": clamp_result,
                                         "clamp_factor": clamp_factor},
                       {"Factor_Float": g.lin(u, 0.3 * fac_scale, 0.6 * fac_scale, 0.05),
                        "A_Color": g.color_a(u), "B_Color": g.color_b(u)})
            return g.out(n, "Result_Color")
        cases.append(C(name, fn))

    for b in blends:
        mix_color("mix_%s" % b.lower(), b)
    mix_color("mix_add_clamp_result", "ADD", clamp_result=True)
    mix_color("mix_mix_factor_unclamped", "MIX", clamp_factor=False, fac_scale=2.5)
    mix_color("mix_linear_light_factor_unclamped", "LINEAR_LIGHT", clamp_factor=False,
              fac_scale=2.5)

    def mix_float(g, u):
        x, y = g.xy(u)
        n = g.node("ShaderNodeMix", {"data_type": "FLOAT"},
                   {"Factor_Float": g.lin(u, 0.4, 0.9, -0.1), "A_Float": x,
                    "B_Float": g.math("MULTIPLY", y, 0.7)})
        return g.out(n, "Result_Float")
    cases.append(C("mix_float", mix_float))

    def mix_vector(uniform):
        def fn(g, u):
            props = {"data_type": "VECTOR", "factor_mode": "UNIFORM" if uniform else
                     "NON_UNIFORM"}
            ins = {"A_Vector": g.color_a(u), "B_Vector": g.color_b(u)}
            if uniform:
                ins["Factor_Float"] = g.lin(u, 0.9, 0.2)
            else:
                ins["Factor_Vector"] = g.mapping(u, rot=(0.2, 0.1, 0.9), scale=(1.2, 0.8, 1))
            return g.out(g.node("ShaderNodeMix", props, ins), "Result_Vector")
        cases.append(C("mix_vector_%s" % ("uniform" if uniform else "non_uniform"), fn))
    mix_vector(True)
    mix_vector(False)

    def mix_rgb(name, blend, clamp=False):
        def fn(g, u):
            n = g.node("ShaderNodeMixRGB", {"blend_type": blend, "use_clamp": clamp},
                       {"Fac": g.lin(u, 0.6, 0.3, 0.05), "Color1": g.color_a(u),
                        "Color2": g.color_b(u)})
            return g.out(n, "Color")
        cases.append(C(name, fn))
    for b in blends:
        mix_rgb("mixrgb_%s" % b.lower(), b)
    mix_rgb("mixrgb_add_clamp", "ADD", clamp=True)
    mix_rgb("mixrgb_divide_clamp", "DIVIDE", clamp=True)

    for k, (h, s, v, f) in enumerate([(0.5, 1.0, 1.0, 1.0), (0.3, 1.4, 0.8, 1.0),
                                      (0.85, 0.4, 1.3, 0.7)]):
        def fn(g, u, h=h, s=s, v=v, f=f):
            n = g.node("ShaderNodeHueSaturation", ins={
                "Hue": h, "Saturation": s, "Value": v, "Fac": f, "Color": g.color_a(u)})
            return g.out(n, "Color")
        cases.append(C("hue_sat_%d" % k, fn))

    def hue_sat_linked(g, u):
        x, y = g.xy(u)
        n = g.node("ShaderNodeHueSaturation", ins={"Hue": x, "Saturation": g.math("ADD", y, 0.5),
                                                   "Color": g.color_b(u)})
        return g.out(n, "Color")
    cases.append(C("hue_sat_linked", hue_sat_linked))

    for k, (br, co) in enumerate([(0.2, 0.0), (-0.1, 0.6), (0.05, -0.4)]):
        def fn(g, u, br=br, co=co):
            n = g.node("ShaderNodeBrightContrast", ins={"Color": g.color_a(u), "Bright": br,
                                                        "Contrast": co})
            return g.out(n, "Color")
        cases.append(C("bright_contrast_%d" % k, fn))

    for k, gm in enumerate([2.2, 0.45]):
        def fn(g, u, gm=gm):
            n = g.node("ShaderNodeGamma", ins={"Color": g.color_b(u), "Gamma": gm})
            return g.out(n, "Color")
        cases.append(C("gamma_%g" % gm, fn))

    for fac in [1.0, 0.35]:
        def fn(g, u, fac=fac):
            n = g.node("ShaderNodeInvert", ins={"Fac": fac, "Color": g.color_a(u)})
            return g.out(n, "Color")
        cases.append(C("invert_%g" % fac, fn))

    def ramp(name, interp, color_mode="RGB", hue="NEAR", out="Color"):
        def fn(g, u):
            n = g.node("ShaderNodeValToRGB", ins={"Fac": g.lin(u, 0.95, 0.25, -0.1)})
            r = n.color_ramp
            r.color_mode = color_mode
            if color_mode != "RGB":
                r.hue_interpolation = hue
            r.interpolation = interp
            r.elements[0].position = 0.1
            r.elements[0].color = (0.9, 0.1, 0.05, 1.0)
            r.elements[1].position = 0.85
            r.elements[1].color = (0.1, 0.3, 0.95, 0.2)
            e = r.elements.new(0.4)
            e.color = (0.2, 0.9, 0.3, 0.7)
            e = r.elements.new(0.6)
            e.color = (0.95, 0.85, 0.1, 1.0)
            return g.out(n, out)
        cases.append(C(name, fn))
    for interp in ["LINEAR", "EASE", "B_SPLINE", "CARDINAL", "CONSTANT"]:
        ramp("color_ramp_%s" % interp.lower(), interp)
    ramp("color_ramp_hsv_far", "LINEAR", "HSV", "FAR")
    ramp("color_ramp_hsl_cw", "LINEAR", "HSL", "CW")
    ramp("color_ramp_alpha", "LINEAR", out="Alpha")

    def rgb_curves(name, extend, fac=1.0):
        def fn(g, u):
            n = g.node("ShaderNodeRGBCurve", ins={"Fac": fac,
                                                  "Color": g.vm("MULTIPLY_ADD", g.color_a(u),
                                                                (1.3, 1.3, 1.3),
                                                                (-0.15, -0.15, -0.15))})
            m = n.mapping
            m.extend = extend
            m.curves[3].points.new(0.3, 0.45)
            m.curves[0].points.new(0.5, 0.2)
            m.curves[1].points[1].location = (0.8, 0.9)
            m.curves[2].points[0].location = (0.1, 0.3)
            m.update()
            return g.out(n, "Color")
        cases.append(C(name, fn))
    rgb_curves("rgb_curves", "HORIZONTAL")
    rgb_curves("rgb_curves_extrapolated", "EXTRAPOLATED")
    rgb_curves("rgb_curves_fac", "HORIZONTAL", fac=0.6)
    return Family("color", 8, 12, cases,
                  "Mix (colour: 18 blend modes, clamp result, unclamped factor; float; vector "
                  "uniform / non-uniform), MixRGB (18 blend modes, clamp), Hue/Saturation/Value, "
                  "Bright/Contrast, Gamma, Invert, ColorRamp (5 interpolations, HSV/HSL, alpha), "
                  "RGB Curves (extend horizontal / extrapolated, factor)")


MATH_OPS = ['ADD', 'SUBTRACT', 'MULTIPLY', 'DIVIDE', 'MULTIPLY_ADD', 'POWER', 'LOGARITHM', 'SQRT',
            'INVERSE_SQRT', 'ABSOLUTE', 'EXPONENT', 'MINIMUM', 'MAXIMUM', 'LESS_THAN',
            'GREATER_THAN', 'SIGN', 'COMPARE', 'SMOOTH_MIN', 'SMOOTH_MAX', 'ROUND', 'FLOOR',
            'CEIL', 'TRUNC', 'FRACT', 'MODULO', 'WRAP', 'SNAP', 'PINGPONG', 'SINE', 'COSINE',
            'TANGENT', 'ARCSINE', 'ARCCOSINE', 'ARCTANGENT', 'ARCTAN2', 'SINH', 'COSH', 'TANH',
            'RADIANS', 'DEGREES']
VMATH_OPS = ['ADD', 'SUBTRACT', 'MULTIPLY', 'DIVIDE', 'MULTIPLY_ADD', 'CROSS_PRODUCT', 'PROJECT',
             'REFLECT', 'REFRACT', 'FACEFORWARD', 'DOT_PRODUCT', 'DISTANCE', 'LENGTH', 'SCALE',
             'NORMALIZE', 'ABSOLUTE', 'MINIMUM', 'MAXIMUM', 'FLOOR', 'CEIL', 'FRACTION',
             'MODULO', 'WRAP', 'SNAP', 'SINE', 'COSINE', 'TANGENT']


def family_converters():
    cases = []
    for op in MATH_OPS:
        for clamp in ([False, True] if op in ("ADD", "SINE") else [False]):
            def fn(g, u, op=op, clamp=clamp):
                # a: -2 .. 2 along x, b: -1.5 .. 1.5 along y, c: 0.6 (0.6 .. 1 for the
                # operations that read it)
                a, b, c = g.abc(u, (4.0, 3.0, 1.0), (-2.0, -1.5, 0.6))
                if op in ("MULTIPLY_ADD", "COMPARE", "SMOOTH_MIN", "SMOOTH_MAX", "WRAP"):
                    c = g.math("MULTIPLY_ADD", a, 0.1, 0.8)
                return g.math(op, a, b, c, clamp=clamp)
            cases.append(C("math_%s%s" % (op.lower(), "_clamp" if clamp else ""), fn))

    def vec_a(g, u):
        return g.mapping(u, loc=(-2.0, -1.5, 0.4), rot=(0.3, 0.2, 0.5), scale=(4.0, 3.0, 1.0))

    def vec_b(g, u):
        return g.mapping(u, loc=(1.2, -0.7, -0.9), rot=(-0.4, 0.6, 1.9), scale=(-2.5, 2.0, 1.0))

    for op in VMATH_OPS:
        def fn(g, u, op=op):
            return g.vm(op, vec_a(g, u), vec_b(g, u), (0.3, -0.6, 0.9),
                        g.lin(u, 0.6, 0.9, 0.5) if op == "REFRACT" else 1.7)
        cases.append(C("vector_math_%s" % op.lower(), fn))

    for dtype in ["FLOAT", "FLOAT_VECTOR"]:
        for interp in ["LINEAR", "STEPPED", "SMOOTHSTEP", "SMOOTHERSTEP"]:
            for clamp in [True, False]:
                def fn(g, u, dtype=dtype, interp=interp, clamp=clamp):
                    props = {"data_type": dtype, "interpolation_type": interp, "clamp": clamp}
                    if dtype == "FLOAT":
                        ins = {"Value": g.lin(u, 1.6, 0.5, -0.3), "From Min": 0.2,
                               "From Max": 1.1, "To Min": -0.5, "To Max": 1.5, "Steps": 3.0}
                        out = "Result"
                    else:
                        ins = {"Vector": g.mapping(u, rot=(0.1, 0.2, 0.4), scale=(1.4, 1.6, 1)),
                               "From_Min_FLOAT3": (0.1, 0.2, -0.3),
                               "From_Max_FLOAT3": (1.0, 0.9, 0.8),
                               "To_Min_FLOAT3": (-0.2, 0.1, 0.0),
                               "To_Max_FLOAT3": (1.2, 0.8, 1.5),
                               "Steps_FLOAT3": (3.0, 4.0, 5.0)}
                        out = "Vector"
                    return g.out(g.node("ShaderNodeMapRange", props, ins), out)
                cases.append(C("map_range_%s_%s%s" % (dtype.lower(), interp.lower(),
                                                      "_clamp" if clamp else ""), fn))

    for ctype, lo, hi in [("MINMAX", 0.2, 0.7), ("RANGE", 0.8, 0.25), ("MINMAX", 0.8, 0.25)]:
        def fn(g, u, ctype=ctype, lo=lo, hi=hi):
            n = g.node("ShaderNodeClamp", {"clamp_type": ctype},
                       {"Value": g.lin(u, 0.9, 0.3, -0.1), "Min": lo, "Max": hi})
            return g.out(n, "Result")
        cases.append(C("clamp_%s_%g_%g" % (ctype.lower(), lo, hi), fn))

    for mode in ["RGB", "HSV", "HSL"]:
        def sep(g, u, mode=mode):
            n = g.node("ShaderNodeSeparateColor", {"mode": mode}, {"Color": g.color_b(u)})
            return g.combine(g.out(n, "Red"), g.out(n, "Green"), g.out(n, "Blue"))
        cases.append(C("separate_color_%s" % mode.lower(), sep))

        def comb(g, u, mode=mode):
            x, y = g.xy(u)
            n = g.node("ShaderNodeCombineColor", {"mode": mode},
                       {"Red": x, "Green": g.math("MULTIPLY_ADD", y, 0.8, 0.1), "Blue": 0.6})
            return g.out(n, "Color")
        cases.append(C("combine_color_%s" % mode.lower(), comb))

    def sep_rgb(g, u):
        n = g.node("ShaderNodeSeparateRGB", ins={"Image": g.color_b(u)})
        return g.combine(g.out(n, "B"), g.out(n, "R"), g.out(n, "G"))
    cases.append(C("separate_rgb", sep_rgb))

    def comb_rgb(g, u):
        x, y = g.xy(u)
        return g.out(g.node("ShaderNodeCombineRGB", ins={"R": y, "G": 0.3, "B": x}), "Image")
    cases.append(C("combine_rgb", comb_rgb))

    def sep_xyz(g, u):
        n = g.node("ShaderNodeSeparateXYZ", ins={"Vector": g.color_a(u)})
        return g.combine(g.out(n, "Z"), g.out(n, "X"), g.out(n, "Y"))
    cases.append(C("separate_xyz", sep_xyz))

    def sep_hsv(g, u):
        n = g.node("ShaderNodeSeparateHSV", ins={"Color": g.color_a(u)})
        return g.combine(g.out(n, "H"), g.out(n, "S"), g.out(n, "V"))
    cases.append(C("separate_hsv", sep_hsv))

    def comb_hsv(g, u):
        x, y = g.xy(u)
        n = g.node("ShaderNodeCombineHSV", ins={"H": x, "S": g.math("MULTIPLY_ADD", y, 0.8, 0.2),
                                                 "V": 0.8})
        return g.out(n, "Color")
    cases.append(C("combine_hsv", comb_hsv))

    def bw(g, u):
        return g.out(g.node("ShaderNodeRGBToBW", ins={"Color": g.color_b(u)}), "Val")
    cases.append(C("rgb_to_bw", bw))

    for name, lo, hi in [("blackbody_800_12800", 800.0, 12800.0),
                         ("blackbody_1000_4000", 1000.0, 4000.0)]:
        def fn(g, u, lo=lo, hi=hi):
            t = g.lin(u, (hi - lo) * 0.8, (hi - lo) * 0.2, lo)
            return g.out(g.node("ShaderNodeBlackbody", ins={"Temperature": t}), "Color")
        cases.append(C(name, fn))

    def wl(g, u):
        t = g.lin(u, 360.0, 60.0, 370.0)
        return g.out(g.node("ShaderNodeWavelength", ins={"Wavelength": t}), "Color")
    cases.append(C("wavelength", wl))

    for extend, fac in [("HORIZONTAL", 1.0), ("EXTRAPOLATED", 1.0), ("HORIZONTAL", 0.5)]:
        def fn(g, u, extend=extend, fac=fac):
            n = g.node("ShaderNodeFloatCurve", ins={"Factor": fac,
                                                    "Value": g.lin(u, 1.2, 0.3, -0.25)})
            m = n.mapping
            m.extend = extend
            c = m.curves[0]
            c.points[0].location = (0.1, 0.2)
            c.points[1].location = (0.9, 0.7)
            c.points.new(0.4, 0.8)
            m.update()
            return g.out(n, "Value")
        cases.append(C("float_curve_%s_%g" % (extend.lower(), fac), fn))
    return Family("converters", 8, 16, cases,
                  "Math (40 operations, clamp), Vector Math (27 operations), Map Range (float "
                  "and vector x 4 interpolations x clamp), Clamp (min-max, range), Separate / "
                  "Combine Color (RGB, HSV, HSL), Separate/Combine RGB, XYZ, HSV, RGB to BW, "
                  "Blackbody, Wavelength, Float Curve")


def family_vector():
    cases = []
    for vtype in ["POINT", "TEXTURE", "VECTOR", "NORMAL"]:
        for k, (loc, rot, scale) in enumerate([((0.3, -0.2, 0.1), (0.4, -0.7, 1.1),
                                                (1.5, 0.8, -1.2)),
                                               ((-0.5, 0.25, 0.0), (1.9, 0.3, -0.6),
                                                (0.6, 1.3, 2.0))]):
            def fn(g, u, vtype=vtype, loc=loc, rot=rot, scale=scale):
                v = g.vm("ADD", u, (0.0, 0.0, 0.35))
                return g.mapping(v, loc, rot, scale, vtype)
            cases.append(C("mapping_%s_%d" % (vtype.lower(), k), fn))
    for rtype in ["AXIS_ANGLE", "X_AXIS", "Y_AXIS", "Z_AXIS", "EULER_XYZ"]:
        for invert in [False, True]:
            def fn(g, u, rtype=rtype, invert=invert):
                v = g.mapping(u, loc=(-0.5, -0.4, 0.3), rot=(0.3, 0.1, 0.2))
                n = g.node("ShaderNodeVectorRotate", {"rotation_type": rtype, "invert": invert},
                           {"Vector": v, "Center": (0.1, -0.2, 0.15),
                            "Axis": (0.3, 0.8, 0.5), "Angle": g.lin(u, 2.0, 1.0, -0.6),
                            "Rotation": (0.7, -0.4, 1.3)})
                return g.out(n, "Vector")
            cases.append(C("vector_rotate_%s%s" % (rtype.lower(), "_invert" if invert else ""),
                           fn))
    pairs = [("WORLD", "OBJECT"), ("OBJECT", "WORLD"), ("WORLD", "CAMERA"), ("CAMERA", "WORLD"),
             ("OBJECT", "CAMERA"), ("CAMERA", "OBJECT")]
    for vtype in ["POINT", "VECTOR", "NORMAL"]:
        for src, dst in pairs:
            def fn(g, u, vtype=vtype, src=src, dst=dst):
                v = g.mapping(u, loc=(-0.5, -0.4, 0.3), rot=(0.3, 0.1, 0.2))
                n = g.node("ShaderNodeVectorTransform",
                           {"vector_type": vtype, "convert_from": src, "convert_to": dst},
                           {"Vector": v})
                return g.out(n, "Vector")
            cases.append(C("vector_transform_%s_%s_%s" % (vtype.lower(), src.lower(),
                                                          dst.lower()), fn, obj="turned"))

    def vcurves(g, u):
        v = g.mapping(u, loc=(-0.5, -0.4, 0.3), rot=(0.3, 0.1, 0.2), scale=(1.6, 1.6, 1.6))
        n = g.node("ShaderNodeVectorCurve", ins={"Vector": v, "Fac": 0.8})
        m = n.mapping
        m.curves[0].points.new(0.2, 0.6)
        m.curves[1].points.new(-0.3, 0.4)
        m.curves[2].points[0].location = (-1.0, -0.5)
        m.update()
        return g.out(n, "Vector")
    cases.append(C("vector_curves", vcurves))

    for space in ["TANGENT", "OBJECT", "WORLD", "BLENDER_OBJECT", "BLENDER_WORLD"]:
        for strength in [1.0, 0.6]:
            def fn(g, u, space=space, strength=strength):
                col = g.vm("MULTIPLY_ADD", u, (0.6, 0.5, 0.0), (0.2, 0.25, 0.8))
                n = g.node("ShaderNodeNormalMap", {"space": space},
                           {"Color": col, "Strength": strength})
                return g.out(n, "Normal")
            cases.append(C("normal_map_%s_%g" % (space.lower(), strength), fn, obj="turned"))

    def bump(name, height, strength=1.0, distance=1.0, invert=False):
        def fn(g, u):
            n = g.node("ShaderNodeBump", {"invert": invert},
                       {"Height": height(g), "Strength": strength, "Distance": distance})
            return g.out(n, "Normal")
        cases.append(C(name, fn, quantized=False))

    def h_linear(g):
        return g.vm("DOT_PRODUCT", g.tc("Object"), (0.05, -0.03, 0.0))

    def h_quadratic(g):
        p = g.vm("MULTIPLY_ADD", g.tc("Object"), (0.125, 0.125, 0.0), (-1.0, -1.0, 0.0))
        return g.vm("DOT_PRODUCT", p, p)

    def h_noise(g):
        n = g.node("ShaderNodeTexNoise", ins={"Vector": g.tc("Generated"), "Scale": 1.5,
                                              "Detail": 0.0})
        return g.out(n, "Fac")
    bump("bump_linear", h_linear)
    bump("bump_quadratic", h_quadratic)
    bump("bump_quadratic_strength", h_quadratic, strength=0.4, distance=2.0)
    bump("bump_quadratic_invert", h_quadratic, invert=True)
    bump("bump_noise", h_noise, distance=0.3)
    return Family("vector", 8, 12, cases,
                  "Mapping (point/texture/vector/normal), Vector Rotate (5 types x invert), "
                  "Vector Transform (world, object, camera: the six pairs x point/vector/normal, "
                  "on a turned and scaled object), Vector Curves, Normal Map (5 spaces x strength), Bump "
                  "(linear, quadratic and noise heights, strength, distance, invert)")
