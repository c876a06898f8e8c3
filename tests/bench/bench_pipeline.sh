#!/usr/bin/env bash
# tests/bench/bench_pipeline.sh: how much of the DM's preparation of an
# animation's frames the NCs' rendering hides (the paper's pipelining: the
# DM prepares frame k+1 while the NCs render frame k; `links1 render
# --frames` does so).  Counted in guest instructions, not wall time: each
# frame is rendered once with --trace (docs/trace.md), which records the
# DM's preparation of that frame (dm_prepare) and the NCs' work, and
# `links1 replay --pipelined` replays the frame on equal-speed unit
# computers (1 MIPS, the replay's serial lines) without its own
# preparation: the time the DM has to prepare the next frame.
#
#   frame k's preparation is hidden up to min(prep(k), render(k-1)).
#
# The first frame's preparation is done at the scene's upload, before any
# frame renders: it is reported apart and, in the second share, counted
# as not hidden.
#
# Usage: bash tests/bench/bench_pipeline.sh [SCENE]   (default scenes/fly.scn)
#   BENCH_NCS (default 8), BENCH_SIZE (default the scene's), BENCH_FRAMES A:B
#   (default every frame of the scene, from its header), BENCH_ARITH (float),
#   BENCH_ARGS (more links1 render options, split at spaces: --world-space).
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
scene=${1:-scenes/fly.scn}
ncs=${BENCH_NCS:-8}
arith=${BENCH_ARITH:-float}
T=$(mktemp -d /tmp/links1-bench-pipeline.XXXXXX)
trap 'rm -rf "$T"' EXIT
frames=${BENCH_FRAMES:-}
if [ -z "$frames" ]; then
    n=$(awk '/animation *\{/ { for (i = 1; i <= NF; i++) if ($i == "frames") print $(i + 1) }' "$scene" | head -n 1)
    frames="0:$(( ${n:-1} - 1 ))"
fi
first=${frames%%:*} last=${frames##*:}
size_args=()
[ -n "${BENCH_SIZE:-}" ] && size_args=(--size "$BENCH_SIZE")
read -r -a more_args <<<"${BENCH_ARGS:-}"
size_args+=("${more_args[@]}")
echo "bench_pipeline: $scene frames $first..$last, $ncs NCs, $arith${BENCH_SIZE:+, $BENCH_SIZE}${BENCH_ARGS:+, $BENCH_ARGS}"
printf '%-6s %14s %16s %22s\n' frame "DM prepare" "NCs' frame (ms" "prepare hidden behind"
printf '%-6s %14s %16s %22s\n' "" "(insns)" "at 1 MIPS)" "the frame before"
prev_ms=""
sum_prep=0 sum_hidden=0 prep_first=0
for ((f = first; f <= last; f++)); do
    tr="$T/f$f.trace"
    if ! "$LINKS1" render "$scene" --frame "$f" --ncs "$ncs" --arith "$arith" "${size_args[@]}" \
        --trace "$tr" -o "$T/f$f.png" >"$T/f$f.log" 2>&1; then
        echo "bench_pipeline: frame $f: links1 render failed: $(tail -n 1 "$T/f$f.log")"
        exit 1
    fi
    prep=$(awk '$1 == "dm_prepare" { print $2 }' "$tr")
    ms=$("$LINKS1" replay "$tr" --ncs "$ncs" --pipelined | awk '$1 == "ncs" { for (i = 1; i < NF; i++) if ($i == "frame_ms") print $(i + 1) }')
    if [ -z "$prep" ] || [ -z "$ms" ]; then
        echo "bench_pipeline: frame $f: no dm_prepare or frame_ms in the trace or its replay"
        exit 1
    fi
    if [ -z "$prev_ms" ]; then
        prep_first=$prep
        hidden="(at the upload)"
    else
        # at 1 MIPS an instruction is a microsecond
        h=$(awk -v p="$prep" -v r="$prev_ms" 'BEGIN { x = r * 1000; print (p < x ? p : x) }')
        sum_prep=$((sum_prep + prep))
        sum_hidden=$(awk -v a="$sum_hidden" -v b="$h" 'BEGIN { print a + b }')
        hidden=$(awk -v h="$h" -v p="$prep" 'BEGIN { printf "%.1f%%", p ? 100 * h / p : 100 }')
    fi
    printf '%-6s %14s %16s %22s\n' "$f" "$prep" "$ms" "$hidden"
    prev_ms=$ms
done
awk -v h="$sum_hidden" -v p="$sum_prep" -v p0="$prep_first" 'BEGIN {
    if (p > 0) printf "hidden: %.2f%% of the preparation of frames after the first (%d of %d insns)\n", 100 * h / p, h, p
    printf "hidden: %.2f%% of every frame'"'"'s preparation, the first (%d insns, at the upload) counted as not hidden\n", 100 * h / (p + p0), p0
}'
