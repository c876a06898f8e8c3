#!/usr/bin/env bash
# The long sweep of failed NCs (make test-full): every k from 1 to 7 of 8
# NCs, and 1, 32 and 63 of 64, each with mixed kinds at random points; then
# an animation whose first frame loses 2 of 4 NCs: every frame equals the
# host build's, and the later frames render on the NCs that are left.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_faults_full || exit 0
for k in 1 2 3 4 5 6 7; do
    render_faults_one render_faults_mixed_${k}of8 scenes/demo.scn 96x72 8 $k $((100 + k)) mixed
done
for k in 1 32 63; do
    render_faults_one render_faults_mixed_${k}of64 scenes/demo.scn 96x72 64 $k $((200 + k)) mixed
done
SIZE=96x72
ref=$(render_ref scenes/anim.scn float $SIZE 0:3)
out="$RENDER_TMP/anim_faults.ppm"
if render_board render_faults_anim "$out" scenes/anim.scn -o "$out" --ncs 4 --size $SIZE \
    --frames 0:3 --inject-faults 2:7; then
    for f in 0 1 2 3; do
        render_same render_faults_anim_frame$f "${ref%.ppm}-000$f.ppm" "${out%.ppm}-000$f.ppm"
    done
    later=$(grep -c '2 NC(s) out since earlier frames' "$RENDER_TMP/render_faults_anim.log")
    if [ "$later" = 3 ]; then
        echo "PASS render_faults_anim_later_frames"
    else
        echo "FAIL render_faults_anim_later_frames: want frames 1..3 to say 2 NCs are out, $later do"
    fi
fi
