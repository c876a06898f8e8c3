#!/usr/bin/env bash
# scenes/creature.scn, the README's film (docs/results/readme-pictures.md):
# a keyed creature of density spheres with maps, a mirror, glass and haze.
# It loads with 24..48 frames, and its first and last frames on the board
# (3 NCs, 64x48) equal the host float build's byte for byte.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_creature_frames render_creature_frame0 render_creature_frame47 || exit 0
SIZE=64x48
scn=scenes/creature.scn
for f in 0 47; do
    name=render_creature_frame$f
    ref=$RENDER_TMP/creature-$f-ref.ppm
    "$LINKS1" ref $scn -o "$ref" --arith float --size $SIZE --frame $f >"$ref.log" 2>&1
    out=$RENDER_TMP/creature-$f.ppm
    if render_board $name "$out" $scn -o "$out" --ncs 3 --size $SIZE --frame $f; then
        render_same $name "$ref" "$out"
    fi
    [ $f = 0 ] || continue
    n=$(sed -n 's/.* loaded: [0-9x]*, \([0-9]*\) frame(s).*/\1/p' "$RENDER_TMP/$name.log")
    if [ -n "$n" ] && [ "$n" -ge 24 ] && [ "$n" -le 48 ]; then
        echo "PASS render_creature_frames"
    else
        echo "FAIL render_creature_frames: want 24..48 frames in $scn, the board loaded '${n:-none}'"
    fi
done
