#!/usr/bin/env python3
"""Writes the hostile OBJ/MTL/FBX inputs in this folder from files real tools
wrote (tests/data/model-tools): truncated, bit-flipped, wrong lengths, huge
declared sizes, material libraries that are directories or missing. Run once
by hand; the outputs are committed and FuzzRegressions imports each one.
  tests/fuzz/regressions/model/make_hostile.py"""
import pathlib
import random
import struct

here = pathlib.Path(__file__).resolve().parent
tools = here.parents[2] / "data" / "model-tools"
fbx = (tools / "torusknot.blender-yup.fbx").read_bytes()
obj = (tools / "cube.assimp.obj").read_text()
mtl = (tools / "cube.assimp.mtl").read_text()

# Binary FBX (Blender's): cut short, bits flipped, an array's declared length huge.
(here / "fbx-truncated.fbx").write_bytes(fbx[:20000])
rng = random.Random(7)
flipped = bytearray(fbx)
for _ in range(64):
    i = rng.randrange(27, len(flipped))
    flipped[i] ^= 1 << rng.randrange(8)
(here / "fbx-bit-flipped.fbx").write_bytes(bytes(flipped))
huge = bytearray(fbx)
at = huge.find(b"Vertices") + len(b"Vertices")
assert huge[at:at + 1] == b"d", "the Vertices property is an array of doubles"
struct.pack_into("<I", huge, at + 1, 0x3FFFFFFF)  # arrayLength: 8 GiB of doubles
(here / "fbx-huge-array.fbx").write_bytes(bytes(huge))
wrong = bytearray(fbx)
struct.pack_into("<I", wrong, at + 9, 0xFFFFFFF0)  # compressedLength past the file's end
(here / "fbx-array-past-end.fbx").write_bytes(bytes(wrong))
# libassimp 5.2.5 takes a file for binary FBX by its first 18 bytes; the 19th
# and 20th (two spaces in every exporter's files) may be anything. Behind
# them, the Vertices array's zlib header broken: the stream does not inflate.
loose = bytearray(fbx)
loose[18:20] = b"XX"
struct.pack_into("<BB", loose, at + 13, 0xFF, 0xFF)
(here / "fbx-loose-magic-array-does-not-inflate.fbx").write_bytes(bytes(loose))

# OBJ (assimp's) naming material libraries that are missing, a directory
# (FuzzRegressions makes 'folder.mtl' one), outside the folder, or its own MTL
# cut mid-line and with huge or broken statements.
body = obj.split("\n", 1)[1] if obj.startswith("mtllib") else obj
def write_obj(name, header):
    (here / name).write_text(header + "\n" + body.replace("mtllib cube.assimp.mtl", ""))
write_obj("obj-missing-mtllib.obj", "mtllib nowhere.mtl")
write_obj("obj-mtllib-directory.obj", "mtllib folder.mtl")
write_obj("obj-mtllib-outside.obj", "mtllib ../../../../../../../../proc/self/status")
write_obj("obj-mtllib-empty-name.obj", "mtllib ")
write_obj("obj-broken-mtl.obj", "mtllib obj-broken-mtl.mtl")
(here / "obj-broken-mtl.mtl").write_text(mtl[: len(mtl) // 2] + "\nNs 1e999\nKd nan inf -inf\nmap_Kd " + "x" * 5000 + ".png\nnewmtl")
faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4000000000\nf -9 -8 -7\nf 1/99999999/1 2 3\nvt 1e999 nan\nf 1 2\n"
(here / "obj-bad-faces.obj").write_text(faces)
(here / "obj-truncated.obj").write_text(obj[: len(obj) * 2 // 3])
