#!/usr/bin/env bash
# tests/images/normal_tex.sh: imported normal textures as tangent-space
# normal maps on the host (models written by host-tools/gen/make_normal_tex.py):
#   normal_tex_import_kinds: a model material's normal texture (OBJ `norm`)
#     is imported as a normal map, its height texture (`map_bump`) as a
#     bump map;
#   normal_tex_gltf: so is a glTF 2 material's normalTexture, and the glTF
#     square's triangles (vertices, their order, uv: glTF's v runs down the
#     picture) are the OBJ square's;
#   normal_tex_flat_ARITH (double, float, fixed): a bent, smooth, UV-mapped
#     grid with a normal texture of the flat normal (RGB 128 128 255) gives
#     the image and lost-precision count of the grid without it, bit for bit
#     (the import turns every triangle over the same way, docs/import.md);
#   normal_tex_tilts: the tilted normal texture changes the grid's image;
#   normal_tex_turned_ARITH: a square whose uv is turned 90 degrees against
#     its geometry, with its texture's picture and normals turned to match,
#     gives the image of the unturned square (every pixel within 1/255 but
#     for those counted as lost precision, taken out by --mark-lost):
#     the frame follows dP/du, not the first edge (which is the same edge in
#     both);
#   normal_tex_mirrored_ARITH: so does a square whose u is mirrored (and its
#     texture's picture and x with it), and one turned and mirrored: the
#     map's y follows the picture's up, -(n x T) on a mirrored mapping;
#   normal_tex_faces_light: a square tilted all over towards the light (the
#     import's light shines along +x, -y, +z of the scene: towards -u and
#     up the picture, since the file's z is negated and the square faces
#     the file's +z) is brighter than one tilted away, along u and along v:
#     the tilt comes out on the outward side, the right way round;
#   normal_tex_check_fails: the same comparison fails for the turned square
#     with its normals left unturned (what a frame ignoring the uv shows).
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/normal_tex
rm -rf "$out"
mkdir -p "$out"
size=96x72
if ! python3 host-tools/gen/make_normal_tex.py "$out" >"$out/make.log" 2>&1; then
    echo "FAIL normal_tex_models: $(tail -n 1 "$out/make.log")"
    exit 0
fi

# import NAME: NAME.obj to NAME.scn (the camera placed by the import)
import() {
    build/links1 import "$out/$1.obj" -o "$out/$1.scn" --camera auto >"$out/$1.import.log" 2>&1
}
# render NAME ARITH: the image (empty when the render failed), its log beside;
# --no-escalate: the arithmetic's own colours and doubts are what is compared
render() {
    local img="$out/$1-$2.ppm"
    rm -f "$img"
    build/links1 ref "$out/$1.scn" --arith "$2" --size $size --no-escalate -o "$img" >"$img.log" 2>&1
    echo "$img"
}
lost() { sed -nE 's/.* ([0-9]+) pixels in doubt.*/\1/p' "$1.log"; }
failed() { [ ! -s "$1" ] || [ ! -s "$2" ]; }
why() { echo "a render failed: $(tail -n 1 "$1.log") / $(tail -n 1 "$2.log")"; }

for m in grid grid-flat grid-plain grid-height quad-xneg quad-xpos quad-yneg \
    quad-ypos quad-0-plain quad-90-plain quad-0-mirror \
    quad-90-mirror quad-90-still; do
    import $m || echo "FAIL normal_tex_import_$m: $(tail -n 1 "$out/$m.import.log")"
done

# the glTF square: its normalTexture a normal map, its triangles (vertices,
# order, uv) those of the OBJ square
if build/links1 import "$out/quad-0-plain.gltf" -o "$out/quad-gltf.scn" --camera auto \
    >"$out/quad-gltf.import.log" 2>&1 &&
    grep -q '^map tilt-0-plain.png normal ' "$out/quad-gltf.scn" &&
    grep -q 'normal_map tilt-0-plain.png' "$out/quad-gltf.scn" &&
    [ "$(grep -c 'triangle {' "$out/quad-gltf.scn")" = 2 ] &&
    diff <(grep -o 'triangle {.*' "$out/quad-gltf.scn") <(grep -o 'triangle {.*' "$out/quad-0-plain.scn") \
        >"$out/quad-gltf.diff"; then
    echo "PASS normal_tex_gltf"
else
    echo "FAIL normal_tex_gltf: $(tail -n 1 "$out/quad-gltf.import.log") $(head -c 300 "$out/quad-gltf.diff" 2>/dev/null)"
fi

if grep -q '^map tilt.png normal ' "$out/grid.scn" && grep -q 'normal_map tilt.png' "$out/grid.scn" &&
    grep -q '^map tilt.png bump ' "$out/grid-height.scn" &&
    grep -q 'bump_map tilt.png' "$out/grid-height.scn" && ! grep -q 'bump' "$out/grid.scn"; then
    echo "PASS normal_tex_import_kinds"
else
    echo "FAIL normal_tex_import_kinds: $(grep -h '^map' "$out/grid.scn" "$out/grid-height.scn")"
fi

for a in double float fixed; do
    plain=$(render grid-plain $a) flat=$(render grid-flat $a)
    if failed "$plain" "$flat"; then
        echo "FAIL normal_tex_flat_$a: $(why "$plain" "$flat")"
    elif ! cmp -s "$plain" "$flat"; then
        echo "FAIL normal_tex_flat_$a: the images differ ($(build/links1 compare "$plain" "$flat" 2>&1 | grep -m1 'largest difference'))"
    elif [ -z "$(lost "$plain")" ] || [ "$(lost "$plain")" != "$(lost "$flat")" ]; then
        echo "FAIL normal_tex_flat_$a: lost-precision pixels $(lost "$plain") and $(lost "$flat")"
    else
        echo "PASS normal_tex_flat_$a"
    fi
done

plain=$out/grid-plain-float.ppm tilted=$(render grid float)
if failed "$plain" "$tilted"; then
    echo "FAIL normal_tex_tilts: $(why "$plain" "$tilted")"
elif build/links1 compare "$plain" "$tilted" --within 8 --min-fraction 0.9 >/dev/null 2>&1; then
    echo "FAIL normal_tex_tilts: the tilted normal texture leaves 90% of the grid within 8/255"
else
    echo "PASS normal_tex_tilts"
fi

# render_marked NAME ARITH: the image with --mark-lost
render_marked() {
    local img="$out/$1-$2-marked.ppm"
    rm -f "$img"
    build/links1 ref "$out/$1.scn" --arith "$2" --size $size --no-escalate --mark-lost -o "$img" >"$img.log" 2>&1
    echo "$img"
}
# like CHECK ARITH REF NAME...: each NAME's image has every pixel within
# 1/255 of REF's but for those either counts as lost precision (a texel
# border closer than the lookup's error: either texel may be taken), which
# are under 1% of the picture
like() {
    local check=$1 a=$2 ref=$3 name said bad=
    shift 3
    local r=$out/$ref-$a.ppm rm
    rm=$(render_marked "$ref" "$a")
    for name in "$@"; do
        local o=$out/$name-$a.ppm om
        om=$(render_marked "$name" "$a")
        if failed "$r" "$om" || failed "$o" "$rm"; then
            bad="$bad $(why "$r" "$om")"
        elif ! said=$(build/links1 compare "$r" "$om" --flagged --within 1 --min-fraction 1 2>&1) ||
            ! said=$(build/links1 compare "$o" "$rm" --flagged --within 1 --min-fraction 1 2>&1); then
            bad="$bad $name: $(grep -m1 'within' <<<"$said")"
        elif [ -z "$(lost "$o")" ] || [ "$(lost "$o")" -gt 69 ]; then
            bad="$bad $name: lost-precision pixels '$(lost "$o")'"
        fi
    done
    if [ -n "$bad" ]; then
        echo "FAIL $check:$bad"
    else
        echo "PASS $check"
    fi
}
for a in double float fixed; do
    for m in quad-0-plain quad-90-plain quad-0-mirror quad-90-mirror; do
        render $m $a >/dev/null
    done
    like normal_tex_turned_$a $a quad-0-plain quad-90-plain
    like normal_tex_mirrored_$a $a quad-0-plain quad-0-mirror quad-90-mirror
done

still=$(render quad-90-still float)
if failed "$out/quad-0-plain-float.ppm" "$still"; then
    echo "FAIL normal_tex_check_fails: $(why "$out/quad-0-plain-float.ppm" "$still")"
elif build/links1 compare "$out/quad-0-plain-float.ppm" "$still" --within 1 --min-fraction 1 >/dev/null 2>&1; then
    echo "FAIL normal_tex_check_fails: normals left unturned pass the turned check"
else
    echo "PASS normal_tex_check_fails"
fi

# mean IMAGE: the mean of all its bytes (binary PPM)
mean() { python3 tests/images/ppm_stat.py "$1" mean; }
xn=$(mean "$(render quad-xneg float)") xp=$(mean "$(render quad-xpos float)")
yp=$(mean "$(render quad-ypos float)") yn=$(mean "$(render quad-yneg float)")
if [[ $xn =~ ^[0-9]+$ && $xp =~ ^[0-9]+$ && $yp =~ ^[0-9]+$ && $yn =~ ^[0-9]+$ ]] &&
    [ "$xn" -gt "$xp" ] && [ "$yp" -gt "$yn" ]; then
    echo "PASS normal_tex_faces_light"
else
    echo "FAIL normal_tex_faces_light: mean brightness towards -u $xn, +u $xp, up $yp, down $yn"
fi
