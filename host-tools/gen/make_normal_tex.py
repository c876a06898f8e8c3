#!/usr/bin/env python3
"""host-tools/gen/make_normal_tex.py OUTDIR: small UV-mapped models with normal
textures for the tests of imported normal maps (tests/images/normal_tex.sh,
tests/board/scene/render_maps.sh), written as OBJ + MTL + PNG, nothing checked in.

  grid.obj / grid-flat.obj / grid-plain.obj / grid-height.obj: a bent
      grid of N x N quads (smooth vertex normals, uv 0..1); grid-flat's
      material has a normal texture of the flat normal (RGB 128 128 255),
      grid-plain's none, grid.obj a tilted one (tilt.png), grid-height's
      the tilted one as a height texture (map_bump).
  quad-xneg.obj, quad-xpos, quad-yneg, quad-ypos: the square below, uv
      unturned, a normal texture tilted 30 degrees one way all over (x: along
      u, y: up the picture).
  quad-R-M.obj with tilt-R-M.png, R in 0 90 (degrees the uv turn, about
      the square's centre, against the geometry), M in plain mirror (u taken
      as 1 - u): one square of two triangles, and a normal texture of 4x4
      texels whose picture and normals turn (and mirror) with the uv, so
      that every point of the square sees the same normal in space;
      quad-90-still.obj the same but for the normals, left as they were
      (what a frame that ignored the uv would see); quad-0-plain.gltf the
      unturned square as glTF 2 (its v down the picture) with the same
      texture as its normalTexture.
  wide.obj, wide-normal.obj: a grid of 2 * 64 * 64 triangles with a colour
      texture, and with the tilted normal texture too (for counting the DM's
      preparation per triangle).
"""
import base64
import json
import math
import os
import struct
import sys


sys.dont_write_bytecode = True  # no __pycache__ left in host-tools/gen
from make_maps import write_png  # noqa: E402 (the scenes' PNG writer, beside this file)
from gen_args import out_operand  # noqa: E402


def png(path, rows):
    """rows: a list of rows of (r, g, b) bytes."""
    write_png(path, len(rows[0]), len(rows), lambda x, y: rows[y][x])


def enc(x):
    """a normal component -1..1 as its byte (2c/255 - 1); 255 - c is -x."""
    return int(round((x + 1) * 255 / 2))


def mtl(path, name, lines):
    with open(path, "w") as f:
        f.write("newmtl %s\nKd 0.8 0.75 0.7\nKa 0.2 0.2 0.2\nKs 0.3 0.3 0.3\nNs 40\n" % name)
        for line in lines:
            f.write(line + "\n")


def grid(path, mtlname, n, bend=True, normals=True, tris=True):
    with open(path, "w") as f:
        f.write("mtllib %s\no grid\n" % mtlname)
        for j in range(n + 1):
            for i in range(n + 1):
                x, y = 2.0 * i / n - 1, 2.0 * j / n - 1
                z = 0.25 * math.cos(1.3 * x) * math.cos(0.9 * y) if bend else 0
                f.write("v %.6f %.6f %.6f\n" % (x, y, z))
                f.write("vt %.6f %.6f\n" % (i / n, j / n))
                if normals:
                    dzx = -0.25 * 1.3 * math.sin(1.3 * x) * math.cos(0.9 * y)
                    dzy = -0.25 * 0.9 * math.cos(1.3 * x) * math.sin(0.9 * y)
                    ln = math.sqrt(dzx * dzx + dzy * dzy + 1)
                    f.write("vn %.6f %.6f %.6f\n" % (-dzx / ln, -dzy / ln, 1 / ln))
        f.write("usemtl m\n")
        for j in range(n):
            for i in range(n):
                a = j * (n + 1) + i + 1
                q = (a, a + 1, a + n + 2, a + n + 1)
                # as two triangles (the library may split a quad either way)
                faces = [(q[0], q[1], q[2]), (q[0], q[2], q[3])] if tris else [q]
                fmt = "%d/%d/%d" if normals else "%d/%d"
                for fc in faces:
                    f.write("f " + " ".join(fmt % ((k, k, k) if normals else (k, k)) for k in fc) + "\n")


# the tilted normals of the quads' texture, texel (i, j) of 4x4 with row 0
# at the top: each tilts its own way, never flat
def tilt_at(i, j):
    a = 0.3 + 0.4 * i + 1.1 * j
    s = 0.45 + 0.1 * ((i + j) % 2)
    return (s * math.cos(a), s * math.sin(a))


def quad(out, rot, mirror, follow=True):
    """the square (-1..1)^2 at z 0, facing +z; its uv turned by rot degrees
    (0 or 90) and mirrored in u; the texture's picture and normals follow."""
    tag = "%d-%s" % (rot, "mirror" if mirror else "plain" if follow else "still")
    n = 4
    # uv (u, v) of the unturned square at geometry (x, y): u = (x+1)/2, v = (y+1)/2
    # (v up the picture).  Turned by 90: (u', v') = (1 - v, u); mirrored: u'' = 1 - u'.
    def uv(u, v):
        if rot == 90:
            u, v = 1 - v, u
        if mirror:
            u = 1 - u
        return u, v

    # texel (ii, jj) of the turned picture holds the unturned texel at the
    # same point of the square (its centre's uv taken back), with the
    # normal (x, y) written in the turned frame, the same vector in space:
    # turned, u' = 1 - v and v' = u, so dP/du' = -dP/dv and dP/dv' = dP/du:
    # (x', y') = (-y, x); mirrored, dP/du'' = -dP/du': x'' = -x'.  The
    # encoding negates exactly (-x is byte 255 - c).
    rows = []
    for jj in range(n):
        row = []
        for ii in range(n):
            u2, v2 = (ii + 0.5) / n, 1 - (jj + 0.5) / n
            if mirror:
                u2 = 1 - u2
            if rot == 90:
                u2, v2 = v2, 1 - u2
            i, j = int(u2 * n), int((1 - v2) * n)
            cx, cy = tilt_at(i, j)
            bx, by = enc(cx), enc(cy)
            if rot == 90 and follow:
                bx, by = 255 - by, bx
            if mirror and follow:
                bx = 255 - bx
            row.append((bx, by, enc(math.sqrt(1 - cx * cx - cy * cy))))
        rows.append(row)
    png(os.path.join(out, "tilt-%s.png" % tag), rows)
    mtl(os.path.join(out, "quad-%s.mtl" % tag), "m", ["norm tilt-%s.png" % tag])
    with open(os.path.join(out, "quad-%s.obj" % tag), "w") as f:
        f.write("mtllib quad-%s.mtl\no quad\n" % tag)
        for (x, y) in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            u, v = uv((x + 1) / 2, (y + 1) / 2)
            f.write("v %d %d 0\nvt %g %g\n" % (x, y, u, v))
        f.write("usemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")


def gltf_quad(out, name, texture):
    """the unturned square of quad() as glTF 2 (uv with v down the picture,
    glTF's way: (u, 1 - v)), its material's normalTexture the given image."""
    pos = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    uv = [((x + 1) / 2, 1 - (y + 1) / 2) for (x, y, _) in pos]
    data = (b"".join(struct.pack("<3f", *p) for p in pos) +
            b"".join(struct.pack("<2f", *t) for t in uv) +
            struct.pack("<6H", 0, 1, 2, 0, 2, 3))
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "quad"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                    "indices": 2, "material": 0}]}],
        "materials": [{"name": "m", "normalTexture": {"index": 0},
                       "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.75, 0.7, 1]}}],
        "textures": [{"source": 0}], "images": [{"uri": texture}],
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [-1, -1, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    with open(os.path.join(out, name + ".gltf"), "w") as f:
        json.dump(doc, f)


def main():
    out = out_operand(__doc__)
    os.makedirs(out, exist_ok=True)
    png(os.path.join(out, "flat.png"), [[(128, 128, 255)] * 4 for _ in range(4)])
    png(os.path.join(out, "tilt.png"),
        [[(enc(tilt_at(i, j)[0]), enc(tilt_at(i, j)[1]),
           enc(math.sqrt(1 - tilt_at(i, j)[0] ** 2 - tilt_at(i, j)[1] ** 2)))
          for i in range(4)] for j in range(4)])
    png(os.path.join(out, "colour.png"),
        [[(60 + 40 * i, 200 - 30 * j, 90 + 20 * ((i + j) % 3)) for i in range(4)] for j in range(4)])
    for name, lines in (("grid-flat", ["norm flat.png"]), ("grid-plain", []),
                        ("grid", ["norm tilt.png"]),
                        ("grid-height", ["map_bump tilt.png"])):
        mtl(os.path.join(out, name + ".mtl"), "m", lines)
        grid(os.path.join(out, name + ".obj"), name + ".mtl", 6)
    # one tilt all over the square, 30 degrees each way
    for name, (x, y) in (("xneg", (-0.5, 0)), ("xpos", (0.5, 0)), ("yneg", (0, -0.5)),
                         ("ypos", (0, 0.5))):
        png(os.path.join(out, "tilt-%s.png" % name),
            [[(enc(x), enc(y), enc(math.sqrt(1 - x * x - y * y)))] * 2] * 2)
        mtl(os.path.join(out, "quad-%s.mtl" % name), "m", ["norm tilt-%s.png" % name])
        with open(os.path.join(out, "quad-%s.obj" % name), "w") as f:
            f.write("mtllib quad-%s.mtl\no quad\n" % name)
            for (x_, y_) in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                f.write("v %d %d 0\nvt %g %g\n" % (x_, y_, (x_ + 1) / 2, (y_ + 1) / 2))
            f.write("usemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")
    for name, lines in (("wide", ["map_Kd colour.png"]),
                        ("wide-normal", ["map_Kd colour.png", "norm tilt.png"])):
        mtl(os.path.join(out, name + ".mtl"), "m", lines)
        grid(os.path.join(out, name + ".obj"), name + ".mtl", 64, normals=False, tris=False)
    # wide.obj is 64 x 64 quads; the DM counts are per triangle (8192)
    for rot in (0, 90):
        for mirror in (False, True):
            quad(out, rot, mirror)
    quad(out, 90, False, follow=False)
    gltf_quad(out, "quad-0-plain", "tilt-0-plain.png")


main()
