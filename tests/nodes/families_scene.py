"""The families of the node scenes (make_node_scenes.py) that read the scene itself: inputs
(continuous coordinates), shader mixes, and graphs that combine nodes."""

import bpy

from node_graph import C, Family, Graph, _sock


def family_inputs():
    cases = []

    def out_of(type_, output, props=None, ins=None):
        def fn(g, u):
            return g.out(g.node(type_, props, ins), output)
        return fn

    for out in ["Generated", "Object", "UV", "Normal", "Reflection", "Camera", "Window"]:
        cases.append(C("tex_coord_%s" % out.lower(), out_of("ShaderNodeTexCoord", out),
                       quantized=False, obj="quad"))
        cases.append(C("tex_coord_%s_sphere" % out.lower(), out_of("ShaderNodeTexCoord", out),
                       quantized=False, obj="sphere"))
    cases.append(C("tex_coord_object_moved", out_of("ShaderNodeTexCoord", "Object"),
                   quantized=False, obj="moved"))
    cases.append(C("tex_coord_generated_moved", out_of("ShaderNodeTexCoord", "Generated"),
                   quantized=False, obj="moved"))
    cases.append(C("tex_coord_normal_moved", out_of("ShaderNodeTexCoord", "Normal"),
                   quantized=False, obj="moved"))
    # Not here (README, known gaps): Parametric (glint has no barycentrics: it gives UV),
    # Pointiness, Random Per Island.
    for out in ["Position", "Normal", "Tangent", "True Normal", "Incoming", "Backfacing"]:
        cases.append(C("geometry_%s" % out.lower().replace(" ", "_"),
                       out_of("ShaderNodeNewGeometry", out), quantized=False, obj="sphere"))
    cases.append(C("geometry_position_quad", out_of("ShaderNodeNewGeometry", "Position"),
                   quantized=False))
    cases.append(C("geometry_backfacing_back", out_of("ShaderNodeNewGeometry", "Backfacing"),
                   quantized=False, obj="back"))
    cases.append(C("geometry_normal_back", out_of("ShaderNodeNewGeometry", "Normal"),
                   quantized=False, obj="back"))
    cases.append(C("uv_map", out_of("ShaderNodeUVMap", "UV"), quantized=False, obj="moved"))

    def obj_info(out):
        def setup(ob, mat):
            ob.color = (0.8, 0.35, 0.1, 0.6)
            ob.pass_index = 5
        return C("object_info_%s" % out.lower().replace(" ", "_"),
                 out_of("ShaderNodeObjectInfo", out), quantized=False, setup=setup)
    # Not here (README, known gaps): Alpha (glint keeps no object alpha: 1), Material Index.
    for out in ["Location", "Color", "Object Index", "Random"]:
        cases.append(obj_info(out))
    # Random differs per object: several objects, each its own tile.
    for k in range(6):
        cases.append(C("object_info_random_%d" % k, out_of("ShaderNodeObjectInfo", "Random"),
                       quantized=False, display=False))

    def value(g, u):
        n = g.node("ShaderNodeValue")
        n.outputs[0].default_value = 0.37
        return n.outputs[0]
    cases.append(C("value", value, quantized=False))

    def rgb(g, u):
        n = g.node("ShaderNodeRGB")
        n.outputs[0].default_value = (0.2, 0.65, 0.9, 1.0)
        return n.outputs[0]
    cases.append(C("rgb", rgb, quantized=False))

    for blend in [0.5, 0.2, 0.85]:
        for out in ["Fresnel", "Facing"]:
            cases.append(C("layer_weight_%s_%g" % (out.lower(), blend),
                           out_of("ShaderNodeLayerWeight", out, ins={"Blend": blend}),
                           quantized=False, obj="sphere"))
    for ior in [1.45, 2.5]:
        cases.append(C("fresnel_%g" % ior, out_of("ShaderNodeFresnel", "Fac", ins={"IOR": ior}),
                       quantized=False, obj="sphere"))
    cases.append(C("fresnel_back", out_of("ShaderNodeFresnel", "Fac", ins={"IOR": 1.45}),
                   quantized=False, obj="back"))

    def light_path(outs):
        def fn(g, u):
            n = g.node("ShaderNodeLightPath")
            return g.combine(*[g.out(n, o) for o in outs])
        return fn
    groups = [("Is Camera Ray", "Is Shadow Ray", "Is Diffuse Ray"),
              ("Is Glossy Ray", "Is Singular Ray", "Is Reflection Ray"),
              ("Is Transmission Ray", "Ray Depth", "Diffuse Depth"),
              ("Glossy Depth", "Transparent Depth", "Transmission Depth")]
    for k, outs in enumerate(groups):
        cases.append(C("light_path_%d" % k, light_path(outs), quantized=False, display=False))
    # Not here (README, known gaps): Ray Length (glint measures camera rays from the camera,
    # Cycles from the near clip plane).
    for out in ["View Vector", "View Z Depth", "View Distance"]:
        cases.append(C("camera_data_%s" % out.lower().replace(" ", "_"),
                       out_of("ShaderNodeCameraData", out), quantized=False, obj="sphere"))
    return Family("inputs", 16, 8, cases,
                  "Texture Coordinate (each output on a quad, a smooth sphere, a moved / rotated "
                  "/ scaled quad), Geometry, UV Map, Object Info, Value, RGB, Layer Weight, "
                  "Fresnel, Light Path, Camera Data; continuous coordinates")


def family_shaders():
    cases = []

    def emission(g, color, strength=1.0):
        n = g.node("ShaderNodeEmission", ins={"Color": color, "Strength": strength})
        return g.out(n, "Emission")

    def mix_fac(g, u):
        x, y = g.xy(u)
        return x

    def mix_shader(g, u):
        n = g.node("ShaderNodeMixShader", ins={
            "Fac": g.lin(u, 0.8, 0.2, 0.0), "Shader": emission(g, (0.9, 0.2, 0.1)),
            "Shader_001": emission(g, g.color_b(u), 0.7)})
        return g.out(n, "Shader")
    cases.append(C("mix_shader", mix_shader))

    def mix_shader_tex(g, u):
        t = g.node("ShaderNodeTexChecker", ins={"Vector": u, "Scale": 3.0,
                                                "Color1": (0.9, 0.9, 0.9, 1),
                                                "Color2": (0.15, 0.15, 0.15, 1)})
        n = g.node("ShaderNodeMixShader", ins={
            "Fac": g.out(t, "Fac"), "Shader": emission(g, g.color_a(u)),
            "Shader_001": emission(g, (0.1, 0.5, 0.9), 0.5)})
        return g.out(n, "Shader")
    cases.append(C("mix_shader_checker", mix_shader_tex))

    def mix_shader_out_of_range(g, u):
        n = g.node("ShaderNodeMixShader", ins={
            "Fac": g.lin(u, 2.0, 0.5, -0.8), "Shader": emission(g, (0.9, 0.6, 0.1)),
            "Shader_001": emission(g, (0.1, 0.3, 0.8))})
        return g.out(n, "Shader")
    cases.append(C("mix_shader_fac_clamped", mix_shader_out_of_range))

    def add_shader(g, u):
        n = g.node("ShaderNodeAddShader", ins={
            "Shader": emission(g, g.color_a(u), 0.5), "Shader_001": emission(g, (0.3, 0.1, 0.2))})
        return g.out(n, "Shader")
    cases.append(C("add_shader", add_shader))

    def nested(g, u):
        a = g.node("ShaderNodeAddShader", ins={"Shader": emission(g, (0.2, 0.1, 0.05)),
                                               "Shader_001": emission(g, g.color_b(u), 0.6)})
        n = g.node("ShaderNodeMixShader", ins={"Fac": g.lin(u, 0.3, 0.6),
                                               "Shader": g.out(a, "Shader"),
                                               "Shader_001": emission(g, g.color_a(u), 0.8)})
        return g.out(n, "Shader")
    cases.append(C("mix_of_add", nested))

    def strength(g, u):
        return emission(g, (0.8, 0.7, 0.5), g.lin(u, 0.9, 0.3, 0.0))
    cases.append(C("emission_strength", strength))

    def color_to_surface(g, u):
        n = g.node("ShaderNodeRGB")
        n.outputs[0].default_value = (0.3, 0.75, 0.45, 1.0)
        return ("surface", n.outputs[0])
    cases.append(C("color_into_surface", color_to_surface))

    def dark_bsdf(g, u):
        d = g.node("ShaderNodeBsdfDiffuse", ins={"Color": (0.8, 0.8, 0.8, 1)})
        n = g.node("ShaderNodeMixShader", ins={"Fac": g.lin(u, 0.5, 0.4, 0.05),
                                               "Shader": g.out(d, "BSDF"),
                                               "Shader_001": emission(g, g.color_a(u))})
        return g.out(n, "Shader")
    cases.append(C("mix_diffuse_emission_unlit", dark_bsdf))

    def principled_emission(g, u):
        n = g.node("ShaderNodeBsdfPrincipled", ins={
            "Base Color": (0, 0, 0, 1), "Specular": 0.0, "Emission": g.color_b(u),
            "Emission Strength": g.lin(u, 0.5, 0.5, 0.4)})
        return g.out(n, "BSDF")
    cases.append(C("principled_emission", principled_emission))

    def transparent_mix(g, u):
        t = g.node("ShaderNodeBsdfTransparent", ins={"Color": (0.9, 0.6, 0.3, 1)})
        n = g.node("ShaderNodeMixShader", ins={"Fac": g.lin(u, 0.9, 0.1, 0.0),
                                               "Shader": g.out(t, "BSDF"),
                                               "Shader_001": emission(g, g.color_a(u))})
        return g.out(n, "Shader")
    cases.append(C("transparent_mix", transparent_mix))

    def principled_alpha(g, u):
        n = g.node("ShaderNodeBsdfPrincipled", ins={
            "Base Color": (0, 0, 0, 1), "Specular": 0.0, "Emission": (0.9, 0.8, 0.2, 1),
            "Alpha": g.lin(u, 0.7, 0.3)})
        return g.out(n, "BSDF")
    cases.append(C("principled_alpha", principled_alpha))

    def backdrop(scene, layout):
        """An emissive plane under the whole grid (seen through the transparent cases)."""
        w, h = layout["width"], layout["height"]
        me = bpy.data.meshes.new("backdrop")
        me.from_pydata([(-w / 2, -h / 2, -1), (w / 2, -h / 2, -1), (w / 2, h / 2, -1),
                        (-w / 2, h / 2, -1)], [], [(0, 1, 2, 3)])
        ob = bpy.data.objects.new("backdrop", me)
        scene.collection.objects.link(ob)
        mat = bpy.data.materials.new("backdrop")
        mat.use_nodes = True
        g = Graph(mat, 1)
        for n in list(g.nt.nodes):
            g.nt.nodes.remove(n)
        out = g.node("ShaderNodeOutputMaterial")
        chk = g.node("ShaderNodeTexChecker", ins={"Vector": g.tc("Object"), "Scale": 0.25,
                                                  "Color1": (0.2, 0.6, 0.3, 1),
                                                  "Color2": (0.7, 0.3, 0.6, 1)})
        em = g.node("ShaderNodeEmission", ins={"Color": g.out(chk, "Color")})
        g.nt.links.new(g.out(em, "Emission"), out.inputs["Surface"])
        me.materials.append(mat)
    return Family("shaders", 16, 4, cases,
                  "Mix Shader (factor from coordinates, a checker, out of [0, 1]), Add Shader, "
                  "nested, Emission strength, a colour into the Surface, an unlit Diffuse, "
                  "Principled emission and alpha, Transparent over an emissive backdrop",
                  extra=backdrop)


def family_graphs():
    cases = []

    def noise_ramp(g, u):
        n = g.node("ShaderNodeTexNoise", ins={"Vector": g.tcq("Object"), "Scale": 0.15,
                                              "Detail": 4.0})
        r = g.node("ShaderNodeValToRGB", ins={"Fac": g.out(n, "Fac")})
        r.color_ramp.interpolation = "EASE"
        r.color_ramp.elements[0].position = 0.35
        r.color_ramp.elements[0].color = (0.05, 0.1, 0.4, 1)
        r.color_ramp.elements[1].position = 0.65
        r.color_ramp.elements[1].color = (0.95, 0.7, 0.2, 1)
        return g.out(r, "Color")
    cases.append(C("noise_color_ramp", noise_ramp, quantized="own"))

    def voronoi_math_mix(g, u):
        v = g.node("ShaderNodeTexVoronoi", ins={"Vector": g.tcq("Generated"), "Scale": 3.0})
        p = g.math("POWER", g.out(v, "Distance"), 2.0)
        c = g.node("ShaderNodeTexChecker", ins={"Vector": g.tcq("UV"), "Scale": 4.0})
        m = g.node("ShaderNodeMix", {"data_type": "RGBA", "blend_type": "MULTIPLY"},
                   {"Factor_Float": g.math("SUBTRACT", 1.0, p), "A_Color": g.out(v, "Color"),
                    "B_Color": g.out(c, "Color")})
        return g.out(m, "Result_Color")
    cases.append(C("voronoi_math_mix", voronoi_math_mix, quantized="own"))

    def musgrave_wave(g, u):
        ms = g.node("ShaderNodeTexMusgrave", ins={"Vector": g.tcq("Object"), "Scale": 0.2})
        mr = g.node("ShaderNodeMapRange", {"interpolation_type": "SMOOTHSTEP"},
                    {"Value": g.out(ms, "Fac"), "From Min": -0.5, "From Max": 0.5})
        wv = g.node("ShaderNodeTexWave", ins={"Vector": g.tcq("Generated"), "Scale": 2.0})
        hs = g.node("ShaderNodeHueSaturation", ins={"Hue": g.out(mr, "Result"),
                                                    "Color": g.out(wv, "Color")})
        return g.out(hs, "Color")
    cases.append(C("musgrave_map_range_hue", musgrave_wave, quantized="own"))

    def brick_mix_shader(g, u):
        b = g.node("ShaderNodeTexBrick", ins={"Vector": g.tcq("UV"), "Scale": 3.0})
        mg = g.node("ShaderNodeTexMagic", ins={"Vector": g.tcq("Generated"), "Scale": 2.0})
        gr = g.node("ShaderNodeTexGradient", {"gradient_type": "SPHERICAL"},
                    {"Vector": g.mapping(g.tcq("Generated"), loc=(-0.5, -0.5, -0.5),
                                         scale=(2, 2, 2))})
        e1 = g.node("ShaderNodeEmission", ins={"Color": g.out(mg, "Color")})
        e2 = g.node("ShaderNodeEmission", ins={"Color": g.out(gr, "Color"), "Strength": 0.8})
        n = g.node("ShaderNodeMixShader", ins={"Fac": g.out(b, "Fac"),
                                               "Shader": g.out(e1, "Emission"),
                                               "Shader_001": g.out(e2, "Emission")})
        return g.out(n, "Shader")
    cases.append(C("brick_mix_shader", brick_mix_shader, quantized="own"))

    def group(g, u):
        """A node group (Math + Mix inside, a reroute and a muted node) used twice."""
        tree = bpy.data.node_groups.get("tint")
        if tree is None:
            tree = bpy.data.node_groups.new("tint", "ShaderNodeTree")
            tree.inputs.new("NodeSocketFloat", "Fac")
            tree.inputs.new("NodeSocketColor", "Color")
            tree.outputs.new("NodeSocketColor", "Color")
            gi = tree.nodes.new("NodeGroupInput")
            go = tree.nodes.new("NodeGroupOutput")
            m = tree.nodes.new("ShaderNodeMath")
            m.operation = "MULTIPLY_ADD"
            m.inputs[1].default_value = 0.6
            m.inputs[2].default_value = 0.2
            tree.links.new(gi.outputs["Fac"], m.inputs[0])
            rr = tree.nodes.new("NodeReroute")
            tree.links.new(gi.outputs["Color"], rr.inputs[0])
            muted = tree.nodes.new("ShaderNodeInvert")
            muted.mute = True
            tree.links.new(rr.outputs[0], muted.inputs["Color"])
            mx = tree.nodes.new("ShaderNodeMix")
            mx.data_type = "RGBA"
            mx.blend_type = "OVERLAY"
            tree.links.new(m.outputs[0], _sock(mx.inputs, "Factor_Float"))
            tree.links.new(muted.outputs["Color"], _sock(mx.inputs, "A_Color"))
            _sock(mx.inputs, "B_Color").default_value = (0.9, 0.3, 0.6, 1)
            tree.links.new(_sock(mx.outputs, "Result_Color"), go.inputs["Color"])
        n1 = g.node("ShaderNodeGroup")
        n1.node_tree = tree
        wv = g.node("ShaderNodeTexWave", {"wave_type": "RINGS"},
                    {"Vector": g.tcq("Generated"), "Scale": 1.5})
        g.nt.links.new(g.out(wv, "Fac"), n1.inputs["Fac"])
        g.nt.links.new(g.tcq("Generated"), n1.inputs["Color"])
        n2 = g.node("ShaderNodeGroup")
        n2.node_tree = tree
        n2.inputs["Fac"].default_value = 0.3
        g.nt.links.new(n1.outputs["Color"], n2.inputs["Color"])
        return n2.outputs["Color"]
    cases.append(C("node_group_twice", group, quantized="own"))

    def coords_noise4d(g, u):
        m = g.mapping(g.tcq("Generated"), loc=(0.3, 0.1, 0), rot=(0, 0, 0.6), scale=(2, 2, 2))
        oi = g.node("ShaderNodeObjectInfo")
        n = g.node("ShaderNodeTexNoise", {"noise_dimensions": "4D"},
                   {"Vector": m, "W": g.math("MULTIPLY", g.out(oi, "Random"), 10.0),
                    "Scale": 1.5, "Detail": 3.0, "Distortion": 0.4})
        sep = g.node("ShaderNodeSeparateColor", {"mode": "HSV"},
                     {"Color": g.out(n, "Color")})
        return g.combine(g.out(sep, "Blue"), g.out(sep, "Green"), g.out(n, "Fac"))
    cases.append(C("generated_noise4d_random_hsv", coords_noise4d, quantized="own"))
    return Family("graphs", 16, 3, cases,
                  "Noise -> ColorRamp; Voronoi -> Math -> Mix with a Checker; Musgrave -> Map "
                  "Range -> Hue/Saturation of a Wave; Brick -> Mix Shader of Magic and "
                  "Gradient emissions; a node group (with a reroute and a muted node) used "
                  "twice; Generated -> Mapping -> Noise 4D (W from Object Info Random) -> "
                  "Separate HSV; coordinates snapped to the pixel")
