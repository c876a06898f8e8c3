#!/usr/bin/env bash
# Both paths of the host link's bulk bytes (proto/hostlink.h): the same
# small scene rendered with the scene uploaded and the frame pulled through
# the board's shared RAM (--link fast) and through DATA frames (--link
# serial) gives the same image byte for byte, equal to the host build; the
# link checks move the pattern both ways through shared memory; a scene the
# board refuses on the fast path is reported and the next one renders.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_link_fast render_link_serial render_link_same render_link_times \
    render_link_refuse || exit 0
SIZE=64x48
scene=scenes/demo.scn
ref=$(render_ref $scene float $SIZE)
for path in fast serial; do
    out="$RENDER_TMP/demo-$path.ppm"
    render_board render_link_$path "$out" $scene -o "$out" --ncs 2 --size $SIZE \
        --link $path || continue
    render_same render_link_$path "$ref" "$out"
done
if [ -s "$RENDER_TMP/demo-fast.ppm" ] &&
    cmp -s "$RENDER_TMP/demo-fast.ppm" "$RENDER_TMP/demo-serial.ppm"; then
    echo "PASS render_link_same"
else
    echo "FAIL render_link_same: the fast and serial paths gave different images (or none)"
fi
# The summary line tells each path's upload and pull time.
if grep -q 'upload [0-9]* ms, pull [0-9]* ms' "$RENDER_TMP/render_link_fast.log" &&
    grep -q 'upload [0-9]* ms, pull [0-9]* ms' "$RENDER_TMP/render_link_serial.log"; then
    echo "PASS render_link_times"
else
    echo "FAIL render_link_times: a summary line lacks 'upload N ms, pull N ms'"
fi
# 8 MiB each way through shared memory, every byte checked.
board_selftest link_fast --ncs 1 --link fast --bytes $((8 << 20)) link-sink link-source
# A damaged scene refused on the fast path; the next one on the same board
# renders equal to the host build (a scene of its own small size: --size
# cannot apply to a compiled one).
good=scenes/pov/spheres.scn
ref=$(render_ref $good float 160x120)
damage=$(render_damaged_scene $good "$RENDER_TMP/bad.l1s") || echo "FAIL render_link_refuse: $damage"
log="$RENDER_TMP/refuse.log"
timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 2 --link fast \
    "$RENDER_TMP/bad.l1s" -o "$RENDER_TMP/bad.ppm" $good -o "$RENDER_TMP/next.ppm" \
    >"$log" 2>&1
rc=$?
echo "--- links1 render --link fast bad.l1s then $good (exit $rc)"; sed 's/^/    /' "$log"
if [ -s "$RENDER_TMP/bad.l1s" ]; then
    if [ $rc -eq 1 ] && grep -qF "$RENDER_DAMAGED_REFUSAL" "$log" &&
        cmp -s "$ref" "$RENDER_TMP/next.ppm"; then
        echo "PASS render_link_refuse"
    else
        echo "FAIL render_link_refuse: exit $rc (want 1), not the loader's '$RENDER_DAMAGED_REFUSAL', or the next scene differs"
    fi
fi
