#!/usr/bin/env bash
# tests/sweeps/margins.sh: sweep scenes that left wrong pixels neither
# flagged nor explained by a move under a pixel (docs/results/sweeps.md),
# at the sweeps' full size 160x120, where a hit-or-miss decision was closer
# than the arithmetic's error (render_prim_t.edge_error): triangles 3000 and
# 10000 times longer than wide, thinner than a pixel, in fixed point (an
# edge test on the sliver), tir_chain at depth 1 in float (a shadow ray
# grazing a sphere) and at depth 4 in fixed (two spheres cutting each other
# hit at distances closer than their hit errors), and cluster_scale 0.1 in
# fixed (the cluster's inverse is off by 6e-4: the ellipsoid's normal, so
# a reflected ray and its shadow ray, move more than the decisions they
# meet; every ray carries its error, render/trace.c); and scenes/glass.scn
# at 320x240 in fixed (a ray moved sideways meets a surface it grazes
# farther off along it, by 1 over the cosine: its shadow rays start there,
# trace_surface_error).  Every pixel beyond 2/255 of the double build must
# be painted as lost precision or lie next to an edge or a moved pixel
# (links1 compare --flagged --silhouette --moved, as in flagged.sh).
#   PASS margin_FAMILY_KNOB_ARITH  or  FAIL ...: the compare's verdict
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
. tests/sweeps/families.sh
out=build/test-images/margins
mkdir -p "$out"
# A run: a sweep family and its knob (at 160x120), or scenes/NAME.scn as
# scene:NAME and its size; then the arithmetic.
for run in "thin_triangles 3000 fixed" "thin_triangles 10000 fixed" "tir_chain 1 float" \
        "tir_chain 4 fixed" "cluster_scale 0.1 fixed" "scene:glass 320x240 fixed"; do
    read -r family knob arith <<<"$run"
    size=160x120
    if [ "${family#scene:}" != "$family" ]; then
        family=${family#scene:} size=$knob
        scn=scenes/$family.scn
    else
        scn=$out/$family-$knob.scn
        family_scene "$family" "$knob" $size >"$scn" || {
            echo "FAIL margin_${family}_${knob}_$arith: make_scene.py failed"; continue; }
    fi
    name=margin_${family}_${knob}_$arith
    if ! "$LINKS1" ref "$scn" --arith double --size $size -o "$out/$family-$knob-double.png" >/dev/null 2>&1 ||
        ! "$LINKS1" ref "$scn" --arith "$arith" --size $size --no-escalate --mark-lost \
            -o "$out/$family-$knob-$arith.png" >"$out/$family-$knob-$arith.log" 2>&1; then
        echo "FAIL $name: links1 ref failed: $(tail -n 1 "$out/$family-$knob-$arith.log")"
        continue
    fi
    lost=$(grep -o '[0-9]* pixels in doubt' "$out/$family-$knob-$arith.log")
    if r=$("$LINKS1" compare "$out/$family-$knob-double.png" "$out/$family-$knob-$arith.png" \
            --within 2 --min-fraction 1 --flagged --silhouette --moved 2>&1); then
        echo "PASS $name ($lost; every other pixel within 2/255, next to an edge or moved)"
    else
        echo "FAIL $name: $(echo "$r" | grep 'on every channel' | sed 's/^ *//')"
    fi
done
