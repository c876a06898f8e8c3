#!/usr/bin/env python3
"""make_fig9.py: writes fig9.scn, a scene in the manner of the paper's Fig. 9
(the scene of its Tables 2 and 3): a few thousand primitives in a hierarchy
of clusters made by hand (room -> table -> groups -> objects -> bands),
transparent and reflecting objects among them.  Deterministic.
Run: python3 host-tools/gen/make_fig9.py OUT.scn (`make` writes
build/scenes/fig9.scn)"""
import math
import sys

sys.dont_write_bytecode = True  # no __pycache__ left in host-tools/gen
from gen_args import out_operand  # noqa: E402 (beside this file)

HEADER = """# fig9.scn: a still life in the manner of the paper's Fig. 9, the scene of its
# Tables 2 and 3 (written by make_fig9.py; do not edit by hand).  A table in
# a room with a mirror wall: vases and wine glasses turned from triangles,
# a stack of glass and pearl balls, potted trees of ellipsoids, a
# chequerboard of boxes.  %(prims)d primitives in %(clusters)d clusters, all
# made by hand (room -> table -> groups -> objects -> bands of 24
# triangles);
# clear glass, coloured glass and mirrors among them.  512x480, as the
# paper's Table 2 ran.
camera { eye 0 3.9 -6.8  look_at 0 1.5 1.6  up 0 1 0  fov 56 }
resolution 512 480
background 0.5 0.6 0.75
options { max_depth 5 }
light point    { colour 0.62 0.6 0.55  position -5 10 -7 }
light parallel { colour 0.3 0.3 0.33  direction 1.2 -2 1.5 }
material floor  { colour 0.55 0.5 0.42  dic 0.3 drc 0.6 }
material wall   { colour 0.75 0.72 0.65  dic 0.3 drc 0.6 }
material mirror { colour 0.9 0.9 0.95  dic 0.02 drc 0.05  src 0.85  phong 120 }
material wood   { colour 0.5 0.3 0.15  dic 0.3 drc 0.6  src 0.06  phong 20 }
material dark   { colour 0.12 0.1 0.1  dic 0.3 drc 0.6  src 0.12  phong 40 }
material light  { colour 0.9 0.88 0.8  dic 0.3 drc 0.6  src 0.12  phong 40 }
material clear  { colour 0.95 0.97 1  dic 0.0 drc 0.04  src 0.06 trc 0.9  ior 1.5  phong 90 }
material ruby   { colour 1 0.35 0.35  dic 0.02 drc 0.06  src 0.06 trc 0.85  ior 1.5  phong 70 }
material jade    { colour 0.35 0.75 0.5  dic 0.25 drc 0.6  src 0.2  phong 50 }
material chrome { colour 0.8 0.82 0.85  dic 0.05 drc 0.1  src 0.75  phong 150 }
material pearl  { colour 0.9 0.85 0.8  dic 0.25 drc 0.65  src 0.15  phong 25 }
material leaf   { colour 0.25 0.55 0.2  dic 0.3 drc 0.65 }
material bark   { colour 0.4 0.28 0.18  dic 0.3 drc 0.65 }
material clay   { colour 0.7 0.35 0.2  dic 0.3 drc 0.6 }
"""


class Out:
    def __init__(self):
        self.lines = []
        self.prims = 0
        self.clusters = 1  # the root

    def put(self, depth, text):
        self.lines.append("  " * depth + text + "\n")

    def prim(self, depth, text):
        self.prims += 1
        self.put(depth, text)

    def open(self, depth, name, *placement):
        self.clusters += 1
        self.put(depth, "cluster %s {" % name)
        for p in placement:
            self.put(depth + 1, p)

    def close(self, depth):
        self.put(depth, "}")


def f(x):
    t = ("%.3f" % x).rstrip("0").rstrip(".")
    return "0" if t in ("-0", "") else t


def lathe(out, depth, name, material, profile, segments, band):
    """A surface of revolution about y from profile [(r, y), ...], its
    triangles in clusters of `band` profile steps (2 * segments each)."""
    out.open(depth, name)
    steps = len(profile) - 1
    for b0 in range(0, steps, band):
        out.open(depth + 1, "%s_band%d" % (name, b0 // band))
        for i in range(b0, min(b0 + band, steps)):
            (r0, y0), (r1, y1) = profile[i], profile[i + 1]
            for s in range(segments):
                a0 = 2 * math.pi * s / segments
                a1 = 2 * math.pi * (s + 1) / segments
                p00 = (r0 * math.cos(a0), y0, r0 * math.sin(a0))
                p01 = (r0 * math.cos(a1), y0, r0 * math.sin(a1))
                p10 = (r1 * math.cos(a0), y1, r1 * math.sin(a0))
                p11 = (r1 * math.cos(a1), y1, r1 * math.sin(a1))
                for tri in ((p00, p10, p11), (p00, p11, p01)):
                    # a cone's tip (r = 0) makes one of the two degenerate
                    if len({t for t in tri}) < 3:
                        continue
                    out.prim(depth + 2, "triangle { material %s %s }" % (material, " ".join(
                        "v %s %s %s" % (f(p[0]), f(p[1]), f(p[2])) for p in tri)))
        out.close(depth + 1)
    out.close(depth)


def vase_profile(k):
    prof = []
    for i in range(9):
        t = i / 8
        r = 0.22 + 0.18 * math.sin(math.pi * (0.15 + 0.85 * t)) - 0.08 * t + 0.03 * (k % 3) * t
        prof.append((r, 0.02 + (0.9 + 0.1 * (k % 2)) * t))
    return prof


def glass_profile():
    # foot, stem, bowl (outside only; a thin bowl reads as glass)
    return [(0.0, 0.01), (0.16, 0.01), (0.03, 0.04), (0.025, 0.3), (0.05, 0.34),
            (0.14, 0.42), (0.17, 0.52), (0.16, 0.64)]


def main():
    path = out_operand(__doc__)
    out = Out()
    body = []
    d = 0
    out.open(d, "room")
    out.prim(d + 1, "box { material floor  min -9 -0.5 -12  max 9 0 9 }")
    out.prim(d + 1, "box { material wall   min -9 0 8  max 9 8 8.5 }")
    out.prim(d + 1, "box { material mirror min -4 0.8 7.9  max 4 5 8 }")
    out.close(d)
    out.open(d, "table", "translate 0 0 1.5")
    out.prim(d + 1, "box { material wood  min -4.2 1.1 -2.4  max 4.2 1.25 2.4 }")
    out.open(d + 1, "legs")
    for i, (x, z) in enumerate([(-3.9, -2.1), (3.9, -2.1), (-3.9, 2.1), (3.9, 2.1)]):
        out.prim(d + 2, "box { material wood  min %g 0 %g  max %g 1.1 %g }" %
                 (x - 0.12, z - 0.12, x + 0.12, z + 0.12))
    out.close(d + 1)
    # vases along the back of the table, two groups
    for g in range(2):
        out.open(d + 1, "vases%d" % g, "translate %g 1.25 1.4" % (-2.4 + 4.8 * g))
        for k in range(4):
            mat = ["jade", "chrome", "ruby", "clay"][(k + g) % 4]
            x = -1.2 + 0.8 * k
            out.open(d + 2, "vase%d_%d" % (g, k), "scale 1 %g 1" % (1.0 + 0.25 * (k % 3)),
                     "translate %g 0 0" % x)
            lathe(out, d + 3, "vase%d_%d_body" % (g, k), mat, vase_profile(k + g), 12, 1)
            out.close(d + 2)
        out.close(d + 1)
    # wine glasses in the middle
    out.open(d + 1, "glasses", "translate 0 1.25 -0.2")
    for k in range(6):
        a = 2 * math.pi * k / 6
        out.open(d + 2, "glass%d" % k, "translate %s 0 %s" % (f(0.9 * math.cos(a)),
                                                              f(0.6 * math.sin(a))))
        lathe(out, d + 3, "glass%d_body" % k, "clear" if k % 3 else "ruby", glass_profile(),
              12, 1)
        out.close(d + 2)
    out.close(d + 1)
    # a stack of balls on the left front, a chequerboard on the right front
    out.open(d + 1, "stack", "translate -2.8 1.25 -1.3")
    r = 0.2
    for layer in range(4):
        n = 4 - layer
        out.open(d + 2, "stack_layer%d" % layer)
        for i in range(n):
            for j in range(n):
                x = (i - (n - 1) / 2) * 2 * r
                z = (j - (n - 1) / 2) * 2 * r
                y = r + layer * r * math.sqrt(2)
                mat = "clear" if (i + j + layer) % 3 == 0 else "pearl" if (i + j) % 2 else "chrome"
                out.prim(d + 3, "sphere { material %s  centre %s %s %s  radius %g }" %
                         (mat, f(x), f(y), f(z), r))
        out.close(d + 2)
    out.close(d + 1)
    out.open(d + 1, "board", "rotate 0 20 0", "translate 2.6 1.25 -1.2")
    for i in range(8):
        out.open(d + 2, "board_row%d" % i)
        for j in range(8):
            mat = "dark" if (i + j) % 2 else "light"
            out.prim(d + 3, "box { material %s  min %g 0 %g  max %g 0.06 %g }" %
                     (mat, -0.8 + 0.2 * j, -0.8 + 0.2 * i, -0.6 + 0.2 * j, -0.6 + 0.2 * i))
        out.close(d + 2)
    # pieces: glass pawns on the board
    out.open(d + 2, "pieces")
    for k in range(8):
        out.open(d + 3, "pawn%d" % k, "translate %g 0.06 %g" % (-0.7 + 0.2 * k, -0.5))
        out.prim(d + 4, "ellipsoid { material clear  centre 0 0.05 0  radii 0.07 0.05 0.07 }")
        out.prim(d + 4, "ellipsoid { material clear  centre 0 0.14 0  radii 0.035 0.09 0.035 }")
        out.prim(d + 4, "sphere { material clear  centre 0 0.25 0  radius 0.055 }")
        out.close(d + 3)
    out.close(d + 2)
    out.close(d + 1)
    out.close(d)
    # potted trees on the floor either side of the table
    for t, (x, z) in enumerate([(-6.2, 3.5), (6.2, 3.5), (-6.5, -2.5), (6.5, -2.5)]):
        out.open(d, "tree%d" % t, "translate %g 0 %g" % (x, z))
        lathe(out, d + 1, "pot%d" % t, "clay",
              [(0.0, 0.0), (0.45, 0.0), (0.6, 0.7), (0.55, 0.75)], 16, 3)
        out.prim(d + 1, "box { material bark  min -0.08 0.7 -0.08  max 0.08 2.6 0.08 }")
        for b in range(5):
            a = 2 * math.pi * b / 5 + t
            out.open(d + 1, "tree%d_branch%d" % (t, b),
                     "translate %s %g %s" % (f(0.45 * math.cos(a)), 2.4 + 0.25 * b,
                                             f(0.45 * math.sin(a))))
            for l in range(12):
                u = 2 * math.pi * l / 12
                v = 0.5 * math.sin(3 * u + b)
                out.prim(d + 2, "ellipsoid { material leaf  centre %s %s %s  radii 0.16 0.07 0.11 }"
                         % (f(0.4 * math.cos(u)), f(0.15 * v), f(0.4 * math.sin(u))))
            out.close(d + 1)
        out.close(d)
    text = HEADER % {"prims": out.prims, "clusters": out.clusters} + "".join(out.lines)
    with open(path, "w") as fh:
        fh.write(text)


if __name__ == "__main__":
    main()
