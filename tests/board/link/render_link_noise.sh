#!/usr/bin/env bash
# The --link-noise relay on a real board (host-tools/launcher/link_relay.h).  With no
# damage (rate 0) the relay is transparent: both paths give the host build's
# image byte for byte.  At 1e-3 per byte each way the retransmission
# (proto/link_arq.h) must give the exact image, exit 0, on every seed: three
# on the fast path, one on the serial path (~10 s).  At 1e-2 (fast path) a
# run ends with the exact image or a clear error that names the count of
# asks, resends or polls after which the link gave up; never a wrong image.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_link_noise_relay_fast render_link_noise_relay_serial \
    render_link_noise_1e-3_fast_1 render_link_noise_1e-3_fast_2 render_link_noise_1e-3_fast_3 \
    render_link_noise_1e-3_serial_5 render_link_noise_1e-2_fast_5 || exit 0
SIZE=64x48
scene=scenes/demo.scn
ref=$(render_ref $scene float $SIZE)
for path in fast serial; do
    out="$RENDER_TMP/relay-$path.ppm"
    render_board render_link_noise_relay_$path "$out" $scene -o "$out" --ncs 2 --size $SIZE \
        --link $path --link-noise 0 || continue
    render_same render_link_noise_relay_$path "$ref" "$out"
done
for run in 1e-3:fast:1 1e-3:fast:2 1e-3:fast:3 1e-3:serial:5 1e-2:fast:5; do
    IFS=: read -r rate path seed <<<"$run"
    name=render_link_noise_${rate}_${path}_$seed
    out="$RENDER_TMP/noise-$rate-$path-$seed.ppm" log="$RENDER_TMP/$name.log"
    start=$(date +%s)
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 2 --size $SIZE --link $path \
        --link-noise "$rate:$seed" $scene -o "$out" >"$log" 2>&1
    rc=$? took=$(($(date +%s) - start))
    echo "--- links1 render --link $path --link-noise $rate:$seed (exit $rc, $took s)"
    grep -v '^links1: the board dropped a frame from the host' "$log" | sed 's/^/    /'
    if [ -e "$out" ] && ! cmp -s "$ref" "$out"; then
        echo "FAIL $name: a wrong image was written"
    elif [ $rc -eq 0 ] && [ -e "$out" ]; then
        echo "PASS $name (exact image)"
    elif [ "$rate" = 1e-3 ]; then
        echo "FAIL $name: exit $rc after $took s: at 1e-3 the image must be exact"
    elif [ $rc -eq 1 ] && grep -qE 'the host link gave up: .*(after [0-9]+ (requests|resends)|[0-9]+ polls|no longer hold)' "$log"; then
        # it gave up by its own counts (asks, resends, polls), not a clock
        echo "PASS $name (clear error after $took s)"
    else
        echo "FAIL $name: exit $rc after $took s, no exact image and no clear error"
    fi
done
