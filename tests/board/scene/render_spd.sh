#!/usr/bin/env bash
# The Standard Procedural Databases (links1-spd, host-tools/spd/; the teapot
# at size 1, 52 smooth triangles and the floor's 2) at their small
# sizes: each generated scene compiles (with its automatic hierarchy) and
# renders on the board exactly as the host build renders it, and the host
# image is the same with the automatic hierarchy off (the arithmetic's own,
# --no-escalate: which pixels are in doubt, and so escalated, can depend on
# the hierarchy a walk goes through; docs/renderer.md, "Escalation").  96x72 on 4 NCs, one
# arithmetic per scene so that all three are covered.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
SPD="$(dirname "$LINKS1")/links1-spd"
board_ready render_spd || exit 0
SIZE=96x72
i=0
for db in "balls 2" "tetra 2" "mount 2" "rings 1" "tree 3" "gears 1" "teapot 1"; do
    set -- $db
    arith=$(echo float fixed soft | cut -d' ' -f$((i % 3 + 1)))
    i=$((i + 1))
    name="render_spd_$1_$2_$arith"
    scene="$RENDER_TMP/spd-$1-$2.scn"
    if ! "$SPD" "$1" "$2" -o "$scene" >"$scene.log" 2>&1; then
        echo "FAIL $name: links1-spd $1 $2 failed: $(tail -n 1 "$scene.log")"
        continue
    fi
    ref=$(render_ref "$scene" "$arith" "$SIZE")
    build=$arith
    [ "$arith" = soft ] && build=float
    flat="$RENDER_TMP/flat-$1-$build.ppm" plain="$RENDER_TMP/plain-$1-$build.ppm"
    "$LINKS1" ref "$scene" -o "$plain" --arith "$build" --size "$SIZE" --no-escalate \
        >"$plain.log" 2>&1
    "$LINKS1" ref "$scene" -o "$flat" --arith "$build" --size "$SIZE" --no-auto-hierarchy \
        --no-escalate >"$flat.log" 2>&1
    render_same "${name}_hierarchy_off" "$plain" "$flat"
    out="$RENDER_TMP/$name.ppm"
    render_board "$name" "$out" "$scene" -o "$out" --arith "$arith" --ncs 4 --size "$SIZE" ||
        continue
    render_same "$name" "$ref" "$out"
done
