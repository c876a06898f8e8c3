#!/usr/bin/env bash
# bench_link.sh: the host link's fast path (the board's RAM shared with the
# host, proto/hostlink.h LINK_BULK) against its targets: 8 MiB up in under
# 2 s, a 1024x1024 frame down in under 0.5 s.  Wall-clock figures, RUNS runs
# each (default 3), the median quoted:
#   up/down: links1 selftest --link fast --bytes 8388608 link-sink link-source
#            (the pattern, every byte checked on the other side)
#   pull:    links1 render --link fast|serial of a 1024x1024 one-sphere scene
#            ("pull N ms" of the summary line; serial once, for the ratio).
set -eu
cd "$(dirname "$0")/../.."
RUNS=${RUNS:-3}
tmp=$(mktemp -d /tmp/links1-bench-link.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
median() { sort -n | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'; }
# secs FILE CHECK: the seconds "(N s)" at the end of a selftest line.
secs() { grep "^selftest $2: ok" "$1" | sed 's/.*(\([0-9.]*\) s)$/\1/'; }
for i in $(seq "$RUNS"); do
    build/links1 selftest --ncs 1 --quiet --link fast --bytes $((8 << 20)) \
        link-sink link-source >"$tmp/st$i.log" 2>&1
    secs "$tmp/st$i.log" link-sink >>"$tmp/up"
    secs "$tmp/st$i.log" link-source >>"$tmp/down"
done
cat >"$tmp/big.scn" <<'SCN'
camera { eye 0 0 -5  look_at 0 0 0  up 0 1 0  fov 40 }
resolution 1024 1024
options { max_depth 0 }
light parallel { colour 1 1 1  direction 1 -1 1 }
material m { colour 0.8 0.5 0.3  dic 0.2 drc 0.8 }
sphere { material m  centre 0 0 0  radius 1.5 }
SCN
pull() { grep -o 'pull [0-9]* ms' "$1" | grep -o '[0-9]*'; }
for i in $(seq "$RUNS"); do
    build/links1 render --quiet --ncs 8 --link fast "$tmp/big.scn" -o "$tmp/fast.ppm" \
        >"$tmp/fast$i.log" 2>&1
    pull "$tmp/fast$i.log" >>"$tmp/pull_fast"
done
build/links1 render --quiet --ncs 8 --link serial "$tmp/big.scn" -o "$tmp/serial.ppm" \
    >"$tmp/serial.log" 2>&1
pull "$tmp/serial.log" >"$tmp/pull_serial"
cmp -s "$tmp/fast.ppm" "$tmp/serial.ppm" || { echo "bench_link: the paths' frames differ"; exit 1; }
up=$(median <"$tmp/up"); down=$(median <"$tmp/down"); pf=$(median <"$tmp/pull_fast")
ps=$(cat "$tmp/pull_serial")
verdict() { awk -v v="$1" -v t="$2" 'BEGIN {print (v < t) ? "target met" : "TARGET MISSED"}'; }
echo "bench_link: $RUNS runs each, medians"
echo "bench_link: 8 MiB up (fast):   $up s   (target < 2 s: $(verdict "$up" 2))"
echo "bench_link: 8 MiB down (fast): $down s"
echo "bench_link: 1024x1024 frame down: fast $pf ms (target < 500 ms: $(verdict "$pf" 500)), serial $ps ms (one run), $(awk -v a="$ps" -v b="$pf" 'BEGIN {printf "%.0fx", b ? a / b : 0}') faster"
