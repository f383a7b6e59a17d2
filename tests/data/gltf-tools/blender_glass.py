# Run by make_fixtures.sh inside Blender (blender --background --python ...):
# builds a small glasshouse in Blender (a floor, a back wall, three coloured
# blocks, and tinted glass panes whose material Blender blends: Alpha below 1,
# blend mode BLEND) and writes it with Blender's glTF exporter, so that a file
# with alphaMode BLEND comes from a real tool. Two panes stand in front of the
# blocks, one crosses in front of the wall's edge against the sky, and one lies
# flat over a block, so that glass covers opaque surfaces, other glass, and
# nothing.
import sys

import bpy

target = sys.argv[sys.argv.index("--") + 1:][0]
bpy.ops.wm.read_factory_settings(use_empty=True)


def material(name, color, alpha=1.0, roughness=0.5):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = next(n for n in m.node_tree.nodes if n.type == "BSDF_PRINCIPLED")
    bsdf.inputs["Base Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    if alpha < 1.0:
        bsdf.inputs["Alpha"].default_value = alpha
        m.blend_method = "BLEND"
        m.use_backface_culling = False
    return m


def add(obj, mat):
    obj.data.materials.append(mat)
    return obj


bpy.ops.mesh.primitive_plane_add(size=12.0, location=(0.0, 0.0, 0.0))
add(bpy.context.object, material("floor", (0.7, 0.68, 0.62)))
bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 4.0, 1.5), scale=(10.0, 0.3, 3.0))
add(bpy.context.object, material("wall", (0.75, 0.7, 0.66)))
for x, color in ((-2.0, (0.8, 0.2, 0.15)), (0.0, (0.2, 0.7, 0.25)), (2.0, (0.2, 0.3, 0.8))):
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(x, 1.5, 0.5))
    add(bpy.context.object, material(f"block{x:+.0f}", color))

panes = (
    ((-1.0, -0.5, 1.0), (0.0, 0.0, 0.0), (2.4, 2.0, 1.0), (0.2, 0.45, 1.0), 0.55),
    ((1.2, -1.5, 1.2), (0.0, 0.0, 0.3), (2.4, 2.4, 1.0), (1.0, 0.4, 0.1), 0.5),
    ((4.5, 2.0, 2.5), (0.0, 0.0, -0.6), (3.0, 5.0, 1.0), (0.3, 1.0, 0.3), 0.45),
    ((2.0, 1.5, 1.3), (-1.5708, 0.0, 0.0), (1.6, 1.6, 1.0), (1.0, 0.9, 0.3), 0.6),
)
for i, (location, rotation, scale, color, alpha) in enumerate(panes):
    # Standing in Blender's XZ plane (width, height) unless turned back flat.
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=location, rotation=(1.5708 + rotation[0], rotation[1], rotation[2]))
    pane = bpy.context.object
    pane.scale = scale
    add(pane, material(f"glass{i}", color, alpha, roughness=0.1))

bpy.ops.export_scene.gltf(filepath=target, export_format="GLB", export_apply=True)
