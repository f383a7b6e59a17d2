# Run by make_fixtures.sh inside Blender (blender --background --python ...):
# an asymmetric, single-sided, normal-mapped model (an extruded letter F with
# a bumpy normal map, back faces culled) exported as Blender writes it, once
# as modelled and once mirrored the way modellers mirror parts: the object's
# scale is -1 on X, which Blender keeps as the node's scale (glTF, FBX) or
# bakes into the vertices (OBJ).
#   blender --background --python blender_mirrored.py -- OUT_PREFIX
import sys

import bpy
import numpy

numpy.bool = bool  # Debian 12's Blender 3.4 with numpy 1.24

prefix = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)

bpy.ops.object.text_add(location=(0.0, 0.0, 0.0), rotation=(1.5707963, 0.0, 0.0))
letter = bpy.context.active_object
letter.data.body = "F"
letter.data.extrude = 0.08
letter.data.align_x = "CENTER"
letter.data.align_y = "CENTER"
bpy.ops.object.convert(target="MESH")
letter = bpy.context.active_object
letter.scale = (1.5, 1.5, 1.5)
bpy.ops.object.transform_apply(location=False, rotation=True, scale=True)
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
bpy.ops.uv.smart_project()
bpy.ops.object.mode_set(mode="OBJECT")

material = bpy.data.materials.new("letter")
material.use_backface_culling = True  # glTF doubleSided false
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
bsdf = next(n for n in nodes if n.type == "BSDF_PRINCIPLED")
bsdf.inputs["Base Color"].default_value = (0.8, 0.55, 0.3, 1.0)
bsdf.inputs["Roughness"].default_value = 0.5
image = bpy.data.images.new("bumps", 64, 64)
pixels = []
for y in range(64):
    for x in range(64):
        dx = 0.5 if (x // 8) % 2 else -0.2
        dy = 0.5 if (y // 16) % 2 else -0.3
        pixels += [0.5 + 0.5 * dx, 0.5 + 0.5 * dy, 0.8, 1.0]
image.pixels = pixels
image.save_render(prefix + "-bumps.png")
image = bpy.data.images.load(prefix + "-bumps.png")
image.colorspace_settings.name = "Non-Color"
texture = nodes.new("ShaderNodeTexImage")
texture.image = image
normal_map = nodes.new("ShaderNodeNormalMap")
links.new(texture.outputs["Color"], normal_map.inputs["Color"])
links.new(normal_map.outputs["Normal"], bsdf.inputs["Normal"])
letter.data.materials.append(material)

def export(name):
    bpy.ops.export_scene.gltf(filepath=prefix + name + ".glb", export_format="GLB", export_tangents=True)
    bpy.ops.export_scene.fbx(filepath=prefix + name + ".fbx", axis_up="Y", axis_forward="-Z", path_mode="COPY", embed_textures=True)
    bpy.ops.wm.obj_export(filepath=prefix + name + ".obj", forward_axis="NEGATIVE_Z", up_axis="Y", path_mode="RELATIVE")


export(".plain")
letter.scale = (-1.0, 1.0, 1.0)
export(".mirrored")
