#!/usr/bin/env bash
# The full grid of `make test-full`: scenes {demo, glass, molecule} x
# arithmetics {float, soft, fixed} x NCs {1, 2, 8, 64} x balancing modes
# {static, dynamic, decreasing}, each image equal bit for bit to the host
# build of its arithmetic.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_grid_full || exit 0
SIZE=${RENDER_FULL_SIZE:-96x72}
for scene in scenes/demo.scn scenes/glass.scn scenes/molecule.scn; do
    for arith in float soft fixed; do
        for ncs in 1 2 8 64; do
            for mode in static dynamic decreasing; do
                render_grid_one $scene $arith $ncs $mode $SIZE
            done
        done
    done
done
