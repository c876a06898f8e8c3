#!/usr/bin/env bash
# tests/images/map_confine.sh: a map statement's image is read only from
# below the scene file's directory, or below a directory given with
# --textures-from DIR (the confinement of a model's textures, one check:
# sd_image_open_below); a directory that would allow too much (/, one
# directly under /, the home directory) is refused as --textures-from and
# as a model statement's textures_from.  Each refusal names the file or
# directory and the rule; the scenes of scenes/ with map images still
# compile.  Everything is made here, in a directory of the test's own.
# Prints "PASS map_NAME" / "FAIL map_NAME: why".
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
T=$(mktemp -d /tmp/links1-map-test.XXXXXX)
trap 'rm -rf "$T"' EXIT
mkdir -p "$T/scene/maps" "$T/outside"
cp scenes/maps/checker.png "$T/scene/maps/own.png"
cp scenes/maps/checker.png "$T/outside/secret.png"
ln -s "$T/outside/secret.png" "$T/scene/maps/link.png"

# scene NAME IMAGE [MODEL-STATEMENT]: $T/scene/NAME.scn, its colour map's image IMAGE
scene() {
    cat >"$T/scene/$1.scn" <<SCN
camera { eye 0 2 -6  look_at 0 0 0  up 0 1 0  fov 45 }
resolution 32 24
light point { position 3 6 -4 }
map t colour { image "$2" }
material m { colour 1 1 1  dic 0.2 drc 0.8  colour_map t }
sphere { material m  centre 0 0 0  radius 1 }
${3:-}
SCN
}

# expect NAME RC WANT CMD...: CMD exits RC and its message holds WANT
# (nothing written when it refuses).
expect() {
    local name=$1 want_rc=$2 want=$3 err rc
    shift 3
    err=$(timeout 20 "$@" 2>&1)
    rc=$?
    if [ $rc -ne "$want_rc" ]; then
        echo "FAIL map_$name: exit $rc, not $want_rc: $err"
    elif [ -n "$want" ] && ! grep -qF -- "$want" <<<"$err"; then
        echo "FAIL map_$name: the message does not say '$want': $err"
    elif [ "$want_rc" -ne 0 ] && [ -e "$T/out.l1s" ]; then
        echo "FAIL map_$name: refused, but $T/out.l1s was written"
    else
        echo "PASS map_$name"
    fi
    rm -f "$T/out.l1s"
}

scene own "maps/own.png"
expect inside_compiles 0 "" "$LINKS1" compile "$T/scene/own.scn" -o "$T/out.l1s"

scene up "../outside/secret.png"
expect outside_refused 1 \
    "$T/scene/../outside/secret.png: outside the scene's directory $T/scene/; not read (a map's image lies below the scene file's directory, or below a directory given with --textures-from DIR)" \
    "$LINKS1" compile "$T/scene/up.scn" -o "$T/out.l1s"
scene abs "$T/outside/secret.png"
expect absolute_refused 1 "$T/outside/secret.png: outside the scene's directory" \
    "$LINKS1" compile "$T/scene/abs.scn" -o "$T/out.l1s"
scene link "maps/link.png"
expect link_out_refused 1 "maps/link.png: outside the scene's directory" \
    "$LINKS1" compile "$T/scene/link.scn" -o "$T/out.l1s"
expect ref_outside_refused 1 "outside the scene's directory" \
    "$LINKS1" ref "$T/scene/up.scn" -o "$T/out.ppm"

# --textures-from DIR allows that directory (and only that one)
expect textures_from_compiles 0 "" \
    "$LINKS1" compile "$T/scene/up.scn" -o "$T/out.l1s" --textures-from "$T/outside"
expect textures_from_other_refused 1 "and $T/scene/maps; not read" \
    "$LINKS1" compile "$T/scene/up.scn" -o "$T/out.l1s" --textures-from "$T/scene/maps"
if timeout 20 "$LINKS1" ref "$T/scene/up.scn" -o "$T/up.ppm" --textures-from "$T/outside" \
        >/dev/null 2>&1 && timeout 20 "$LINKS1" ref "$T/scene/own.scn" -o "$T/own.ppm" \
        >/dev/null 2>&1 && cmp -s "$T/up.ppm" "$T/own.ppm"; then
    echo "PASS map_textures_from_ref_same"
else
    echo "FAIL map_textures_from_ref_same: links1 ref --textures-from did not render the outside image as the inside one"
fi

# directories that would allow too much: refused, naming the rule
for spec in "root:/:/ is the root of the file system" \
    "tmp:/tmp:/tmp is a directory directly under /" "etc:/etc:/etc is a directory directly under /" \
    "tmp_by_dots:$T/..:/tmp is a directory directly under /"; do
    IFS=: read -r name dir why <<<"$spec"
    expect "textures_from_refuses_$name" 2 "--textures-from \"$dir\": $why" \
        "$LINKS1" compile "$T/scene/own.scn" -o "$T/out.l1s" --textures-from "$dir"
done
expect import_textures_from_root_refused 2 \
    "--textures-from \"/\": / is the root of the file system, which would allow images from too much of the system; refused" \
    "$LINKS1" import tests/models/cube.obj -o "$T/out.scn" --camera auto --textures-from /
cp tests/models/tetra.ply "$T/scene/tetra.ply"
scene stmt_root "maps/own.png" 'model { file "tetra.ply"  material m  textures_from "/" }'
expect model_textures_from_root_refused 1 \
    "model: textures_from \"/\": / is the root of the file system" \
    "$LINKS1" compile "$T/scene/stmt_root.scn" -o "$T/out.l1s"
scene stmt_ok "maps/own.png" 'model { file "tetra.ply"  material m  textures_from "../outside" }'
expect model_textures_from_compiles 0 "" "$LINKS1" compile "$T/scene/stmt_ok.scn" -o "$T/out.l1s"

# an import whose textures lie outside the written scene's directory says
# which --textures-from reads it; the scene is refused without it
err=$(timeout 60 "$LINKS1" import tests/models/cube.obj -o "$T/cube.scn" --camera auto 2>&1)
if [ -s "$T/cube.scn" ] && grep -qF -- "names map images outside its directory: compile, render or ref it with --textures-from tests/models/" <<<"$err"; then
    echo "PASS map_import_outside_note"
else
    echo "FAIL map_import_outside_note: $err"
fi
expect import_scene_refused 1 ".ppm: outside the scene's directory $T/" \
    "$LINKS1" compile "$T/cube.scn" -o "$T/out.l1s"
expect import_scene_textures_from 0 "" \
    "$LINKS1" compile "$T/cube.scn" -o "$T/out.l1s" --textures-from tests/models

# the scenes of scenes/ that name map images still compile
bad=
for scn in $(grep -l 'image "' scenes/*.scn); do
    timeout 60 "$LINKS1" compile "$scn" -o "$T/scene.l1s" >/dev/null 2>&1 || bad="$bad $scn"
done
if [ -z "$bad" ]; then
    echo "PASS map_scenes_compile"
else
    echo "FAIL map_scenes_compile:$bad"
fi
