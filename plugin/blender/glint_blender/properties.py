"""Scene settings for glint (scene.glint), mapped one to one onto glint's command line."""

import bpy


class GlintSceneSettings(bpy.types.PropertyGroup):
    integrator: bpy.props.EnumProperty(
        name="Integrator",
        description="glint --integrator",
        items=(
            ('PATH', "Path Tracing", "Monte Carlo path tracer (matches Cycles)"),
            ('WHITTED', "Whitted", "POV-Ray's classic lighting model (no global illumination)"),
        ),
        default='PATH',
    )
    samples: bpy.props.IntProperty(
        name="Samples", description="Samples per pixel (glint --spp)",
        default=64, min=1, soft_max=4096, max=16777216,
    )
    max_depth: bpy.props.IntProperty(
        name="Max Depth",
        description="Maximum path length (glint --max-depth; the Cycles equivalent is "
                    "Max Bounces = Max Depth - 1)",
        default=8, min=0, soft_max=64, max=4096,
    )
    time_limit: bpy.props.FloatProperty(
        name="Time Limit",
        description="Stop after the progressive pass that passes this many seconds "
                    "(glint --time-limit; 0: no limit)",
        default=0.0, min=0.0, soft_max=3600.0, subtype='TIME_ABSOLUTE', unit='TIME_ABSOLUTE',
    )
    seed: bpy.props.IntProperty(
        name="Seed", description="Sampler seed (glint --seed)", default=0, min=0,
    )
    threads: bpy.props.IntProperty(
        name="Threads",
        description="Worker threads (glint --threads; 0: all hardware threads). The image is "
                    "the same whatever the count",
        default=0, min=0, max=4096,
    )


def register():
    bpy.utils.register_class(GlintSceneSettings)
    bpy.types.Scene.glint = bpy.props.PointerProperty(type=GlintSceneSettings)


def unregister():
    del bpy.types.Scene.glint
    bpy.utils.unregister_class(GlintSceneSettings)
