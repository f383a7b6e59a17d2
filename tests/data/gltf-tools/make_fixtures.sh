#!/usr/bin/env bash
# Writes the fixtures in this folder with real third-party tools, the way users'
# files are written; run once by hand, its outputs are committed (CI never runs
# it). Needs Debian's gltfpack (0.18) and blender (3.4), and glTF-Transform's
# CLI from the npm registry (4.5.1: npm install @gltf-transform/cli@4.5.1).
#   tests/data/gltf-tools/make_fixtures.sh [../shared/testdata/gltf]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
testdata=$(realpath "${1:-$here/../../../../shared/testdata/gltf}")
gltf_transform=${GLTF_TRANSFORM:-npx gltf-transform}
cd "$here"

# A model with UVs, colours, tangents, a normal map and an unlit surface,
# exported by Blender's glTF exporter.
blender --background --python blender_colors.py -- "$testdata/blender-exports/teapot.gltf" blender-colors.glb
# Tinted glass panes (alphaMode BLEND) over and beside opaque blocks, by Blender.
blender --background --python blender_glass.py -- blender-glass.glb
# A sheet of 384 faces, each its own material (one mesh of 384 primitives), by Blender.
blender --background --python blender_materials.py -- blender-materials.glb

# EXT_meshopt_compression (and KHR_mesh_quantization unless -noq) by gltfpack;
# -mi writes EXT_mesh_gpu_instancing, whose transforms use the QUATERNION and
# EXPONENTIAL filters. (Not over subpass_scene_opaque: gltfpack 0.18 -mi moves
# its mirrored nodes, whose scale is -1 on every axis; an independent decode
# with glTF-Transform puts them where Atrium does.)
for source in "$testdata/blender-exports/teapot.gltf" "$testdata/blender-exports/torusknot.gltf" \
              "$testdata/blender-exports/subpass_scene_opaque.gltf"; do
  name=$(basename "$source" .gltf)
  for flags in "-c" "-cc" "-c -noq" "-cc -noq"; do
    gltfpack $flags -i "$source" -o "$name.gltfpack-$(echo $flags | tr -d - | tr ' ' '-').glb"
  done
done
gltfpack -cc -mi -i blender-colors.glb -o blender-colors.gltfpack-cc-mi.glb
gltfpack -c -i blender-colors.glb -o blender-colors.gltfpack-c.glb
gltfpack -cc -i blender-colors.glb -o blender-colors.gltfpack-cc.glb

# KHR_draco_mesh_compression by glTF-Transform: edgebreaker and sequential
# coding, float sources (which Draco quantises) and a KHR_mesh_quantization
# source (integer attributes, which it keeps exact).
$gltf_transform draco "$testdata/blender-exports/teapot.gltf" teapot.draco-edgebreaker.glb
$gltf_transform draco "$testdata/blender-exports/teapot.gltf" teapot.draco-sequential.glb --method sequential --quantize-position 16
$gltf_transform draco "$testdata/blender-exports/torusknot.gltf" torusknot.draco-edgebreaker.glb
gltfpack -i "$testdata/blender-exports/torusknot.gltf" -o /tmp/torusknot.gltfpack-quantized.glb
$gltf_transform draco /tmp/torusknot.gltfpack-quantized.glb torusknot.quantized.draco-edgebreaker.glb
$gltf_transform draco blender-colors.glb blender-colors.draco-edgebreaker.glb

# A JSON document that is not glTF, saved as .gltf: npm's package.json.
(cd "$(mktemp -d)" && npm init -y >/dev/null && cp package.json "$here/not-gltf.npm-package.gltf")
