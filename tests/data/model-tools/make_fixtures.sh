#!/usr/bin/env bash
# Writes the fixtures in this folder with third-party tools, run once by hand
# (CI never runs it); the outputs are committed. Needs Debian's assimp-utils,
# blender (3.4) and imagemagick (6.9).
#   tests/data/model-tools/make_fixtures.sh [../shared/testdata]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
testdata=$(realpath "${1:-$here/../../../../shared/testdata}")
cd "$here"
im=/usr/bin/convert  # ImageMagick's own, not a stand-in earlier on PATH

# OBJ + MTL by assimp's exporter; the cube's MTL names Cube_BaseColor.png,
# which the tests copy beside it from ../shared.
assimp export "$testdata/gltf/tinygltf/Cube/Cube.gltf" cube.assimp.obj -fobj
assimp export "$testdata/gltf/blender-exports/torusknot.gltf" torusknot.assimp.obj -fobj
# FBX by Blender's exporter, one Z-up (as 3ds Max and Blender's default
# orientation write them) and one Y-up.
blender --background --python blender_fbx.py -- "$testdata/gltf/blender-exports/subpass_scene_opaque.gltf" subpass_scene_opaque.blender-zup.fbx Z
blender --background --python blender_fbx.py -- "$testdata/gltf/blender-exports/torusknot.gltf" torusknot.blender-yup.fbx Y

# DDS by ImageMagick (BC1 and BC3 with mip chains, uncompressed RGB and RGBA)
# from two of Sponza's textures, with their PNG twins.
textures=$testdata/scenes/sponza-crytek/textures
$im "$textures/7268504077753552595.jpg" -resize 128x128 bricks.png
$im bricks.png -define dds:compression=dxt1 -define dds:mipmaps=7 bricks.bc1.dds
$im bricks.png -define dds:compression=none -define dds:mipmaps=0 bricks.rgba.dds
$im "$textures/5061699253647017043.png" -resize 128x128 leaves.png
$im leaves.png -define dds:compression=dxt5 -define dds:mipmaps=7 leaves.bc3.dds
$im leaves.png -define dds:compression=none -define dds:mipmaps=0 leaves.rgba.dds
# PGM and PPM at 8 and 16 bits a sample (stb_image misreads the 16-bit ones),
# with PNG twins, 16x16.
for depth in 8 16; do
  $im bricks.png -resize 16x16 -colorspace Gray -depth $depth bricks.grey$depth.pgm
  $im bricks.png -resize 16x16 -depth $depth bricks.rgb$depth.ppm
done
$im bricks.png -resize 16x16 -colorspace Gray -depth 8 bricks.grey8.png
$im bricks.png -resize 16x16 -depth 8 bricks.rgb8.png

# An asymmetric, single-sided, normal-mapped letter F by Blender, as modelled
# and mirrored (scale -1 on X): glTF and FBX keep the node's scale, OBJ bakes
# it; the FBX embeds the normal map mirror-f-bumps.png.
blender --background --python blender_mirrored.py -- mirror-f
