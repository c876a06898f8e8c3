#!/usr/bin/env bash
# Cones and cylinders (SCENE_PRIM_CONE, render/prim_cone.c) on the board
# equal the host build of the same arithmetic, bit for bit: the POV-Ray
# check's cylinder scene (capped and open, upright and in a rotated
# cluster, a pointed cone) in float, soft float, fixed point and double,
# and SPD rings 1 (its open cylinders, as links1-spd writes them in the
# text form) in float and fixed.  Small sizes, 2 NCs: a few seconds a
# render.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_cones || exit 0
SIZE=96x72
render_grid_one scenes/pov/cylinders.scn float 2 dynamic $SIZE
render_grid_one scenes/pov/cylinders.scn soft 2 static $SIZE
render_grid_one scenes/pov/cylinders.scn fixed 2 decreasing $SIZE
render_grid_one scenes/pov/cylinders.scn double 2 dynamic $SIZE
rings="$RENDER_TMP/rings1.scn"
if ! "$(dirname "$LINKS1")/links1-spd" rings 1 -o "$rings" 2>"$RENDER_TMP/spd.log"; then
    echo "FAIL render_rings1_float_2nc_dynamic: links1-spd rings 1 failed: $(tail -n 1 "$RENDER_TMP/spd.log")"
    echo "FAIL render_rings1_fixed_2nc_static: links1-spd rings 1 failed"
    exit 0
fi
render_grid_one "$rings" float 2 dynamic $SIZE
render_grid_one "$rings" fixed 2 static $SIZE
