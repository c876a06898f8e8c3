#!/usr/bin/env python3
"""make_scene.py FAMILY KNOB [--size WxH]: one scene of a sweep family, as
scene text on stdout.  Each family varies one knob; the rest of the scene
stays the same (docs/results/sweeps.md).

  scale   three shapes on a floor, every length times KNOB (1e-3..1e3);
          the image should not change
  cluster_scale  the same, the objects in one cluster scaled by KNOB
                 (1e-6..1e6; the camera and lights scaled by hand)
  model_scale    the scale scene at KNOB with a model beside it (a glTF
                 file written to MODEL_DIR, default build/sweep-models)
                 whose node scales its unscaled pyramid by KNOB
  grazing        a floor seen KNOB degrees above it (90..0.1)
  coincident     a plate KNOB above the floor (1e-1..1e-6)
  thin_triangles triangles KNOB times longer than wide
  tir_chain      glass spheres in a row, max_depth KNOB (total internal
                 reflection inside them)
  ellipsoid_ratio an ellipsoid with axes KNOB : 1 : 1
  map_repeat     colour and bump maps repeated KNOB times
  density_steps  density spheres with thin features (small components in a
                 faint halo, two blobs joined by a thin neck), the root
                 finder's steps KNOB (64..2); the image should not change
Map paths are relative to the repository (run it from there, or set MAPS).
"""
import os
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


def model_gltf(s):
    """A glTF 2 file: one node scaled by s holding a pyramid of four
    triangles, 1.2 wide and 1.1 high, its vertices in an embedded buffer."""
    import base64, json, struct
    pos = [(-0.6, 0, -0.6), (0.6, 0, -0.6), (0.6, 0, 0.6), (-0.6, 0, 0.6), (0, 1.1, 0)]
    idx = [0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0]
    data = b"".join(struct.pack("<3f", *p) for p in pos) + struct.pack("<12H", *idx)
    lo = [min(p[i] for p in pos) for i in range(3)]
    hi = [max(p[i] for p in pos) for i in range(3)]
    doc = {
        "asset": {"version": "2.0", "generator": "links1 host-tools/gen/make_scene.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "scaled", "mesh": 0, "scale": [s, s, s]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 60},
                        {"buffer": 0, "byteOffset": 60, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 5, "type": "VEC3",
                       "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],
    }
    return json.dumps(doc, indent=1)


def model_scale_scene(s, w, h):
    """The scale scene at s with a model beside the shapes whose node
    scales its pyramid by s: the model statement's transform."""
    d = os.path.abspath(os.environ.get("MODEL_DIR", "build/sweep-models"))
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, "pyramid-%.9g.gltf" % s)
    with open(path, "w") as f:
        f.write(model_gltf(s))
    t = " ".join("%.9g" % (x * s) for x in (0.4, 0, -1.6))
    return (scale_scene(s, w, h).replace("every length x", "a model scaled by its node, every length x") +
            "cluster pyramid {\n  translate %s\n  model { file \"%s\"  material green }\n}\n" % (t, path))


COMMON = """background 0.1 0.12 0.2
light point {{ colour 0.7 0.7 0.65  position 4 8 -5 }}
light parallel {{ colour 0.25 0.25 0.3  direction 0.4 -1 0.5 }}
material floor {{ colour 0.8 0.8 0.75  dic 0.25 drc 0.7  src 0.1 }}
material red   {{ colour 0.9 0.2 0.15  dic 0.15 drc 0.75  src 0.2  phong 40 }}
material green {{ colour 0.2 0.8 0.3  dic 0.15 drc 0.75  phong 20 }}
material glass {{ colour 0.9 0.95 1  dic 0.02 drc 0.05  src 0.1 trc 0.85  fresnel 0.6  ior 1.5  phong 60 }}
resolution {w} {h}
"""


def grazing_scene(deg, w, h):
    """The eye looks at a floor from deg degrees above it (90 .. 0.1)."""
    import math
    a = math.radians(deg)
    eye = (0, 12 * math.sin(a), -12 * math.cos(a))
    return f"""# sweep family grazing, knob {deg:g}: a floor seen {deg:g} degrees above it
camera {{ eye {eye[0]:.9g} {eye[1]:.9g} {eye[2]:.9g}  look_at 0 0 0  up 0 1 0  fov 40 }}
options {{ max_depth 3 }}
""" + COMMON.format(w=w, h=h) + """box { material floor  min -40 -1 -40  max 40 0 40 }
sphere { material red  centre 0 0.5 0  radius 0.5 }
"""


def coincident_scene(gap, w, h):
    """A thin plate floats gap above the floor: near-coincident surfaces."""
    return f"""# sweep family coincident, knob {gap:g}: a plate {gap:g} above the floor
camera {{ eye 0 3 -6  look_at 0 0 0.5  up 0 1 0  fov 50 }}
options {{ max_depth 2 }}
""" + COMMON.format(w=w, h=h) + f"""box {{ material floor  min -6 -0.5 -4  max 6 0 8 }}
box {{ material green  min -1.5 {gap:.9g} -1  max 1.5 {gap + 0.05:.9g} 2 }}
sphere {{ material red  centre 1.5 {gap + 0.05 + 0.6:.9g} 0  radius 0.6 }}
"""


def thin_triangle_scene(aspect, w, h):
    """A fan of triangles aspect times longer than wide."""
    out = [f"""# sweep family thin_triangles, knob {aspect:g}: triangles {aspect:g} times longer than wide
camera {{ eye 0 3 -6  look_at 0 0.5 0.5  up 0 1 0  fov 50 }}
options {{ max_depth 2 }}
""" + COMMON.format(w=w, h=h) + "box { material floor  min -6 -0.5 -4  max 6 0 8 }\n"]
    width = 3.0 / aspect  # each triangle: this wide at its base, 3 long
    n = max(1, min(48, int(aspect)))
    for i in range(n):
        x0 = -1.5 + 3.0 * i / n
        out.append(f"triangle {{ material red  v {x0:.9g} 0.01 -0.5  v {x0 + width:.9g} 0.01 -0.5  "
                   f"v {x0 + width / 2:.9g} 2 2 }}\n")
    return "".join(out)


def tir_chain_scene(depth, w, h):
    """A row of glass spheres seen through each other; max_depth = knob."""
    d = int(depth)
    return f"""# sweep family tir_chain, knob {d}: glass spheres in a row, max_depth {d}
camera {{ eye 0 1.2 -6  look_at 0 0.8 2  up 0 1 0  fov 40 }}
options {{ max_depth {d}  refractionless on }}
""" + COMMON.format(w=w, h=h) + "box { material floor  min -6 -0.5 -4  max 6 0 12 }\n" + "".join(
        f"sphere {{ material glass  centre {0.15 * k:.9g} 0.9 {1.5 * k:.9g}  radius 0.8 }}\n" for k in range(6)
    ) + "box { material red  min -1 0 9  max 1 2 9.5 }\n"


def ellipsoid_ratio_scene(ratio, w, h):
    """An ellipsoid whose axes are ratio : 1 : 1 (the long one fixed)."""
    r = 2.0 / ratio
    return f"""# sweep family ellipsoid_ratio, knob {ratio:g}: axes 2 : {r:.3g} : {r:.3g}
camera {{ eye 0 2 -6  look_at 0 0.6 0  up 0 1 0  fov 45 }}
options {{ max_depth 2 }}
""" + COMMON.format(w=w, h=h) + f"""box {{ material floor  min -6 -0.5 -4  max 6 0 8 }}
cluster e {{
  rotate 0 0 20
  translate 0 1 0
  ellipsoid {{ material red  centre 0 0 0  radii 2 {r:.9g} {max(r, 0.3):.9g} }}
}}
"""


def map_repeat_scene(rep, w, h):
    """A checker colour map and a bump map repeated rep times on a floor."""
    return f"""# sweep family map_repeat, knob {rep:g}: maps repeated {rep:g} times
camera {{ eye 0 3 -6  look_at 0 0 1  up 0 1 0  fov 50 }}
options {{ max_depth 1 }}
map checker colour {{ image "{MAPS}/checker.png"  repeat {rep:.9g} {rep:.9g} }}
map dimples bump {{ image "{MAPS}/dimples.png"  repeat {rep:.9g} {rep:.9g}  depth 1 }}
material mapped {{ colour 1 1 1  dic 0.25 drc 0.7  colour_map checker  bump_map dimples }}
""" + COMMON.format(w=w, h=h) + """box { material mapped  min -6 -0.5 -4  max 6 0 8 }
"""


def density_steps_scene(steps, w, h):
    """Thin density features, found by a march of `steps` steps along a
    ray's span through the field: one density sphere of a faint halo (d =
    3, b = 0.2: no surface of its own, but every ray through it marches
    across its 6 units) and five small components (d = 0.9 down to 0.15,
    b = 1) whose surfaces, 0.15 to 0.9 across, lie anywhere along that
    span; and two blobs joined by a neck about 0.1 d thick (their sum is
    0.529 midway, the threshold 0.5)."""
    n = int(steps)
    out = [f"""# sweep family density_steps, knob {n}: thin density features, {n} root-finder steps
camera {{ eye 0 2.2 -6  look_at 0 1.4 0  up 0 1 0  fov 45 }}
options {{ max_depth 2  density_steps {n} }}
""" + COMMON.format(w=w, h=h) + "box { material floor  min -6 -0.5 -4  max 6 0 8 }\n"]
    small = ((-2.2, 1.2, 0.5, 0.9), (-1.1, 2.0, 0.2, 0.6), (0.0, 1.0, 0.0, 0.4),
             (1.1, 1.9, 0.3, 0.25), (2.2, 1.1, 0.6, 0.15))
    out.append("density { material red  threshold 0.6  component 0 1.4 1 3 0.2\n" + "".join(
        f"  component {x:g} {y:g} {z:g} {d:g} 1\n" for x, y, z, d in small) + "}\n")
    out.append("density { material green  threshold 0.5  component -0.58 2.9 1.5 1 1  "
               "component 0.58 2.9 1.5 1 1 }\n")
    return "".join(out)


MAPS = "scenes/maps"
FAMILIES = {"scale": scale_scene, "cluster_scale": cluster_scale_scene,
            "model_scale": model_scale_scene, "grazing": grazing_scene,
            "coincident": coincident_scene, "thin_triangles": thin_triangle_scene,
            "tir_chain": tir_chain_scene, "ellipsoid_ratio": ellipsoid_ratio_scene,
            "map_repeat": map_repeat_scene, "density_steps": density_steps_scene}


def main():
    args = sys.argv[1:]
    w, h = 160, 120
    if "--size" in args:
        i = args.index("--size")
        w, h = (int(x) for x in args[i + 1].split("x"))
        del args[i:i + 2]
    if len(args) != 2 or args[0] not in FAMILIES:
        sys.exit("usage: make_scene.py FAMILY KNOB [--size WxH]; families: " + " ".join(FAMILIES))
    global MAPS
    # the maps' directory as the scene names it: $MAPS (a copy below the
    # scene's own directory), else scenes/maps, which a scene outside it
    # reads only with --textures-from scenes/maps
    MAPS = os.path.abspath(os.environ.get("MAPS", "scenes/maps"))
    sys.stdout.write(FAMILIES[args[0]](float(args[1]), w, h))


main()
