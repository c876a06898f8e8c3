#!/usr/bin/env bash
# tests/images/maps.sh: normal and attribute maps on the host, in the three
# arithmetics of the board (double, float: also soft float's, fixed):
#   maps_flat_normal_ARITH: a normal map of the flat normal (given as texels
#     0 0 1, and as an image of RGB 128 128 255, repeated) gives the image
#     and the lost-precision count of no normal map, bit for bit;
#   maps_attribute_one_ARITH: attribute maps of 1 on dic, drc, src and trc
#     give the image and count of no maps;
#   maps_attribute_constant_ARITH: coefficients of 1 times a constant map
#     of 0.4 give the image and count of coefficients of 0.4;
#   maps_each_counts: in scenes/surface_maps.scn each map kind changes the
#     image (without its normal maps, its src map, its trc map: another
#     image), and the normal maps' texel borders add lost-precision pixels.
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/maps
mkdir -p "$out"
size=96x72

# the flat normal as an image: 2x2 of RGB 128 128 255
printf 'P6\n2 2\n255\n\x80\x80\xff\x80\x80\xff\x80\x80\xff\x80\x80\xff' >"$out/flat.ppm"

# scene NAME PLATE BALL GLASS: a plate, a ball and a glass ball whose
# materials end with the given statements.
scene() {
    cat >"$out/$1.scn" <<SCN
camera { eye 0 2.6 -7.5  look_at 0 0.9 0.5  up 0 1 0  fov 50 }
resolution 96 72
background 0.05 0.06 0.1
options { max_depth 4 }
light point    { colour 0.7 0.7 0.65  position 4 7 -5 }
light parallel { colour 0.25 0.25 0.3  direction -0.3 -1 0.5 }
map flat normal { size 1 1  texels 0 0 1 }
map flatimg normal { image "flat.ppm"  repeat 3 3 }
map one attribute { size 1 1  texels 1 }
map ones attribute { size 4 4  texels 1 1 1 1  1 1 1 1  1 1 1 1  1 1 1 1  repeat 3 3 }
map c40 attribute { size 1 1  texels 0.4 }
material floor { colour 1 1 1  dic 0.2 drc 0.8  src 0.3 }
material plate { colour 0.75 0.75 0.8  dic 0.2 drc 0.7  src 0.15  phong 40 $2 }
material ball  { colour 0.9 0.6 0.2  dic 0.15 drc 0.75  src 0.1  phong 60 $3 }
material glass { colour 0.8 1 0.9  ior 1.4 $4 }
box { material floor  min -7 -0.5 -5  max 7 0 9 }
box { material plate  min -3.2 0 1.5  max -0.4 2.8 1.7 }
sphere { material ball   centre 1.6 0.9 0.8  radius 0.9 }
sphere { material glass  centre -0.5 0.7 -1.5  radius 0.7 }
SCN
}
glass="src 0.3 trc 0.6 dic 0.1 drc 0.5"
scene none "" "" "$glass"
scene flat "normal_map flat" "normal_map flatimg" "$glass"
scene one "src_map one drc_map ones" "" "$glass dic_map one trc_map ones src_map ones drc_map one"
scene c40 "src 0.4 dic 0.4 drc 0.4" "" "trc 0.4 drc 0.4"
scene c40map "src 1 src_map c40 dic 1 dic_map c40 drc 1 drc_map c40" "" \
    "trc 1 trc_map c40 drc 1 drc_map c40"

# render SCENE ARITH: the image (empty when the render failed), its log beside;
# --no-escalate: the arithmetic's own colours and doubts are what is compared
render() {
    local img="$out/$(basename "$1" .scn)-$2.ppm"
    rm -f "$img"
    build/links1 ref "$1" --arith "$2" --size $size --no-escalate -o "$img" >"$img.log" 2>&1
    echo "$img"
}
lost() { sed -nE 's/.* ([0-9]+) pixels in doubt.*/\1/p' "$1.log"; }

# same CHECK A B: PASS when both rendered and are equal, image and count
same() {
    local check=$1 a=$2 b=$3
    if [ ! -s "$a" ] || [ ! -s "$b" ]; then
        echo "FAIL $check: a render failed: $(tail -n 1 "$a.log") / $(tail -n 1 "$b.log")"
    elif ! cmp -s "$a" "$b"; then
        echo "FAIL $check: the images differ ($(build/links1 compare "$a" "$b" 2>&1 | grep -m1 'largest difference'))"
    elif [ "$(lost "$a")" != "$(lost "$b")" ] || [ -z "$(lost "$a")" ]; then
        echo "FAIL $check: lost-precision pixels $(lost "$a") and $(lost "$b")"
    else
        echo "PASS $check"
    fi
}

for a in double float fixed; do
    none=$(render "$out/none.scn" $a)
    same maps_flat_normal_$a "$none" "$(render "$out/flat.scn" $a)"
    same maps_attribute_one_$a "$none" "$(render "$out/one.scn" $a)"
    same maps_attribute_constant_$a "$(render "$out/c40.scn" $a)" "$(render "$out/c40map.scn" $a)"
done

# Each kind of map in the scene counts, and normal maps flag texel borders.
# (its map images copied beside it: a map's image is read only from below
# the scene's directory, and a link out of it is refused)
cp scenes/surface_maps.scn "$out/sm.scn"
rm -rf "$out/maps"
cp -r scenes/maps "$out/maps"
sed 's/  normal_map rivets//' scenes/surface_maps.scn >"$out/sm-no-normal.scn"
sed 's/  src_map stripes//' scenes/surface_maps.scn >"$out/sm-no-src.scn"
sed 's/  trc_map spots//' scenes/surface_maps.scn >"$out/sm-no-trc.scn"
full=$(render "$out/sm.scn" float)
bad=
for v in no-normal no-src no-trc; do
    img=$(render "$out/sm-$v.scn" float)
    if [ ! -s "$img" ] || [ ! -s "$full" ]; then
        bad="$bad $v: render failed ($(tail -n 1 "$img.log"));"
    elif cmp -s "$full" "$img"; then
        bad="$bad $v: same image as with the map;"
    fi
done
with=$(lost "$full") without=$(lost "$out/sm-no-normal-float.ppm")
if [ -z "$bad" ] && [ -n "$with" ] && [ -n "$without" ] && [ "$with" -gt "$without" ]; then
    echo "PASS maps_each_counts"
else
    echo "FAIL maps_each_counts:$bad lost pixels with normal maps '$with', without '$without'"
fi
