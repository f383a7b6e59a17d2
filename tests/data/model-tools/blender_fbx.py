# Run by make_fixtures.sh inside Blender: imports a glTF with Blender's importer and
# exports it with Blender's FBX exporter, Z or Y up.
import sys, bpy, numpy
numpy.bool = bool
src, dst, up = sys.argv[sys.argv.index("--") + 1:][:3]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=src)
bpy.ops.export_scene.fbx(filepath=dst, axis_up=up, axis_forward='-Y' if up == 'Z' else '-Z', path_mode='COPY', embed_textures=False)
