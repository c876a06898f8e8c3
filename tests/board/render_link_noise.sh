#!/usr/bin/env bash
# The --link-noise relay on a real board (host-tools/link_relay.h).  With no
# damage (rate 0) the relay is transparent: both paths give the host build's
# image byte for byte.  With damage the link does not yet retransmit (issue
# 12's target, an exact frame at 1e-3, is not met): each run must then end
# with an exact image or, within seconds, a clear error, and never write a
# wrong image.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/render_lib.sh"
board_ready render_link_noise_relay_fast render_link_noise_relay_serial \
    render_link_noise_1e-3_fast render_link_noise_1e-3_serial render_link_noise_1e-2_fast || exit 0
SIZE=64x48
scene=scenes/demo.scn
ref=$(render_ref $scene float $SIZE)
for path in fast serial; do
    out="$RENDER_TMP/relay-$path.ppm"
    render_board render_link_noise_relay_$path "$out" $scene -o "$out" --ncs 2 --size $SIZE \
        --link $path --link-noise 0 || continue
    render_same render_link_noise_relay_$path "$ref" "$out"
done
for run in 1e-3:fast 1e-3:serial 1e-2:fast; do
    rate=${run%%:*} path=${run#*:}
    name=render_link_noise_${rate}_$path
    out="$RENDER_TMP/noise-$rate-$path.ppm" log="$RENDER_TMP/$name.log"
    start=$(date +%s)
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 2 --size $SIZE --link $path \
        --link-noise "$rate:5" $scene -o "$out" >"$log" 2>&1
    rc=$? took=$(($(date +%s) - start))
    echo "--- links1 render --link $path --link-noise $rate:5 (exit $rc, $took s)"
    sed 's/^/    /' "$log"
    if [ -e "$out" ] && ! cmp -s "$ref" "$out"; then
        echo "FAIL $name: a wrong image was written"
    elif [ $rc -eq 0 ] && [ -e "$out" ]; then
        echo "PASS $name (exact image)"
    elif [ $rc -eq 1 ] && [ $took -le 20 ] &&
        grep -qE 'lost a frame|dropped a frame|no .* from the board within|was not loaded' "$log"; then
        echo "PASS $name (clear error after $took s)"
    else
        echo "FAIL $name: exit $rc after $took s, no exact image and no clear error"
    fi
done
