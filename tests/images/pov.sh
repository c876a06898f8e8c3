#!/usr/bin/env bash
# tests/images/pov.sh: the outside check of the renderer against POV-Ray 3.7.
# Each scene in scenes/pov/, and scenes/haze.scn, uses only what both
# renderers express the same way (docs/pov-mapping.md); it is rendered by `links1 ref` (double) and by
# POV-Ray from `links1 export-pov --strict`, and at least 99% of the pixels
# away from silhouettes must agree within 3/255 on every channel.
# Models imported from tests/models/ are held to the same bar.  Anti-aliased
# (two scenes): links1 --aa 3 --aa-threshold 0 against POV-Ray +A0.0 +AM2
# +R4 (its adaptive sampling cutting every pixel, the closest match of
# +R3..+R4), edges included: 99% of all pixels within 3/255.
# Prints "PASS pov_NAME" or "FAIL pov_NAME: why" per scene.
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/pov
mkdir -p "$out"
if ! command -v povray >/dev/null; then
    echo "FAIL pov_setup: povray is not installed (apt-get install povray)"
    exit 1
fi
# pov_check NAME SCENE [LINKS1_ARGS [POV_ARGS [COMPARE_ARGS]]]: links1 ref
# (double) against POV-Ray of export-pov --strict; by default without
# anti-aliasing, the pixels next to silhouettes left out.
pov_check() {
    local name=$1 scn=$2 largs=${3:-} pargs=${4:--A} cargs=${5:---silhouette --max-masked 0.15}
    local ref="$out/$name-links1.png" pov="$out/$name.pov" img="$out/$name-povray.png"
    local err size report
    # shellcheck disable=SC2086 # the argument lists split into words
    if ! err=$(build/links1 ref "$scn" -o "$ref" $largs 2>&1); then
        echo "FAIL pov_$name: links1 ref failed: $err"
        return
    fi
    if ! err=$(build/links1 export-pov "$scn" -o "$pov" --strict 2>&1); then
        echo "FAIL pov_$name: export-pov failed: $err"
        return
    fi
    size=$(sed -n 's/.*+W\([0-9]*\) +H\([0-9]*\).*/+W\1 +H\2/p' "$pov" | head -1)
    # File_Gamma=1.0: the file holds the linear values, as links1 writes them.
    if ! (cd "$out" && timeout 120 povray -D "+I$name.pov" "+O$name-povray.png" $size \
              $pargs +WT1 File_Gamma=1.0 >"$name-povray.log" 2>&1); then
        echo "FAIL pov_$name: povray failed, see $out/$name-povray.log"
        return
    fi
    if report=$(build/links1 compare "$ref" "$img" --within 3 --min-fraction 0.99 $cargs); then
        echo "PASS pov_$name"
    else
        echo "FAIL pov_$name: $(echo "$report" | tail -n 2 | tr '\n' ' ')"
    fi
    echo "$report" | sed 's/^/    /'
}

for scn in scenes/pov/*.scn; do
    pov_check "$(basename "$scn" .scn)" "$scn"
done
# Haze against POV-Ray's fog_type 1 (export-pov writes fog { fog_type 1
# distance D color rgb H }): every ray hazed from its own origin, the
# mirror's reflections included, a miss taking the haze colour.
pov_check haze scenes/haze.scn
# Anti-aliased, edges included: every pixel cut to the limit on both sides.
for scn in spheres triangles; do
    pov_check "aa_$scn" "scenes/pov/$scn.scn" "--aa 3 --aa-threshold 0" "+A0.0 +AM2 +R4" " "
done
# Models made elsewhere, through links1 import --camera auto (flat
# triangles, Lambert, the added light): the same agreement.  POV-Ray's
# ambient is never shadowed, so the imported scene takes that reading
# (ambient_shadowed off), as the scenes of scenes/pov/ do.
for model in tests/models/tetra.ply tests/models/pyramid.stl; do
    name=import_$(basename "$model" | tr . _)
    if ! err=$(build/links1 import "$model" -o "$out/$name.scn" --camera auto 2>&1); then
        echo "FAIL pov_$name: links1 import failed: $err"
        continue
    fi
    if ! grep -q 'ambient_shadowed on' "$out/$name.scn"; then
        echo "FAIL pov_$name: the imported scene does not say ambient_shadowed on"
        continue
    fi
    sed -i 's/ambient_shadowed on/ambient_shadowed off/' "$out/$name.scn"
    pov_check "$name" "$out/$name.scn"
done
