#!/usr/bin/env python3
"""tests/models/make_ply_twins.py OUTDIR: one small PLY model written three
times, as ASCII (twin-ascii.ply), binary little endian (twin-le.ply) and
binary big endian (twin-be.ply): the same header but for its format line,
vertex properties float x y z (and one more float with a name longer than
15 characters, which the reader skips), faces as list uchar int
vertex_indices (four triangles and a quad).  Every coordinate is a
dyadic fraction, so the text and the binary twins hold the same floats.
The test (tests/images/ply_binary.sh) writes them at run time: no binary
model is kept in the repository."""
import os
import struct
import sys

VERTS = [
    (0.0, 0.0, 0.0),
    (1.5, 0.0, 0.25),
    (1.25, 1.0, -0.5),
    (-0.25, 1.25, 0.0),
    (0.5, 0.75, 1.5),
]
# counter-clockwise seen from outside; the last face a quad
FACES = [(0, 4, 1), (1, 4, 2), (2, 4, 3), (3, 4, 0), (0, 1, 2, 3)]
EXTRA = "surface_confidence_value"  # longer than 15 characters


def header(fmt):
    lines = [
        "ply",
        "format %s 1.0" % fmt,
        "comment tests/models/make_ply_twins.py",
        "element vertex %d" % len(VERTS),
        "property float x",
        "property float y",
        "property float z",
        "property float %s" % EXTRA,
        "element face %d" % len(FACES),
        "property list uchar int vertex_indices",
        "end_header",
    ]
    return ("\n".join(lines) + "\n").encode("ascii")


def ascii_body():
    out = ["%r %r %r 0.5" % v for v in VERTS]
    out += ["%d %s" % (len(f), " ".join(str(i) for i in f)) for f in FACES]
    return ("\n".join(out) + "\n").encode("ascii")


def binary_body(order):
    b = bytearray()
    for v in VERTS:
        b += struct.pack(order + "4f", v[0], v[1], v[2], 0.5)
    for f in FACES:
        b += struct.pack(order + "B%di" % len(f), len(f), *f)
    return bytes(b)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_ply_twins.py OUTDIR")
    out = sys.argv[1]
    twins = {
        "twin-ascii.ply": header("ascii") + ascii_body(),
        "twin-le.ply": header("binary_little_endian") + binary_body("<"),
        "twin-be.ply": header("binary_big_endian") + binary_body(">"),
    }
    for name, data in twins.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
