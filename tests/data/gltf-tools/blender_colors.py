# Run by make_fixtures.sh inside Blender (blender --background --python ...):
# imports the teapot from ../shared/testdata with Blender's glTF importer, gives
# it UVs, a colour attribute and a normal-mapped material, adds a plane whose
# material is unlit (a Background shader), and exports both with Blender's
# glTF exporter: COLOR_0, TANGENT, TEXCOORD_0 and KHR_materials_unlit, written
# by Blender rather than by Atrium. Six linked copies of a cone (one mesh,
# rotated and scaled differently) give gltfpack -mi something to instance.
import sys

import bpy
import numpy

# Debian 12's Blender 3.4 importer still uses numpy.bool, which numpy 1.24 removed.
numpy.bool = bool

source, target = sys.argv[sys.argv.index("--") + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=source)
teapot = next(o for o in bpy.context.scene.objects if o.type == "MESH")
bpy.context.view_layer.objects.active = teapot
teapot.select_set(True)
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
bpy.ops.uv.smart_project()
bpy.ops.object.mode_set(mode="OBJECT")

mesh = teapot.data
colors = mesh.color_attributes.new(name="Col", type="FLOAT_COLOR", domain="POINT")
lo = [min(v.co[i] for v in mesh.vertices) for i in range(3)]
hi = [max(v.co[i] for v in mesh.vertices) for i in range(3)]
for v, c in zip(mesh.vertices, colors.data):
    t = [(v.co[i] - lo[i]) / (hi[i] - lo[i]) for i in range(3)]
    c.color = (0.2 + 0.8 * t[0], 0.2 + 0.8 * t[1], 0.2 + 0.8 * t[2], 1.0)
mesh.color_attributes.active_color = colors

# A bumpy normal map (Blender's noise texture baked into an image node is not
# needed: an image generated in Blender and packed into the file will do).
material = teapot.active_material or bpy.data.materials.new("teapot")
teapot.active_material = material
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
bsdf = next(n for n in nodes if n.type == "BSDF_PRINCIPLED")
bsdf.inputs["Roughness"].default_value = 0.45
image = bpy.data.images.new("bumps", 64, 64)
pixels = []
for y in range(64):
    for x in range(64):
        dx = 0.35 if (x // 8) % 2 else -0.35
        dy = 0.35 if (y // 8) % 2 else -0.35
        pixels += [0.5 + 0.5 * dx, 0.5 + 0.5 * dy, 0.85, 1.0]
image.pixels = pixels
image.colorspace_settings.name = "Non-Color"
image.pack()
texture = nodes.new("ShaderNodeTexImage")
texture.image = image
normal_map = nodes.new("ShaderNodeNormalMap")
links.new(texture.outputs["Color"], normal_map.inputs["Color"])
links.new(normal_map.outputs["Normal"], bsdf.inputs["Normal"])
# Blender multiplies the base colour by the colour attribute through a node.
attribute = nodes.new("ShaderNodeVertexColor")
attribute.layer_name = "Col"
links.new(attribute.outputs["Color"], bsdf.inputs["Base Color"])

bpy.ops.mesh.primitive_plane_add(size=6.0, location=(0.0, -2.0, 0.0))
plane = bpy.context.active_object
unlit = bpy.data.materials.new("unlit")
unlit.use_nodes = True
unlit.node_tree.nodes.clear()
background = unlit.node_tree.nodes.new("ShaderNodeBackground")
background.inputs["Color"].default_value = (0.8, 0.3, 0.1, 1.0)
output = unlit.node_tree.nodes.new("ShaderNodeOutputMaterial")
unlit.node_tree.links.new(background.outputs["Background"], output.inputs["Surface"])
plane.data.materials.append(unlit)

bpy.ops.mesh.primitive_cone_add(vertices=24, radius1=0.4, depth=1.2, location=(0.0, 0.0, 0.0))
cone = bpy.context.active_object
bronze = bpy.data.materials.new("bronze")
bronze.use_nodes = True
principled = next(n for n in bronze.node_tree.nodes if n.type == "BSDF_PRINCIPLED")
principled.inputs["Base Color"].default_value = (0.6, 0.4, 0.2, 1.0)
principled.inputs["Metallic"].default_value = 1.0
principled.inputs["Roughness"].default_value = 0.35
cone.data.materials.append(bronze)
for i in range(6):
    copy = cone if i == 0 else cone.copy()  # a linked duplicate: the same mesh
    if i:
        bpy.context.collection.objects.link(copy)
    copy.location = (-4.0 + 1.6 * i, 3.0, 0.8 + 0.3 * (i % 2))
    copy.rotation_euler = (0.3 * i, 0.5 * i, 0.2)
    copy.scale = (1.0 + 0.1 * i, 1.0, 1.3 - 0.1 * i)

bpy.ops.export_scene.gltf(filepath=target, export_format="GLB", export_tangents=True, export_colors=True,
                          export_texcoords=True, export_normals=True)
