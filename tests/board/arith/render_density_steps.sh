#!/usr/bin/env bash
# The scene's density_steps on the board: the sweep family's scene
# (host-tools/gen/make_scene.py density_steps: thin density features) with
# --density-steps 8 renders on the board as on the host, in float and
# fixed, and differs from the same scene at 64 steps (features thinner
# than a step are stepped over: the option reaches the NCs' root finder).
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_density_steps_float render_density_steps_fixed render_density_steps_differ || exit 0
SIZE=64x48
scn=$RENDER_TMP/density_steps.scn
python3 host-tools/gen/make_scene.py density_steps 64 --size $SIZE >"$scn"
for arith in float fixed; do
    ref=$RENDER_TMP/density8-host-$arith.ppm
    "$LINKS1" ref "$scn" --arith $arith --density-steps 8 -o "$ref" >"$ref.log" 2>&1
    out=$RENDER_TMP/density8-board-$arith.ppm
    render_board render_density_steps_$arith "$out" "$scn" -o "$out" --arith $arith --ncs 2 \
        --density-steps 8 || continue
    render_same render_density_steps_$arith "$ref" "$out"
done
"$LINKS1" ref "$scn" --arith float -o "$RENDER_TMP/density64-host-float.ppm" >/dev/null 2>&1
if [ -s "$RENDER_TMP/density64-host-float.ppm" ] && [ -s "$RENDER_TMP/density8-board-float.ppm" ] &&
    ! cmp -s "$RENDER_TMP/density64-host-float.ppm" "$RENDER_TMP/density8-board-float.ppm"; then
    echo "PASS render_density_steps_differ"
else
    echo "FAIL render_density_steps_differ: 8 and 64 steps gave the same image (or none)"
fi
