#!/usr/bin/env python3
"""make_city.py: writes city.scn, a scene of many objects in nested clusters
(city -> district -> block -> building), the kind of hierarchy the paper's
bounding boxes and screen clipping are measured on.  Deterministic: the
"random" heights come from a fixed formula.
Run: python3 host-tools/gen/make_city.py OUT.scn (`make` writes
build/scenes/city.scn; its map, maps/bricks.png, is looked for beside OUT)"""
import sys

sys.dont_write_bytecode = True  # no __pycache__ left in host-tools/gen
from gen_args import out_operand  # noqa: E402 (beside this file)

HEADER = """# city.scn: many objects in nested clusters (written by make_city.py).
# 4 districts x 4 blocks x 4 buildings, each building a box with an
# ellipsoid dome or a four-triangle roof: 227 primitives, 86 clusters
# (the root, the city, 4 districts, 16 blocks, 64 buildings).
camera { eye -13 15 -21  look_at 0 0 1  up 0 1 0  fov 50 }
resolution 320 240
background 0.6 0.7 0.9
options { max_depth 3 }
light parallel { colour 0.55 0.52 0.45  direction 1 -2 1.2 }
light point    { colour 0.35 0.35 0.4  position -10 12 -8 }
map bricks colour { image "maps/bricks.png"  repeat 2 3 }
material ground { colour 0.35 0.4 0.35  dic 0.3 drc 0.6 }
material street { colour 0.3 0.3 0.32  dic 0.3 drc 0.6  src 0.1 }
material brick  { colour 1 1 1  dic 0.25 drc 0.7  colour_map bricks }
material stone  { colour 0.8 0.78 0.7  dic 0.25 drc 0.7 }
material glassy { colour 0.5 0.65 0.8  dic 0.15 drc 0.5  src 0.35  phong 60 }
material dome   { colour 0.3 0.6 0.45  dic 0.2 drc 0.7  src 0.2  phong 30 }
material roof   { colour 0.6 0.25 0.2  dic 0.25 drc 0.7 }
box { material ground  min -14 -1 -14  max 14 0 14 }
box { material street  min -12 0 -0.4  max 12 0.02 0.4 }
box { material street  min -0.4 0 -12  max 0.4 0.02 12 }
"""


def height(i):
    return 1.0 + ((i * 7919) % 13) / 5.0


def building(out, n, x, z, indent):
    h = height(n)
    wall = ["brick", "stone", "glassy"][n % 3]
    p = " " * indent
    out.append(f"{p}cluster b{n} {{\n")
    out.append(f"{p}  translate {x:g} 0 {z:g}\n")
    out.append(f"{p}  box {{ material {wall}  min -0.6 0 -0.6  max 0.6 {h:.2f} 0.6 }}\n")
    if n % 2 == 0:
        out.append(f"{p}  ellipsoid {{ material dome  centre 0 {h:.2f} 0  radii 0.5 0.45 0.5 }}\n")
    else:
        top = h + 0.7
        for (ax, az, bx, bz) in [(-0.6, -0.6, 0.6, -0.6), (0.6, -0.6, 0.6, 0.6),
                                 (0.6, 0.6, -0.6, 0.6), (-0.6, 0.6, -0.6, -0.6)]:
            out.append(f"{p}  triangle {{ material roof  v {ax:g} {h:.2f} {az:g}  "
                       f"v {bx:g} {h:.2f} {bz:g}  v 0 {top:.2f} 0 }}\n")
    out.append(f"{p}}}\n")


def main():
    path = out_operand(__doc__)
    out = [HEADER, "cluster city {\n"]
    n = 0
    for d, (dx, dz) in enumerate([(-6, -6), (6, -6), (-6, 6), (6, 6)]):
        out.append(f"  cluster district{d} {{\n    translate {dx} 0 {dz}\n")
        if d % 2:
            out.append("    rotate 0 90 0\n")
        for b, (bx, bz) in enumerate([(-2.6, -2.6), (2.6, -2.6), (-2.6, 2.6), (2.6, 2.6)]):
            out.append(f"    cluster block{d}_{b} {{\n      translate {bx} 0 {bz}\n")
            for (x, z) in [(-0.8, -0.8), (0.8, -0.8), (-0.8, 0.8), (0.8, 0.8)]:
                building(out, n, x, z, 6)
                n += 1
            out.append("    }\n")
        out.append("  }\n")
    out.append("}\n")
    with open(path, "w") as f:
        f.write("".join(out))


main()
