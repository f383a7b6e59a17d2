#!/usr/bin/env python3
"""make_big_texture.py OUT_DIR: writes the texture-limit test data.

quadrants-16384.png is a 16384x16384 texture of four solid quadrants (red, green,
blue, white); quadrants-64.png is the same picture in 64x64 pixels, small enough
for any context. big-texture.gltf and small-texture.gltf each show one of them
on a square, as emission on a black surface, so lights do not change what the
camera sees.
The PNG is written row by row (Up-filtered rows of a quadrant deflate to almost
nothing), so the 1 GiB image costs about 1 MB on disk and no memory to make.
"""
import base64
import json
import struct
import sys
import zlib
from pathlib import Path

COLOURS = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)]  # top left, top right, bottom left, bottom right


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def write_png(path, size):
    half = size // 2
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)))
        deflate = zlib.compressobj(9)
        data = bytearray()
        for y in range(size):
            top = y < half
            if y in (0, half):
                left, right = (COLOURS[0], COLOURS[1]) if top else (COLOURS[2], COLOURS[3])
                row = bytes(left) * half + bytes(right) * (size - half)
                data += deflate.compress(b"\x00" + row)
            else:
                data += deflate.compress(b"\x02" + bytes(size * 3))  # Up filter: same as the row above
            if len(data) > 1 << 20:
                out.write(chunk(b"IDAT", bytes(data)))
                data.clear()
        data += deflate.flush()
        out.write(chunk(b"IDAT", bytes(data)))
        out.write(chunk(b"IEND", b""))


def write_gltf(path, image):
    positions = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    normals = [(0, 0, 1)] * 4
    uvs = [(0, 1), (1, 1), (1, 0), (0, 0)]
    indices = [0, 1, 2, 0, 2, 3]
    blob = b"".join(struct.pack("<3f", *p) for p in positions) + b"".join(struct.pack("<3f", *n) for n in normals)
    blob += b"".join(struct.pack("<2f", *t) for t in uvs) + struct.pack("<6H", *indices)
    gltf = {
        "asset": {"version": "2.0", "generator": "tests/data/make_big_texture.py"},
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "images": [{"uri": image}],
        "textures": [{"source": 0}],
        "materials": [{"name": "quadrants", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
                       "emissiveFactor": [1, 1, 1], "emissiveTexture": {"index": 0}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
    }
    Path(path).write_text(json.dumps(gltf, indent=1) + "\n")


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    write_png(out / "quadrants-16384.png", 16384)
    write_png(out / "quadrants-64.png", 64)
    write_gltf(out / "big-texture.gltf", "quadrants-16384.png")
    write_gltf(out / "small-texture.gltf", "quadrants-64.png")


if __name__ == "__main__":
    main()
