#!/usr/bin/env bash
# bench_wallclock.sh: where the wall time of `links1 render` goes on the
# host (the compile with the boot beside it, the rest of the boot, upload,
# the DM's load with frame 0's preparation, render,
# pull, write, shutdown), and the
# 1 -> 2 NC wall-clock ratio of the frame on the host's cores, with the
# host cores QEMU used while rendering.  Wall time on a shared host is
# noisy: each NC count runs BENCH_WALL_RUNS times (default 3); medians.
#   bash tests/bench/bench_wallclock.sh          (demo.scn at 512x480)
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
RUNS=${BENCH_WALL_RUNS:-3}
SIZE=${BENCH_WALL_SIZE:-512x480}
TMP=$(mktemp -d /tmp/links1-bench-wall.XXXXXX)
trap 'rm -rf "$TMP"' EXIT
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "### Wall time of links1 render (demo.scn $SIZE, float, decreasing; median of $RUNS)"
echo
echo "host: $(nproc) cores; $(uptime | sed 's/.*load average/load average/')"
echo
echo "| NCs | total ms | compile (the board booting) | boot after it | upload | load (DM: checks, frame 0 prepared) | frame | pull | write | shutdown | QEMU host cores while rendering |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for n in 1 2; do
    : >"$TMP/lines"
    for r in $(seq "$RUNS"); do
        timeout 900 "$LINKS1" render scenes/demo.scn --size "$SIZE" --ncs "$n" \
            -o "$TMP/out.ppm" >"$TMP/log" 2>&1 || { echo "bench_wallclock: render failed:" >&2; tail -3 "$TMP/log" >&2; exit 1; }
        # The numbers of the wall line in order: total, compile, boot,
        # upload, load, frames, prepare, render, pull, write, shutdown,
        # other, QEMU CPU ms, cores.
        grep 'links1 render: wall' "$TMP/log" | sed 's/^links1 render: //' | grep -o '[-0-9.]\+' |
            tr '\n' ' ' | awk '{ print $1, $2, $3, $4, $5, $6, $9, $10, $11, $14 }' >>"$TMP/lines"
    done
    row="| $n"
    for c in 1 2 3 4 5 6 7 8 9 10; do
        row="$row | $(awk -v c=$c '{ print $c }' "$TMP/lines" | median)"
    done
    echo "$row |"
    awk '{ print $6 }' "$TMP/lines" | median >"$TMP/frame-$n"
done
echo
awk -v a="$(cat "$TMP/frame-1")" -v b="$(cat "$TMP/frame-2")" \
    'BEGIN { printf "Frame wall time, 1 NC over 2 NCs: %.2fx (median frames %d ms and %d ms).\n", a / b, a, b }'
