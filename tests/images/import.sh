#!/usr/bin/env bash
# tests/images/import.sh: `links1 import` of each model format in
# tests/models/ writes a scene that `links1 ref` renders, with the model in
# the picture; refused models leave no scene behind and name the problem.
# Prints "PASS import_NAME" / "FAIL import_NAME: why".
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/import
rm -rf "$out"
mkdir -p "$out"

# covered PPM: how many pixels differ from the top-left one (the background).
covered() { python3 tests/images/ppm_stat.py "$1" covered; }

# import_renders NAME MODEL [import options]: import, ref at 80x60, and
# at least 2% of the picture is the model.  The scenes lie outside
# tests/models/, so the ref takes --textures-from tests/models for the
# textures the scenes name there (a map's image is read only from below
# the scene's directory or a --textures-from DIR).
import_renders() {
    local name=$1 model=$2; shift 2
    local scn="$out/$name.scn" img="$out/$name.ppm" err n
    if ! err=$(build/links1 import "$model" -o "$scn" "$@" 2>&1); then
        echo "FAIL import_$name: import: $err"
    elif ! err=$(build/links1 ref "$scn" -o "$img" --size 80x60 --textures-from tests/models 2>&1); then
        echo "FAIL import_$name: ref: $err"
    elif ! n=$(covered "$img") || ! [[ $n =~ ^[0-9]+$ ]]; then
        echo "FAIL import_$name: could not count the model's pixels in $img ('$n')"
    elif [ "$n" -lt 96 ]; then
        echo "FAIL import_$name: only $n of 4800 pixels show the model"
    else
        echo "PASS import_$name"
    fi
}

import_renders obj_mtl tests/models/cube.obj --camera auto
import_renders gltf2 tests/models/plate.gltf
import_renders ply tests/models/tetra.ply --camera auto
import_renders stl tests/models/pyramid.stl --camera auto
import_renders collada tests/models/tower.dae
import_renders 3ds tests/models/tetra.3ds --camera auto
import_renders fit tests/models/huge.obj --fit --camera auto

# Faces out: a closed convex model whose file lists each face
# counter-clockwise seen from outside (the formats' rule) comes out with
# every triangle's e1 x e2 pointing away from the model's centre, the side
# a ray entering glass meets (the import negates z, which alone would turn
# them in).
faces_out() { # NAME SCENE: PASS when every triangle faces away from the centroid
    python3 - "$2" <<'PY' && echo "PASS import_faces_out_$1" || echo "FAIL import_faces_out_$1"
import re, sys
tris = [[list(map(float, v)) for v in re.findall(r"\bv (\S+) (\S+) (\S+)", line)]
        for line in open(sys.argv[1]) if line.lstrip().startswith("triangle")]
pts = [p for t in tris for p in t]
if not tris or not pts:
    print("no triangles in", sys.argv[1]); sys.exit(1)
c = [sum(p[i] for p in pts) / len(pts) for i in range(3)]
inward = 0
for a, b, d in tris:
    e1 = [b[i] - a[i] for i in range(3)]
    e2 = [d[i] - a[i] for i in range(3)]
    n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    m = [(a[i] + b[i] + d[i]) / 3 - c[i] for i in range(3)]
    inward += sum(n[i] * m[i] for i in range(3)) <= 0
if inward:
    print(inward, "of", len(tris), "triangles face into the model")
sys.exit(1 if inward else 0)
PY
}
faces_out obj "$out/obj_mtl.scn"
build/links1 import tests/models/ball.obj -o "$out/ball.scn" --camera auto >/dev/null 2>&1
faces_out ball "$out/ball.scn"

# The textures of the OBJ's material are named relative to the scene.
if grep -q 'image "[^"]*tex.ppm"' "$out/obj_mtl.scn" 2>/dev/null; then
    echo "PASS import_texture_named"
else
    echo "FAIL import_texture_named: no map image tex.ppm in $out/obj_mtl.scn"
fi

# import_refused NAME WANT MODEL [options]: exit 1 (2 for a bad option),
# WANT in the message, no scene.
import_refused() {
    local name=$1 want=$2 model=$3; shift 3
    local want_rc=1
    [[ $name == bad_option* ]] && want_rc=2
    local scn="$out/refused-$name.scn" err rc
    err=$(build/links1 import "$model" -o "$scn" "$@" 2>&1)
    rc=$?
    if [ $rc -ne $want_rc ]; then
        echo "FAIL import_refuses_$name: exit $rc, not $want_rc ($err)"
    elif ! grep -qF -- "$want" <<<"$err"; then
        echo "FAIL import_refuses_$name: the message does not say '$want': $err"
    elif ls "$out"/refused-"$name".scn* >/dev/null 2>&1; then
        echo "FAIL import_refuses_$name: a scene file was left behind"
    else
        echo "PASS import_refuses_$name"
    fi
}

import_refused library "bad_syntax.gltf: the model library cannot read it" \
    tests/models/bad_syntax.gltf --camera auto
import_refused nonfinite "vertex 2 is not finite" tests/models/nonfinite.obj --camera auto
import_refused missing_texture "no_such_texture.png" tests/models/missing_tex.obj --camera auto
import_refused extent "spans x -2.5e+08..2.5e+08" tests/models/huge.obj --camera auto
import_refused no_camera "no camera (--camera auto frames it)" tests/models/tetra.ply
import_refused bad_option_camera "--camera 'front': want auto" tests/models/tetra.ply --camera front

# The model library is opened only when a model is read (assimp_lib.h):
# links1 does not load it at its start, and where it cannot be loaded (here
# a broken copy found first on LD_LIBRARY_PATH) the import names it and
# writes nothing, while commands without a model still work.
if ! deps=$(ldd build/links1 2>&1) || ! grep -q "libc\.so" <<<"$deps"; then
    echo "FAIL import_library_on_demand: ldd build/links1 listed no libraries: $deps"
elif grep -q "libassimp" <<<"$deps"; then
    echo "FAIL import_library_on_demand: links1 loads libassimp at its start"
else
    echo "PASS import_library_on_demand"
fi
broken="$out/broken-lib"
mkdir -p "$broken"
for lib in /usr/lib/*/libassimp.so.*; do
    echo "not a library" >"$broken/$(basename "$lib")"
done
LD_LIBRARY_PATH="$broken" import_refused library_missing \
    "tetra.ply: the model library (libassimp.so." tests/models/tetra.ply --camera auto
if ! err=$(LD_LIBRARY_PATH="$broken" build/links1 ref scenes/demo.scn --size 16x12 \
        -o "$out/no-model-lib.ppm" 2>&1); then
    echo "FAIL import_library_missing_ref: links1 ref without a model failed: $err"
else
    echo "PASS import_library_missing_ref"
fi

# Degenerate triangles are dropped and counted, not fatal.
if err=$(build/links1 import tests/models/degenerate.obj -o "$out/degenerate.scn" \
        --camera auto 2>&1) && grep -q "2 degenerate triangles dropped" <<<"$err" &&
   [ "$(grep -c '^ *triangle' "$out/degenerate.scn")" -eq 2 ]; then
    echo "PASS import_degenerate_dropped"
else
    echo "FAIL import_degenerate_dropped: $err"
fi

# libassimp's own crashes (tests/fuzz/assimp-crashes/, fuzz_import inputs:
# the first byte picks the format, the rest is the model): each model as a
# file of its format.  The library runs in a child process, so `links1
# import` and a scene's model statement never die with it: where it
# crashes they name the file and the signal and write nothing; the others
# (the OBJ and glTF inputs crash it only when read from memory, as the fuzz
# harness reads them; tests/host/test_model_child.c runs them so) are
# refused with the file named or imported.
formats=(obj ply stl gltf dae 3ds glb off)
for input in tests/fuzz/assimp-crashes/*; do
    name=$(basename "$input")
    [ "$name" = README ] && continue
    ext=${formats[$(( $(od -An -tu1 -N1 "$input") & 7 ))]}
    model="$out/crash-$name.$ext" scn="$out/crash-$name.scn"
    tail -c +2 "$input" >"$model"
    err=$(timeout 60 build/links1 import "$model" -o "$scn" --camera auto 2>&1)
    rc=$?
    crashed=0 said=
    grep -q "the model library crashed (signal" <<<"$err" && crashed=1 said=", the crash named"
    if [ $rc -ne 0 ] && [ $rc -ne 1 ]; then
        echo "FAIL import_assimp_crash_$name: exit $rc ($err)"
    elif [ $rc -eq 1 ] && ! grep -qF "links1 import: $model: " <<<"$err"; then
        echo "FAIL import_assimp_crash_$name: the message does not name $model: $err"
    elif [ $rc -eq 1 ] && ls "$scn"* >/dev/null 2>&1; then
        echo "FAIL import_assimp_crash_$name: a scene file was left behind"
    elif [ $rc -eq 0 ] && [ ! -s "$scn" ]; then
        echo "FAIL import_assimp_crash_$name: exit 0 but no scene"
    elif [ "$name" = ply-abort-in-postprocess ] && ! grep -qF \
        "$model: the model library crashed (signal 6, SIGABRT) while reading it; the file is malformed or unsupported" \
        <<<"$err"; then
        echo "FAIL import_assimp_crash_$name: not named as the library's crash: $err"
    else
        echo "PASS import_assimp_crash_$name (exit $rc$said)"
    fi
    # the same model through a scene's model statement
    printf 'light point { position 0 5 -5 }\nmaterial m { colour 1 0 0 }\ncluster c {\n  model { file "%s"  material m  fit on } }\n' \
        "crash-$name.$ext" >"$out/crash-$name-stmt.scn"
    err=$(timeout 60 build/links1 compile "$out/crash-$name-stmt.scn" -o "$out/crash-$name.l1s" 2>&1)
    rc=$?
    if [ $rc -ne 0 ] && ! grep -qF "crash-$name-stmt.scn:4:3: model: $model: " <<<"$err"; then
        echo "FAIL import_assimp_crash_statement_$name: exit $rc, the message does not name the statement and $model: $err"
    elif [ $rc -ne 0 ] && [ -e "$out/crash-$name.l1s" ]; then
        echo "FAIL import_assimp_crash_statement_$name: a compiled scene was left behind"
    elif [ $crashed = 1 ] && [ $rc -eq 0 ]; then
        echo "FAIL import_assimp_crash_statement_$name: compiled, where links1 import said the library crashed"
    else
        echo "PASS import_assimp_crash_statement_$name (exit $rc)"
    fi
done
