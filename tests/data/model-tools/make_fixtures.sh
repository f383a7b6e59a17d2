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

# DDS by ImageMagick (BC1 and BC3 with mip chains, BC1 without one, uncompressed RGB and RGBA)
# from two of Sponza's textures, with their PNG twins.
textures=$testdata/scenes/sponza-crytek/textures
$im "$textures/7268504077753552595.jpg" -resize 128x128 bricks.png
$im bricks.png -define dds:compression=dxt1 -define dds:mipmaps=7 bricks.bc1.dds
$im bricks.png -define dds:compression=dxt1 -define dds:mipmaps=0 bricks.bc1-nomips.dds
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
# PNG and JPEG in the layouts libspng and TurboJPEG must read as stb_image did,
# 32x32: 16-bit RGBA, palette with transparency, grey with alpha, Adam7
# interlaced, a gAMA chunk of 1.0 (ignored, as glTF asks); baseline 4:2:0,
# progressive, greyscale and CMYK JPEG.
$im bricks.png -resize 32x32 bricks.32.png
$im leaves.png -resize 32x32 -depth 16 PNG64:leaves.rgba16.png
$im leaves.png -resize 32x32 -colors 64 PNG8:leaves.palette.png
$im leaves.png -resize 32x32 -colorspace Gray -define png:color-type=4 leaves.grey-alpha.png
$im bricks.32.png -interlace PNG bricks.interlaced.png
$im bricks.32.png -set gamma 1.0 -define png:include-chunk=gAMA bricks.gamma1.png
$im bricks.32.png -quality 90 -sampling-factor 2x2 bricks.baseline.jpg
$im bricks.32.png -quality 90 -interlace JPEG bricks.progressive.jpg
$im bricks.32.png -quality 90 -colorspace Gray bricks.grey.jpg
$im bricks.32.png -quality 90 -colorspace CMYK bricks.cmyk.jpg
# TGA and BMP, which stb_image reads for Atrium, with PNG twins: colour-mapped
# TGA from the top-left corner, the rest from the bottom-left, as most tools
# write it (colour-mapped run-length encoded, true-colour RLE, 32-bit with
# alpha); 24-bit BMP, 32-bit BMP with an alpha mask, and an RLE8 BMP
# (stb_image reads no RLE BMP: refused in one line). ImageMagick 6.9 writes
# a PNG's rows top row first under a bottom-left header (PIL and stb_image
# read it upside down): -flip -orient BottomLeft stores them as declared.
$im leaves.png -resize 32x32 -depth 8 PNG32:leaves.rgba8.png
$im bricks.rgb8.png -orient TopLeft bricks.rgb8.tga
$im bricks.rgb8.png -flip -orient BottomLeft -compress RLE bricks.rle.tga
$im bricks.rgb8.png -flip -orient BottomLeft -type TrueColor -compress RLE bricks.truecolor-rle.tga
$im leaves.rgba8.png -flip -orient BottomLeft leaves.rgba8.tga
$im bricks.rgb8.png -type TrueColor BMP3:bricks.rgb8.bmp
$im leaves.rgba8.png BMP:leaves.rgba8.bmp
$im bricks.rgb8.png -type Palette -compress RLE BMP3:bricks.rle8.bmp
# Formats stb_image reads that Atrium refuses as textures, 8x8.
for format in gif psd hdr; do $im bricks.png -resize 8x8 bricks.8.$format; done

# An asymmetric, single-sided, normal-mapped letter F by Blender, as modelled
# and mirrored (scale -1 on X): glTF and FBX keep the node's scale, OBJ bakes
# it; the FBX embeds the normal map mirror-f-bumps.png.
blender --background --python blender_mirrored.py -- mirror-f
