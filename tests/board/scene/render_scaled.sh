#!/usr/bin/env bash
# Lengths scaled to the scene (docs/renderer.md): the sweep's scene of three
# shapes on a floor shrunk by 1,000 (its largest length 0.008, stored times
# 2^10), enlarged by 100 (800, stored times 2^-6) and by 1,000 (8000, stored
# times 2^-9; beyond the old coordinate limit of 1000) renders on the board
# in fixed point and in float bit for bit as `links1 ref --arith fixed` /
# `--arith float`, 2 NCs, 64x48.  So does the same scene with its objects
# in a cluster scaled by 1e-6 and by 1e6 (make_scene.py cluster_scale: the
# loader takes the cluster's power of two into the lengths it holds), in
# float and in double.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_scaled || exit 0
for knob in 0.001 100 1000; do
    scn="$RENDER_TMP/scaled_$knob.scn"
    python3 host-tools/gen/make_scene.py scale "$knob" --size 64x48 >"$scn" || {
        echo "FAIL render_scaled_$knob: make_scene.py failed"
        continue
    }
    for arith in fixed float; do
        render_grid_one "$scn" "$arith" 2 dynamic 64x48
    done
done
for knob in 1e-06 1e+06; do
    scn="$RENDER_TMP/cluster_scaled_$knob.scn"
    python3 host-tools/gen/make_scene.py cluster_scale "$knob" --size 64x48 >"$scn" || {
        echo "FAIL render_cluster_scaled_$knob: make_scene.py failed"
        continue
    }
    render_grid_one "$scn" float 2 dynamic 64x48
    render_grid_one "$scn" double 2 dynamic 64x48
done
