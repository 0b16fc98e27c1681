"""Panels: glint's own settings in Render Properties and a light panel; the stock panels
(material, world, light, camera, output, color management, object data, ...) are opened to the
GLINT engine by adding it to their COMPAT_ENGINES, and closed again on unregister."""

import bpy

ENGINE = "GLINT"

# Stock panels meant for one of Blender's own engines that glint also wants: material and world
# surfaces (node inputs), material slots, spot shape, depth of field (shown so that its warning
# makes sense).
EXTRA_PANELS = {
    "EEVEE_MATERIAL_PT_context_material",
    "EEVEE_MATERIAL_PT_surface",
    "EEVEE_WORLD_PT_surface",
    "DATA_PT_camera_dof",
    "DATA_PT_camera_dof_aperture",
}
# Panels for Blender's internal engine that glint replaces with its own or cannot use.
EXCLUDED_PANELS = {
    "DATA_PT_light",
    "DATA_PT_area",
    "DATA_PT_preview",
    "DATA_PT_falloff_curve",
    "MATERIAL_PT_preview",
    "EEVEE_MATERIAL_PT_viewport_settings",
}

_opened = []


def _stock_panels():
    for panel in bpy.types.Panel.__subclasses__():
        engines = getattr(panel, "COMPAT_ENGINES", None)
        if engines is None or panel.__name__.startswith("GLINT_"):
            continue
        name = panel.__name__
        if name in EXTRA_PANELS or ('BLENDER_RENDER' in engines and
                                    name not in EXCLUDED_PANELS):
            yield panel


class GlintPanel:
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    COMPAT_ENGINES = {ENGINE}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES


class GLINT_RENDER_PT_sampling(GlintPanel, bpy.types.Panel):
    bl_context = "render"
    bl_label = "Sampling"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        g = context.scene.glint
        col = layout.column()
        col.prop(g, "integrator")
        sub = col.column()
        sub.active = g.integrator == 'PATH'
        sub.prop(g, "samples")
        sub.prop(g, "max_depth")
        sub.prop(g, "time_limit")
        sub.prop(g, "seed")


class GLINT_RENDER_PT_performance(GlintPanel, bpy.types.Panel):
    bl_context = "render"
    bl_label = "Performance"
    bl_options = {'DEFAULT_CLOSED'}

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        layout.prop(context.scene.glint, "threads")


class GLINT_LIGHT_PT_light(GlintPanel, bpy.types.Panel):
    bl_context = "data"
    bl_label = "Light"

    @classmethod
    def poll(cls, context):
        return context.light is not None and super().poll(context)

    def draw(self, context):
        layout = self.layout
        light = context.light
        layout.row().prop(light, "type", expand=True)
        layout.use_property_split = True
        layout.use_property_decorate = False
        col = layout.column()
        col.prop(light, "color")
        col.prop(light, "energy")
        if light.type in {'POINT', 'SPOT'}:
            col.prop(light, "shadow_soft_size", text="Radius")
        elif light.type == 'SUN':
            col.prop(light, "angle")
        elif light.type == 'AREA':
            col.prop(light, "shape")
            sub = col.column(align=True)
            if light.shape in {'SQUARE', 'DISK'}:
                sub.prop(light, "size")
            else:
                sub.prop(light, "size", text="Size X")
                sub.prop(light, "size_y", text="Y")
            col.prop(light, "spread")
        if light.type == 'SPOT':
            col.separator()
            col.prop(light, "spot_size", text="Spot Size")
            col.prop(light, "spot_blend", text="Blend")
            col.prop(light, "show_cone")


classes = (GLINT_RENDER_PT_sampling, GLINT_RENDER_PT_performance, GLINT_LIGHT_PT_light)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    for panel in _stock_panels():
        if ENGINE not in panel.COMPAT_ENGINES:
            panel.COMPAT_ENGINES.add(ENGINE)
            _opened.append(panel)


def unregister():
    for panel in _opened:
        panel.COMPAT_ENGINES.discard(ENGINE)
    _opened.clear()
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
