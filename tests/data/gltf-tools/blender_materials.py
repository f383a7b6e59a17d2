# Run by make_fixtures.sh inside Blender (blender --background --python ...):
# a rolling sheet of 24 x 16 faces, each with a material of its own (384 in
# all, each a different base colour, roughness and metalness), exported by
# Blender's glTF exporter as one mesh of 384 primitives. More materials than
# a tile of the visibility buffer can show, even with 4x MSAA (64 pixels x 4
# samples): its material tile lists must not grow with the materials.
import colorsys
import math
import sys

import bpy

target = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
columns, rows = 24, 16
bpy.ops.mesh.primitive_grid_add(x_subdivisions=columns, y_subdivisions=rows, size=6.0)
sheet = bpy.context.active_object
sheet.name = "sheet"
mesh = sheet.data
for v in mesh.vertices:
    v.co.z = 0.35 * math.sin(1.3 * v.co.x) * math.cos(0.9 * v.co.y)

for i, face in enumerate(mesh.polygons):
    material = bpy.data.materials.new(f"face-{i:03d}")
    material.use_nodes = True
    bsdf = material.node_tree.nodes["Principled BSDF"]
    r, g, b = colorsys.hsv_to_rgb((i * 0.618034) % 1.0, 0.55 + 0.45 * ((i * 7) % 5) / 4, 0.35 + 0.65 * ((i * 3) % 7) / 6)
    bsdf.inputs["Base Color"].default_value = (r, g, b, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.2 + 0.7 * ((i * 5) % 11) / 10
    bsdf.inputs["Metallic"].default_value = 1.0 if i % 6 == 0 else 0.0
    mesh.materials.append(material)
    face.material_index = i

bpy.ops.export_scene.gltf(filepath=target, export_format="GLB", use_selection=False)
