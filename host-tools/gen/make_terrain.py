#!/usr/bin/env python3
"""make_terrain.py N OUT_DIR: a terrain of (N-1)^2 * 2 triangles as an ASCII
PLY (terrain.ply, heights of a few sines, the same bytes every time) and a
scene that places it with the model statement (terrain.scn): the big
imported model of tests/bench/bench_big.sh."""
import math
import os
import sys


def main():
    if len(sys.argv) != 3 or not sys.argv[1].isdigit() or not 2 <= int(sys.argv[1]) <= 2000:
        sys.exit("usage: make_terrain.py N OUT_DIR   (N: 2..2000 vertices a side)")
    n, out = int(sys.argv[1]), sys.argv[2]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "terrain.ply"), "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment links1 bench terrain\n")
        f.write(f"element vertex {n * n}\nproperty float x\nproperty float y\nproperty float z\n")
        f.write(f"element face {2 * (n - 1) * (n - 1)}\nproperty list uchar int vertex_indices\n")
        f.write("end_header\n")
        for j in range(n):
            for i in range(n):
                u, v = i / (n - 1), j / (n - 1)
                h = (0.08 * math.sin(11 * u) * math.cos(7 * v) + 0.05 * math.sin(23 * u + 17 * v)
                     + 0.02 * math.cos(41 * v - 29 * u))
                f.write(f"{u * 2 - 1:.6f} {h:.6f} {v * 2 - 1:.6f}\n")
        for j in range(n - 1):
            for i in range(n - 1):
                a = j * n + i
                f.write(f"3 {a} {a + n} {a + 1}\n3 {a + 1} {a + n} {a + n + 1}\n")
    with open(os.path.join(out, "terrain.scn"), "w") as f:
        f.write("# terrain.scn: the generated terrain, placed by the model statement\n"
                "camera { eye 0 2.2 -3.2  look_at 0 0 0.2  up 0 1 0  fov 45 }\n"
                "resolution 512 480\nbackground 0.1 0.12 0.2\n"
                "light point { colour 0.8 0.8 0.75  position 3 6 -4 }\n"
                "light parallel { colour 0.2 0.2 0.25  direction -0.3 -1 0.4 }\n"
                "material ground { colour 0.45 0.6 0.3  dic 0.2 drc 0.75 }\n"
                "cluster land { scale 2 2 2\n"
                "  model { file \"terrain.ply\"  material ground } }\n")


main()
