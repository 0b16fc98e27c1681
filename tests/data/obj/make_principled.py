# Writes principled.obj/.mtl (PBR extensions) and principled_classic.obj/.mtl (without) with
# Blender 3.4's OBJ exporter, for tests/unit/obj_importer_test.cpp's round trip:
#   blender -b --factory-startup --python tests/data/obj/make_principled.py
# The Principled values set here are what the test expects back. The three 4x4 PNGs
# (ramp_gray.png, tint.png, flat_normal.png) are written here too, with Blender's image API.
import os
import bpy

HERE = os.path.dirname(os.path.abspath(__file__))

bpy.ops.object.select_all(action='SELECT')
bpy.ops.object.delete()


def png(name, pixel):
    img = bpy.data.images.new(name, 4, 4, alpha=False)
    px = []
    for y in range(4):
        for x in range(4):
            px += list(pixel(x, y)) + [1.0]
    img.pixels = px
    img.filepath_raw = os.path.join(HERE, name)
    img.file_format = 'PNG'
    img.save()
    return img


ramp = png('ramp_gray.png', lambda x, y: (x / 3,) * 3)
tint = png('tint.png', lambda x, y: (x / 3, y / 3, 0.5))
normal = png('flat_normal.png', lambda x, y: (0.5, 0.5, 1.0))


def principled(name, **inputs):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    p = m.node_tree.nodes['Principled BSDF']
    for k, v in inputs.items():
        p.inputs[k.replace('_', ' ')].default_value = v
    return m, p


def plane(name, x, material):
    bpy.ops.mesh.primitive_plane_add(size=1, location=(x, 0, 0))
    o = bpy.context.active_object
    o.name = name
    o.data.materials.append(material)


mats = [
    principled('Plastic', Base_Color=(0.8, 0.2, 0.1, 1), Metallic=0.0, Roughness=0.3, IOR=1.6,
               Specular=0.4),
    principled('Metal', Base_Color=(0.9, 0.6, 0.2, 1), Metallic=1.0, Roughness=0.15),
    principled('Glass', Base_Color=(1, 1, 1, 1), Transmission=1.0, Roughness=0.05, IOR=1.5),
    principled('Lamp', Base_Color=(0.1, 0.1, 0.1, 1), Emission=(1, 0.5, 0.25, 1),
               Emission_Strength=4.0),
    principled('Cutout', Base_Color=(0.2, 0.8, 0.2, 1), Alpha=0.4),
]
m, p = principled('Textured')
nt = m.node_tree
coords = nt.nodes.new('ShaderNodeTexCoord')
mapping = nt.nodes.new('ShaderNodeMapping')
mapping.inputs['Location'].default_value = (0.25, 0.5, 0)
mapping.inputs['Scale'].default_value = (2, 3, 1)
nt.links.new(coords.outputs['UV'], mapping.inputs['Vector'])


def image(img, socket, mapped=False):
    t = nt.nodes.new('ShaderNodeTexImage')
    t.image = img
    if mapped:
        nt.links.new(mapping.outputs['Vector'], t.inputs['Vector'])
    nt.links.new(t.outputs['Color'], socket)


image(tint, p.inputs['Base Color'], mapped=True)
image(ramp, p.inputs['Roughness'])
image(ramp, p.inputs['Metallic'])
image(tint, p.inputs['Emission'])
image(ramp, p.inputs['Alpha'])
nm = nt.nodes.new('ShaderNodeNormalMap')
nm.inputs['Strength'].default_value = 0.7
image(normal, nm.inputs['Color'])
nt.links.new(nm.outputs['Normal'], p.inputs['Normal'])
mats.append((m, p))

for i, (mat, _) in enumerate(mats):
    plane(mat.name, 2 * i, mat)

bpy.ops.object.select_all(action='SELECT')
for suffix, pbr in (('', True), ('_classic', False)):
    bpy.ops.wm.obj_export(filepath=os.path.join(HERE, 'principled' + suffix + '.obj'),
                          forward_axis='NEGATIVE_Z', up_axis='Y', export_materials=True,
                          export_pbr_extensions=pbr, path_mode='STRIP',
                          export_triangulated_mesh=True)
