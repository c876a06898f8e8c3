#!/usr/bin/env bash
# An imported model renders on the board bit for bit as `links1 ref` of the
# same arithmetic: the textured OBJ+MTL cube and the Collada tower (nested
# nodes, its own camera and lights), float and fixed, 2 NCs, at 160x120;
# and the ball with its vertex normals interpolated (--smooth, beyond the
# paper) in float, soft and fixed.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_import || exit 0
SIZE=160x120
for spec in "cube tests/models/cube.obj --camera auto" "tower tests/models/tower.dae" \
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
        render_grid_one "$scn" $arith 2 dynamic $SIZE
    done
done
