#!/usr/bin/env bash
# bench_render.sh: guest instructions of links1 render, counted per core by
# the TCG plugin (--count-insns), printed as the tables of
# docs/results/gigs-pipeline.md.  Counts cover the whole board session: boot, upload,
# preparing, rendering, pulling the frame.  NC work = an NC's count; the
# critical path of a frame = the largest NC count; speed-up over N NCs =
# (NC total of the 1-NC run) / (largest NC count of the N-NC run).  The
# counts start at each core's first frame (proto/insn_mark.h), so boot-time
# waits do not blur them.  Which NC gets which area depends on timing, so
# the largest NC varies from run to run: the 64-NC row is run three times.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
LIMIT_S=${BENCH_RUN_LIMIT_S:-900}
TMP=$(mktemp -d /tmp/links1-bench-render.XXXXXX)
trap 'rm -rf "$TMP"' EXIT

# run LABEL SCENE links1-render-args...: prints
# "LABEL|NC total|NC max|NC min|DM|RC|render ms"; exits the script on failure.
run() {
    local label=$1 scene=$2; shift 2
    local log="$TMP/run.log"
    if ! timeout "$LIMIT_S" "$LINKS1" render --quiet --count-insns "$scene" -o "$TMP/out.ppm" \
        "$@" >"$log" 2>&1; then
        echo "bench_render: $label failed:" >&2
        tail -n 5 "$log" >&2
        kill -TERM $$
    fi
    local line ms
    line=$(grep 'NCs total' "$log")
    ms=$(grep -o 'render [0-9]* ms' "$log" | grep -o '[0-9]*')
    echo "$line" | sed -E "s/^ *DM ([0-9]+), RC ([0-9]+), NCs total ([0-9]+) \(min ([0-9]+), max ([0-9]+).*/$label|\3|\5|\4|\1|\2|$ms/"
}

m() { awk -v x="$1" 'BEGIN { printf "%.1f", x / 1e6 }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }

DEMO=(scenes/demo.scn --size ${BENCH_SIZE:-320x240})
echo "### Speed-up with the number of NCs (demo.scn ${BENCH_SIZE:-320x240}, float, the board's default schedule)"
echo
echo "| NCs | NC total (M insns) | largest NC (M) | smallest NC (M) | total / largest | speed-up vs 1 NC | board render ms |"
echo "|---|---|---|---|---|---|---|"
one=
for n in 1 4 16 64 64 64; do
    IFS='|' read -r _ tot max min dm rc ms < <(run "$n" "${DEMO[@]}" --ncs $n)
    [ -z "$one" ] && one=$tot
    echo "| $n | $(m $tot) | $(m $max) | $(m $min) | $(ratio $tot $max) | $(ratio $one $max) | $ms |"
done
echo
echo "### Balancing modes and K (demo.scn ${BENCH_SIZE:-320x240}, float, 64 NCs)"
echo
echo "| mode | K | areas | largest NC (M insns) | NC total (M) | total / largest | RC (M) |"
echo "|---|---|---|---|---|---|---|"
for cfg in "static 0" "dynamic 64" "dynamic 256" "dynamic 1024" "decreasing 64" "decreasing 256" "decreasing 1024"; do
    set -- $cfg
    IFS='|' read -r _ tot max min dm rc ms < <(run "$1" "${DEMO[@]}" --ncs 64 --balance $1 \
        $([ "$2" != 0 ] && echo --areas $2))
    echo "| $1 | $([ "$2" = 0 ] && echo - || echo $2) | $(grep -o '[0-9]* areas' "$TMP/run.log" | head -1 | grep -o '[0-9]*') | $(m $max) | $(m $tot) | $(ratio $tot $max) | $(m $rc) |"
done
echo
CITY=(build/scenes/city.scn --size 160x120 --ncs 16)
echo "### Speed-ups switched off (city.scn 160x120, float, 16 NCs, decreasing)"
echo
echo "| speed-ups | NC total (M insns) | vs all on |"
echo "|---|---|---|"
all=
for cfg in "all on|" "no X clipping|--no-xclip" "no Y or X clipping|--no-yclip --no-xclip" \
    "bounding boxes only (no hierarchy, no clipping)|--no-yclip --no-xclip --no-hierarchy" \
    "none|--no-yclip --no-xclip --no-bbox --no-hierarchy"; do
    IFS='|' read -r _ tot max min dm rc ms < <(run x "${CITY[@]}" ${cfg#*|})
    [ -z "$all" ] && all=$tot
    echo "| ${cfg%%|*} | $(m $tot) | $(ratio $tot $all)x |"
done
echo
GLASS=(scenes/glass.scn --size 160x120 --ncs 16)
echo "### Refracting vs refractionless transmission (glass.scn 160x120, float, 16 NCs)"
echo
echo "| transmission | NC total (M insns) | vs refractionless depth 2 |"
echo "|---|---|---|"
base=
for cfg in "refractionless, max_depth 2|--max-depth 2 --refractionless on" \
    "refractionless, max_depth 6 (the scene's)|--max-depth 6 --refractionless on" \
    "refracting only, max_depth 16|--max-depth 16 --refractionless off"; do
    IFS='|' read -r _ tot max min dm rc ms < <(run x "${GLASS[@]}" ${cfg#*|})
    [ -z "$base" ] && base=$tot
    echo "| ${cfg%%|*} | $(m $tot) | $(ratio $tot $base)x |"
done
