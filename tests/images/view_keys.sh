#!/usr/bin/env bash
# tests/images/view_keys.sh: keys move the camera and the lights.  A frame
# halfway between two keys equals, bit for bit, a still scene written with
# the values the interpolation gives there (chosen exactly representable:
# halves of values with exact halves, a fov and spot angles whose tangent
# and cosines are such values), in double, float and fixed; after the last
# key the last key holds; and the keys do move the picture.
# Prints "PASS view_keys_NAME" / "FAIL view_keys_NAME: why".
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
T=$(mktemp -d /tmp/links1-view-keys.XXXXXX)
trap 'rm -rf "$T"' EXIT

# scene FILE CAMERA POINT SPOT PARALLEL: the test scene with the given
# camera and lights blocks (the geometry spans 12, more than any eye or
# light, so keyed and still scenes are scaled alike: scene_t.unit_exp).
scene() {
    cat >"$1" <<EOF
$2
resolution 64 48
animation { frames 4 }
$3
$4
$5
material floor { colour 1 1 1  dic 0.2 drc 0.7  src 0.1 }
material red   { colour 0.9 0.2 0.15  dic 0.2 drc 0.75  src 0.2  phong 40 }
material glass { colour 0.8 0.9 1  dic 0.02 drc 0.05  src 0.1 trc 0.85  ior 1.5 }
box { material floor  min -12 -0.5 -6  max 12 0 12 }
sphere { material red  centre -1 0.8 1  radius 0.8 }
ellipsoid { material glass  centre 1.2 0.9 -0.5  radii 0.5 0.9 0.5 }
box { material red  min 1.5 0 2  max 3 1.5 3 }
EOF
}

# Angles (degrees) whose tangents and cosines are exact: fov 2 atan(t) has
# tan(fov/2) = t; a spot's cone acos(c) has cosine c.
read -r FOV_A FOV_B FOV_M IN_A OUT_A IN_B OUT_B IN_M OUT_M < <(python3 -c '
import math
d = math.degrees
fov = lambda t: 2 * d(math.atan(t))
print(" ".join("%.17g" % v for v in (fov(0.5), fov(1.0), fov(0.75),
      d(math.acos(0.75)), d(math.acos(0.5)) - d(math.acos(0.75)),
      d(math.acos(0.875)), d(math.acos(0.75)) - d(math.acos(0.875)),
      d(math.acos(0.8125)), d(math.acos(0.625)) - d(math.acos(0.8125)))))')

scene "$T/keyed.scn" \
    "camera { eye 0 2 -8  look_at 0 1 0  up 0 1 0  fov $FOV_A
       key 0 { }
       key 2 { eye 2 3 -6  look_at 1 1 1  up 0.5 1 0  fov $FOV_B } }" \
    "light point { colour 1 0.5 0.25  position -4 8 -5
       key 0 { }  key 2 { colour 0.5 1 0.75  position 4 8 -3 } }" \
    "light spot { colour 0.5 0.5 0.5  position -2 6 -2  direction 1 -2 1  cone $IN_A falloff $OUT_A
       key 0 { }  key 2 { position 2 6 -2  direction -1 -2 1  cone $IN_B falloff $OUT_B } }" \
    "light parallel { colour 0.25 0.25 0.25  direction -1 -2 1
       key 0 { }  key 2 { direction 1 -2 3  colour 0.5 0.25 0 } }"
scene "$T/mid.scn" \
    "camera { eye 1 2.5 -7  look_at 0.5 1 0.5  up 0.25 1 0  fov $FOV_M }" \
    "light point { colour 0.75 0.75 0.5  position 0 8 -4 }" \
    "light spot { colour 0.5 0.5 0.5  position 0 6 -2  direction 0 -2 1  cone $IN_M falloff $OUT_M }" \
    "light parallel { colour 0.375 0.25 0.125  direction 0 -2 2 }"
scene "$T/end.scn" \
    "camera { eye 2 3 -6  look_at 1 1 1  up 0.5 1 0  fov $FOV_B }" \
    "light point { colour 0.5 1 0.75  position 4 8 -3 }" \
    "light spot { colour 0.5 0.5 0.5  position 2 6 -2  direction -1 -2 1  cone $IN_B falloff $OUT_B }" \
    "light parallel { colour 0.5 0.25 0  direction 1 -2 3 }"

# ref NAME SCENE ARITH [--frame N]: renders to $T/NAME.ppm; the error on failure
ref() {
    local name=$1 scn=$2 arith=$3; shift 3
    "$LINKS1" ref "$scn" -o "$T/$name.ppm" --arith "$arith" "$@" >"$T/$name.log" 2>&1 ||
        echo "links1 ref $scn --arith $arith $*: $(tail -n 1 "$T/$name.log")"
}

same() { # NAME A B WHAT
    local err
    if [ ! -s "$T/$2.ppm" ] || [ ! -s "$T/$3.ppm" ]; then
        echo "FAIL view_keys_$1: an image is missing: $(cat "$T/$2.log" "$T/$3.log" 2>/dev/null | tail -n 2 | tr '\n' ' ')"
    elif cmp -s "$T/$2.ppm" "$T/$3.ppm"; then
        echo "PASS view_keys_$1"
    else
        err=$("$LINKS1" compare "$T/$2.ppm" "$T/$3.ppm" 2>&1 | grep -m1 'largest' || true)
        echo "FAIL view_keys_$1: $4 differ ($err)"
    fi
}

for arith in double float fixed; do
    ref "keyed1-$arith" "$T/keyed.scn" $arith --frame 1
    ref "mid-$arith" "$T/mid.scn" $arith
    same "halfway_$arith" "keyed1-$arith" "mid-$arith" "frame 1 of the keyed scene and the still written with the interpolated camera and lights"
done
ref keyed3 "$T/keyed.scn" double --frame 3
ref end "$T/end.scn" double
same after_last_key keyed3 end "frame 3 (after the last key) and the still written with the last key's values"
ref keyed0 "$T/keyed.scn" double --frame 0
if [ -s "$T/keyed0.ppm" ] && [ -s "$T/keyed1-double.ppm" ] && ! cmp -s "$T/keyed0.ppm" "$T/keyed1-double.ppm"; then
    echo "PASS view_keys_move"
else
    echo "FAIL view_keys_move: frames 0 and 1 of the keyed scene are the same picture (or missing)"
fi
