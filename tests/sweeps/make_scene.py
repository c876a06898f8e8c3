#!/usr/bin/env python3
"""make_scene.py FAMILY KNOB [--size WxH]: one scene of a sweep family, as
scene text on stdout.  Each family varies one knob; the rest of the scene
stays the same (docs/RESULTS.md, "Where each method fails").

  scale   three shapes on a floor, every length times KNOB (1e-3..1e3);
          the image should not change
  cluster_scale  the same, the objects in one cluster scaled by KNOB
"""
import sys


def scale_scene(s, w, h):
    def v(*xs):
        return " ".join("%.9g" % (x * s) for x in xs)
    return f"""# sweep family scale, knob {s:g}: three shapes on a floor, every length x {s:g}
camera {{ eye {v(0, 2.5, -7)}  look_at {v(0, 0.8, 0)}  up 0 1 0  fov 50 }}
resolution {w} {h}
background 0.1 0.12 0.2
options {{ max_depth 3  refractionless on }}
light point {{ colour 0.7 0.7 0.65  position {v(4, 8, -5)} }}
light parallel {{ colour 0.25 0.25 0.3  direction 0.4 -1 0.5 }}
material floor {{ colour 0.8 0.8 0.75  dic 0.25 drc 0.7  src 0.1 }}
material red   {{ colour 0.9 0.2 0.15  dic 0.15 drc 0.75  src 0.2  phong 40 }}
material green {{ colour 0.2 0.8 0.3  dic 0.15 drc 0.75  phong 20 }}
material blue  {{ colour 0.2 0.35 0.9  dic 0.15 drc 0.7  src 0.3  phong 60 }}
box {{ material floor  min {v(-6, -0.5, -4)}  max {v(6, 0, 8)} }}
sphere {{ material red  centre {v(-1.6, 0.8, 0.5)}  radius {v(0.8)} }}
box {{ material green  min {v(-0.3, 0, 1.2)}  max {v(1.1, 1.4, 2.4)} }}
ellipsoid {{ material blue  centre {v(1.9, 0.6, -0.3)}  radii {v(0.5, 0.6, 0.9)} }}
"""


def cluster_scale_scene(s, w, h):
    """The same scene with its objects in one cluster scaled by s (the
    camera and lights scaled by hand): the arithmetic must invert it."""
    text = scale_scene(1, w, h)
    head, body = text.split("box {", 1)
    def v(*xs):
        return " ".join("%.9g" % (x * s) for x in xs)
    head = head.replace("eye 0 2.5 -7  look_at 0 0.8 0", f"eye {v(0, 2.5, -7)}  look_at {v(0, 0.8, 0)}")
    head = head.replace("position 4 8 -5", f"position {v(4, 8, -5)}")
    head = head.replace("every length x 1", f"in a cluster scaled by {s:g}")
    return head + "cluster all {\n  scale %.9g\n  box {" % s + body + "}\n"


FAMILIES = {"scale": scale_scene, "cluster_scale": cluster_scale_scene}


def main():
    args = sys.argv[1:]
    w, h = 160, 120
    if "--size" in args:
        i = args.index("--size")
        w, h = (int(x) for x in args[i + 1].split("x"))
        del args[i:i + 2]
    if len(args) != 2 or args[0] not in FAMILIES:
        sys.exit("usage: make_scene.py FAMILY KNOB [--size WxH]; families: " + " ".join(FAMILIES))
    sys.stdout.write(FAMILIES[args[0]](float(args[1]), w, h))


main()
