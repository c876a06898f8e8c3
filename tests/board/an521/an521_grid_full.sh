#!/usr/bin/env bash
# make test-full: on the an521 boards, every arithmetic (float, soft, fixed)
# at 2, 4 and 8 NCs (2, 3 and 5 boards) on demo.scn and two SPD scenes
# that fit the machine (tetra 4, balls 2), each image byte for byte equal
# to the host build of the same arithmetic.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
spd=$RENDER_TMP/spd
mkdir -p "$spd"
build/links1-spd tetra 4 -o "$spd/tetra4.scn" >/dev/null 2>&1
build/links1-spd balls 2 -o "$spd/balls2.scn" >/dev/null 2>&1
for scene in scenes/demo.scn "$spd/tetra4.scn" "$spd/balls2.scn"; do
    for arith in float soft fixed; do
        for ncs in 2 4 8; do
            name=an521_grid_$(basename "$scene" .scn)_${arith}_${ncs}nc
            if [ ! -r "$FW_DIR/an521/links1-$arith.elf" ] || [ ! -s "$scene" ]; then
                echo "FAIL $name: $FW_DIR/an521/links1-$arith.elf or $scene missing (run make)"
                continue
            fi
            out=$RENDER_TMP/$name.ppm
            ref=$(render_ref "$scene" "$arith" 80x60)
            render_board "$name" "$out" "$scene" -o "$out" --machine an521 --ncs "$ncs" \
                --arith "$arith" --size 80x60 || continue
            render_same "$name" "$ref" "$out"
        done
    done
done
