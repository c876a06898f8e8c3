#!/usr/bin/env bash
# The board's image equals, bit for bit, the host build of the same
# arithmetic: the demo and a paper-like scene (glass.scn) x {float, soft,
# fixed}, each arithmetic with NCs {1, 2, 8} and the three balancing modes
# paired so that every pair of (arithmetic, NCs, mode) values occurs; and
# the double firmware (VFP in double precision) against the host's double
# build on 2 and 8 NCs.  At
# 96x72 so the whole set runs in about half a minute; `make test-full` runs the
# full grid (render_grid_full.sh).
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_grid || exit 0
SIZE=96x72
for scene in scenes/demo.scn scenes/glass.scn; do
    render_grid_one $scene float 1 static $SIZE
    render_grid_one $scene float 2 dynamic $SIZE
    render_grid_one $scene float 8 decreasing $SIZE
    render_grid_one $scene soft 1 dynamic $SIZE
    render_grid_one $scene soft 2 decreasing $SIZE
    render_grid_one $scene soft 8 static $SIZE
    render_grid_one $scene fixed 1 decreasing $SIZE
    render_grid_one $scene fixed 2 static $SIZE
    render_grid_one $scene fixed 8 dynamic $SIZE
    render_grid_one $scene double 2 decreasing $SIZE
    render_grid_one $scene double 8 static $SIZE
done
