#!/usr/bin/env bash
# An imported model renders on the board bit for bit as `links1 ref` of the
# same arithmetic: the textured OBJ+MTL cube and the Collada tower (nested
# nodes, its own camera and lights), float and fixed, 2 NCs, at 160x120.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/render_lib.sh"
board_ready render_import || exit 0
SIZE=160x120
for spec in "cube tests/models/cube.obj --camera auto" "tower tests/models/tower.dae"; do
    set -- $spec
    name=$1 model=$2; shift 2
    scn="$RENDER_TMP/import_$name.scn"
    if ! err=$("$LINKS1" import "$model" -o "$scn" "$@" 2>&1); then
        echo "FAIL render_import_$name: links1 import: $err"
        continue
    fi
    for arith in float fixed; do
        render_grid_one "$scn" $arith 2 dynamic $SIZE
    done
done
