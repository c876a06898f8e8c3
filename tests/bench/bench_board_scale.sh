#!/usr/bin/env bash
# bench_board_scale.sh: what the board spends as the scene grows
# (docs/results/board-scale.md): the DM and the RC per triangle of a frame,
# and the NCs per ray at a small and a large frame, with the board's
# choice of clipping (auto: the paper's lists where few clusters cover a
# pixel, the hierarchy where many) and with each method alone.  Scenes: the SPD
# tetra at 4,096 to 262,144 triangles (links1-spd tetra 6..9) and the
# teapot at 67,328 (teapot 32), each rendered on the board (float, 8 NCs):
#   links1 render SCENE --size 128x96 --count-insns --trace T    (DM, RC, NCs)
#   links1 render SCENE --size 512x480 --count-insns             (NCs)
#   links1 render SCENE --size 128x96 --count-insns --clip lists (NCs)
#   links1 render SCENE --size 128x96 --count-insns --clip tree  (NCs)
# Per triangle: the DM's and the RC's guest instructions for the whole
# command (the DM counts from the scene's upload: the link's check, the
# load, the frame's preparation), and the DM's preparation of the frame
# alone (the trace's dm_prepare span: what every later frame costs).  Per
# ray (primary + shadow + secondary): the NCs' instructions summed.
# Prints a markdown table and draws BENCH_OUT/board-scale.png (gnuplot; a
# temporary directory unless BENCH_OUT is given).  BENCH_BOARD_SCALE_SCENES
# picks scenes ("tetra 6, teapot 32").  One run each.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SPD=${SPD:-build/links1-spd}
export FW_DIR=${FW_DIR:-build}
SCENES=${BENCH_BOARD_SCALE_SCENES:-tetra 6, tetra 7, tetra 8, tetra 9, teapot 32}
NCS=8
LIMIT_S=${BENCH_RUN_LIMIT_S:-1800}
make -s --no-print-directory build/links1 build/links1-spd all >&2
TMP=$(mktemp -d /tmp/links1-bench-board-scale.XXXXXX)
trap 'rm -rf "$TMP"' EXIT
OUT=${BENCH_OUT:-$TMP}
mkdir -p "$OUT"

# run SCENE TAG SIZE ARGS...: the render's log in $TMP/TAG.log
run() {
    local scn=$1 tag=$2 size=$3
    shift 3
    if ! timeout "$LIMIT_S" "$LINKS1" render "$scn" --size "$size" --ncs $NCS --count-insns \
            -o "$TMP/$tag.ppm" "$@" >"$TMP/$tag.log" 2>&1; then
        echo "bench_board_scale: $tag: the render failed:" >&2
        tail -3 "$TMP/$tag.log" >&2
        exit 1
    fi
}
# per_ray TAG: the NCs' instructions over the rays of every kind
per_ray() {
    local total rays
    total=$(sed -nE 's/^  DM [0-9]+, RC [0-9]+, NCs total ([0-9]+).*/\1/p' "$TMP/$1.log")
    rays=$(sed -nE 's/.*rays ([0-9]+) primary, ([0-9]+) shadow, ([0-9]+) reflection, ([0-9]+) refraction, ([0-9]+) transmission.*/\1 \2 \3 \4 \5/p' "$TMP/$1.log" |
        awk '{ print $1 + $2 + $3 + $4 + $5 }')
    [ -n "$total" ] && [ -n "$rays" ] || { echo "bench_board_scale: $1: no counts" >&2; exit 1; }
    awk -v t="$total" -v r="$rays" 'BEGIN { printf "%.0f", t / r }'
}

echo "### The board as the scene grows (float, $NCS NCs, one run each)"
echo
echo "Guest instructions: the DM's and the RC's per triangle (whole command at 128x96; the"
echo "DM's preparation of one frame alone), the NCs' per ray (the board's choice of clipping;"
echo "and at 128x96 the paper's lists alone, --clip lists, and the hierarchy alone, --clip tree)."
echo
echo "| scene | triangles | DM per triangle | DM preparing a frame, per triangle | RC per triangle | NC per ray, 128x96 | NC per ray, 512x480 | 128x96, lists | 128x96, hierarchy |"
echo "|---|---|---|---|---|---|---|---|---|"
: >"$TMP/scale.dat"
IFS=',' read -ra LIST <<<"$SCENES"
for entry in "${LIST[@]}"; do
    read -r name size <<<"$entry"
    tag=$name$size
    scn="$TMP/$tag.nff"
    tris=$("$SPD" "$name" "$size" -o "$scn" 2>&1 | sed -n 's/.* \([0-9]*\) triangles$/\1/p')
    if [ -z "$tris" ] || [ "$tris" -eq 0 ]; then
        echo "bench_board_scale: links1-spd $name $size: no triangle count" >&2
        exit 1
    fi
    run "$scn" "$tag-small" 128x96 --trace "$TMP/$tag.trace"
    run "$scn" "$tag-large" 512x480
    run "$scn" "$tag-lists" 128x96 --clip lists
    run "$scn" "$tag-tree" 128x96 --clip tree
    read -r dm rc < <(sed -nE 's/^  DM ([0-9]+), RC ([0-9]+),.*/\1 \2/p' "$TMP/$tag-small.log")
    prep=$(awk '$1 == "dm_prepare" { print $2 }' "$TMP/$tag.trace")
    small=$(per_ray "$tag-small") large=$(per_ray "$tag-large") lists=$(per_ray "$tag-lists")
    tree=$(per_ray "$tag-tree")
    awk -v s="$name $size" -v t="$tris" -v dm="$dm" -v p="$prep" -v rc="$rc" -v a="$small" \
        -v b="$large" -v c="$lists" -v d="$tree" 'BEGIN {
            printf "| %s | %d | %.0f | %.0f | %.0f | %d | %d | %d | %d |\n", s, t, dm / t, p / t, rc / t, a, b, c, d }'
    [ "$name" = tetra ] && echo "$tris $small $large $lists $tree" >>"$TMP/scale.dat"
done
echo
awk 'NR == 1 { a = $2; b = $3; c = $4; d = $5 } END {
    printf "NC per ray, the largest tetra over the smallest: %.2fx at 128x96, %.2fx at 512x480; at 128x96 the lists alone %.2fx, the hierarchy alone %.2fx\n", $2 / a, $3 / b, $4 / c, $5 / d }' "$TMP/scale.dat"
gnuplot <<GP || { echo "bench_board_scale: gnuplot failed" >&2; exit 1; }
set terminal pngcairo size 800,520
set output "$OUT/board-scale.png"
set title "NC instructions per ray on the board, SPD tetra (float, $NCS NCs)"
set xlabel "triangles"; set ylabel "guest instructions per ray"
set logscale xy; set key top left; set grid
plot "$TMP/scale.dat" using 1:2 title "the board's choice (default), 128x96" with linespoints pt 7 lw 2, \
     "$TMP/scale.dat" using 1:3 title "the board's choice (default), 512x480" with linespoints pt 5 lw 2, \
     "$TMP/scale.dat" using 1:4 title "the paper's lists alone (--clip lists), 128x96" with linespoints pt 9, \
     "$TMP/scale.dat" using 1:5 title "the hierarchy alone (--clip tree), 128x96" with linespoints pt 11
GP
echo "chart: $OUT/board-scale.png"
