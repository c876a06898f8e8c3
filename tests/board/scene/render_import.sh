#!/usr/bin/env bash
# An imported model renders on the board bit for bit as `links1 ref` of the
# same arithmetic: the textured OBJ+MTL cube and the Collada tower (nested
# nodes, its own camera and lights), float and fixed, 2 NCs, at 160x120;
# and the ball with its vertex normals interpolated (--smooth, beyond the
# paper) in float, soft and fixed; and a binary (big endian) PLY in float,
# equal to the host's picture of its ASCII twin (tests/models/make_ply_twins.py).
# The cube is imported from a copy beside the scenes, so its textures lie
# below the scene's directory (a map's image is read only from there, or
# from --textures-from DIR).
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_import || exit 0
SIZE=160x120
mkdir -p "$RENDER_TMP/models"
cp tests/models/cube.obj tests/models/cube.mtl tests/models/tex.ppm tests/models/bump.ppm \
    "$RENDER_TMP/models/"
for spec in "cube $RENDER_TMP/models/cube.obj --camera auto" "tower tests/models/tower.dae" \
    "ball tests/models/ball.obj --camera auto --smooth"; do
    set -- $spec
    name=$1 model=$2; shift 2
    scn="$RENDER_TMP/import_$name.scn"
    if ! err=$("$LINKS1" import "$model" -o "$scn" "$@" 2>&1); then
        echo "FAIL render_import_$name: links1 import: $err"
        continue
    fi
    ariths="float fixed"
    if [ "$name" = ball ]; then
        ariths="float soft fixed"
        if ! grep -Eq '^ *triangle .*( +n( +[-0-9.e]+){3}){3}' "$scn"; then
            echo "FAIL render_import_ball_smooth: the imported scene has no vertex normals"
            continue
        fi
    fi
    for arith in $ariths; do
        if [ "$name" = tower ]; then
            # The tower's own colours (--no-escalate): on its walls' diagonal
            # edge the host flags 6 pixels in float where the NCs' screen
            # search flags 1, so escalated the two images differ (as
            # --escalate did before it was the default)
            tplain=$RENDER_TMP/tower-$arith-plain.ppm tout=$RENDER_TMP/render_import_tower_$arith.ppm
            "$LINKS1" ref "$scn" --arith $arith --size $SIZE --no-escalate -o "$tplain" >/dev/null 2>&1
            render_board render_import_tower_${arith}_2nc_dynamic "$tout" "$scn" -o "$tout" \
                --arith $arith --ncs 2 --balance dynamic --size $SIZE --no-escalate &&
                render_same render_import_tower_${arith}_2nc_dynamic "$tplain" "$tout"
            continue
        fi
        render_grid_one "$scn" $arith 2 dynamic $SIZE
    done
done

# Binary PLY on the board: the big-endian twin in float, the picture the
# host makes of the ASCII twin.
python3 tests/models/make_ply_twins.py "$RENDER_TMP"
name=render_import_ply_binary_be_float
out="$RENDER_TMP/$name.ppm"
if ! err=$("$LINKS1" import "$RENDER_TMP/twin-ascii.ply" -o "$RENDER_TMP/twin_ascii.scn" \
        --camera auto 2>&1) ||
    ! err=$("$LINKS1" import "$RENDER_TMP/twin-be.ply" -o "$RENDER_TMP/twin_be.scn" \
        --camera auto 2>&1); then
    echo "FAIL $name: links1 import: $err"
else
    ref=$(render_ref "$RENDER_TMP/twin_ascii.scn" float $SIZE)
    render_board "$name" "$out" "$RENDER_TMP/twin_be.scn" -o "$out" --arith float --ncs 2 \
        --size $SIZE && render_same "$name" "$ref" "$out"
fi
