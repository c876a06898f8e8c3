#!/usr/bin/env bash
# SCN_MAX_LIGHTS (16) lights of the three kinds (6 point, 5 parallel, 5
# spot) over objects that shadow, reflect and transmit:
#  - the board's image equals the host build's, bit for bit, in float, soft
#    float and fixed point, with the paper's readings (the defaults:
#    ambient shadowed, shadows untinted, src(th) and trc(th) on the angle)
#    and with the other ones (ambient_shadowed off, shadow_tint on);
#  - the 16th light counts: without it the host's image differs;
#  - a 17th light is refused by the compiler, naming the limit and the
#    line, and links1 render refuses the scene before a board boots.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_lights16_float_2nc_dynamic render_lights16_soft_1nc_static \
    render_lights16_fixed_8nc_decreasing render_lights_other_readings_float render_lights_other_readings_fixed \
    render_lights_sixteenth_counts render_lights_17_refused || exit 0
SIZE=96x72

# lights_scene FILE N [OPTIONS]: the scene with the first N of the 17 lights.
lights_scene() {
    python3 - "$1" "$2" "${3:-}" <<'PY'
import sys
path, n, opts = sys.argv[1], int(sys.argv[2]), sys.argv[3]
out = ["camera { eye 0 4 -9  look_at 0 0.8 0  up 0 1 0  fov 50 }",
       "resolution 96 72", "background 0.05 0.05 0.1",
       "options { max_depth 3 %s }" % opts]
lights = []
for i in range(17):
    c = "%.3g %.3g %.3g" % (0.05 + 0.01 * (i % 3), 0.06, 0.05 + 0.01 * (i % 5))
    x, z = (i % 6) * 2.0 - 5, (i // 6) * 3.0 - 4
    if i % 3 == 0:
        lights.append("light point { colour %s  position %g 7 %g }" % (c, x, z))
    elif i % 3 == 1:
        lights.append("light parallel { colour %s  direction %g -2 %g }" % (c, 0.3 * (i % 4) - 0.5, 0.2 * (i % 3) + 0.1))
    else:
        lights.append("light spot { colour %s  position %g 6 %g  at %g 0 %g  cone 20  falloff 10 }"
                      % (c, x, z, x * 0.3, z * 0.3))
out += lights[:n]
out += ["material floor { colour 0.9 0.85 0.8  dic 0.2 drc 0.7  src 0.1 }",
        "material glass { colour 0.5 0.9 0.6  dic 0.02 drc 0.05  src 0.05 trc 0.9  ior 1.5  phong 40 }",
        "material red { colour 0.9 0.2 0.15  dic 0.2 drc 0.7  src 0.2  phong 30 }",
        "material chalk { colour 0.8 0.8 0.9  dic 0.3 drc 0.7 }",
        "box { material floor  min -6 -0.5 -5  max 6 0 6 }",
        "sphere { material glass  centre -1.2 1 0  radius 0.9 }",
        "ellipsoid { material red  centre 1.5 0.7 0.5  radii 0.6 0.7 0.5 }",
        "box { material chalk  min -0.4 0 2  max 0.6 1.6 2.8 }"]
open(path, "w").write("\n".join(out) + "\n")
PY
}

lights_scene "$RENDER_TMP/lights16.scn" 16
lights_scene "$RENDER_TMP/lights16-other.scn" 16 "ambient_shadowed off  shadow_tint on"
lights_scene "$RENDER_TMP/lights15.scn" 15
lights_scene "$RENDER_TMP/lights17.scn" 17

render_grid_one "$RENDER_TMP/lights16.scn" float 2 dynamic $SIZE
render_grid_one "$RENDER_TMP/lights16.scn" soft 1 static $SIZE
render_grid_one "$RENDER_TMP/lights16.scn" fixed 8 decreasing $SIZE
for a in float fixed; do
    name=render_lights_other_readings_$a
    ref=$(render_ref "$RENDER_TMP/lights16-other.scn" $a $SIZE)
    out="$RENDER_TMP/$name.ppm"
    if render_board $name "$out" "$RENDER_TMP/lights16-other.scn" -o "$out" --arith $a \
        --ncs 2 --size $SIZE; then
        render_same $name "$ref" "$out"
    fi
done
# The 16th light (a point light) lights the scene: 15 lights make another
# image; and the other readings make another image than the defaults.
r16=$(render_ref "$RENDER_TMP/lights16.scn" float $SIZE)
r15=$(render_ref "$RENDER_TMP/lights15.scn" float $SIZE)
if [ -s "$r16" ] && [ -s "$r15" ] && ! cmp -s "$r16" "$r15"; then
    echo "PASS render_lights_sixteenth_counts"
else
    echo "FAIL render_lights_sixteenth_counts: the images of 16 and 15 lights are the same or missing"
fi

# 17 lights: the compiler names the limit at the 17th light's line (5 + 16:
# after four lines of camera, resolution, background and options), and
# links1 render stops before any board boots.
msg=$("$LINKS1" compile "$RENDER_TMP/lights17.scn" -o "$RENDER_TMP/lights17.l1s" 2>&1)
rc=$?
rmsg=$(timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render "$RENDER_TMP/lights17.scn" \
    -o "$RENDER_TMP/lights17.ppm" --ncs 1 2>&1)
rrc=$?
echo "--- links1 compile lights17.scn (exit $rc): $msg"
echo "--- links1 render lights17.scn (exit $rrc): $rmsg"
if [ $rc -ne 0 ] && [ $rrc -ne 0 ] &&
    [[ "$msg" == *"lights17.scn:21:1: more than SCN_MAX_LIGHTS (16) lights"* ]] &&
    [[ "$rmsg" == *"more than SCN_MAX_LIGHTS (16) lights"* ]] && [[ "$rmsg" != *"boot"* ]] &&
    [ ! -e "$RENDER_TMP/lights17.l1s" ] && [ ! -e "$RENDER_TMP/lights17.ppm" ]; then
    echo "PASS render_lights_17_refused"
else
    echo "FAIL render_lights_17_refused: compile exit $rc '$msg', render exit $rrc '$rmsg'"
fi
