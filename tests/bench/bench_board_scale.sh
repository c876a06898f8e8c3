#!/usr/bin/env bash
# bench_board_scale.sh: what the DM and the RC spend per triangle of a
# frame as the scene grows (issue 20), printed as the table of
# docs/results/board-scale.md.  Scenes: the SPD tetra at 4,096, 16,384 and
# 65,536 triangles (links1-spd tetra 5, 6, 7) and the teapot at size 8
# (65,408 triangles); each rendered once on the board,
#   links1 render SCENE --size 128x96 --ncs 8 --count-insns --trace T
# (float).  Per scene: the DM's and the RC's guest instructions for the
# whole command (the DM counts from the scene's upload: the link's check,
# the load, the frame's preparation) and the DM's preparation of the frame
# alone (the trace's dm_prepare span: what every later frame costs).
# BENCH_BEFORE_BUILD=DIR also runs each scene with DIR's links1 and
# firmware (another tree's build/, e.g. the commit before) and prints its
# figures beside these.  BENCH_BOARD_SCALE_SCENES picks scenes ("tetra 5,
# teapot 8").
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SPD=${SPD:-build/links1-spd}
export FW_DIR=${FW_DIR:-build}
BEFORE=${BENCH_BEFORE_BUILD:-}
SCENES=${BENCH_BOARD_SCALE_SCENES:-tetra 5, tetra 6, tetra 7, teapot 8}
SIZE=128x96
NCS=8
LIMIT_S=${BENCH_RUN_LIMIT_S:-1800}
make -s --no-print-directory build/links1 build/links1-spd >&2
TMP=$(mktemp -d /tmp/links1-bench-board-scale.XXXXXX)
trap 'rm -rf "$TMP"' EXIT

# run LINKS1 FW_DIR SCENE TAG: prints "DM RC PREPARE" (guest instructions)
run() {
    local bin=$1 fw=$2 scn=$3 tag=$4
    if ! FW_DIR=$fw timeout "$LIMIT_S" "$bin" render "$scn" --size $SIZE --ncs $NCS --count-insns \
            --trace "$TMP/$tag.trace" -o "$TMP/$tag.ppm" >"$TMP/$tag.log" 2>&1; then
        echo "bench_board_scale: $tag: the render failed:" >&2
        tail -3 "$TMP/$tag.log" >&2
        exit 1
    fi
    local dm rc prep
    dm=$(sed -n 's/^  DM \([0-9]*\), RC \([0-9]*\),.*/\1/p' "$TMP/$tag.log")
    rc=$(sed -n 's/^  DM \([0-9]*\), RC \([0-9]*\),.*/\2/p' "$TMP/$tag.log")
    prep=$(awk '$1 == "dm_prepare" { print $2 }' "$TMP/$tag.trace")
    if [ -z "$dm" ] || [ -z "$rc" ] || [ -z "$prep" ]; then
        echo "bench_board_scale: $tag: no instruction counts in the output" >&2
        exit 1
    fi
    echo "$dm $rc $prep"
}

# cell N TRIANGLES: "N (N / TRIANGLES)"
cell() { awk -v n="$1" -v t="$2" 'BEGIN { printf "%.1f M (%d)", n / 1e6, n / t + 0.5 }'; }

echo "### The DM's and the RC's guest instructions per frame, by triangles (float, $NCS NCs, $SIZE)"
echo
echo "Each cell: instructions of the whole render command (per triangle)."
echo
if [ -n "$BEFORE" ]; then
    echo "| scene | triangles | DM before | DM after | DM preparing the frame, before | after | RC before | RC after |"
    echo "|---|---|---|---|---|---|---|---|"
else
    echo "| scene | triangles | DM | DM preparing the frame | RC |"
    echo "|---|---|---|---|---|"
fi
IFS=',' read -ra LIST <<<"$SCENES"
for entry in "${LIST[@]}"; do
    read -r name size <<<"$entry"
    scn="$TMP/$name$size.scn"
    tris=$("$SPD" "$name" "$size" -o "$scn" 2>&1 | sed -n 's/.* \([0-9]*\) triangles$/\1/p')
    if [ -z "$tris" ] || [ "$tris" -eq 0 ]; then
        echo "bench_board_scale: links1-spd $name $size: no triangle count" >&2
        exit 1
    fi
    read -r dm rc prep <<<"$(run "$LINKS1" "$FW_DIR" "$scn" "$name$size")" || exit 1
    [ -n "$dm" ] || exit 1
    if [ -n "$BEFORE" ]; then
        read -r bdm brc bprep <<<"$(run "$BEFORE/links1" "$BEFORE" "$scn" "$name$size-before")" || exit 1
        [ -n "$bdm" ] || exit 1
        echo "| $name $size | $tris | $(cell "$bdm" "$tris") | $(cell "$dm" "$tris") | $(cell "$bprep" "$tris") | $(cell "$prep" "$tris") | $(cell "$brc" "$tris") | $(cell "$rc" "$tris") |"
    else
        echo "| $name $size | $tris | $(cell "$dm" "$tris") | $(cell "$prep" "$tris") | $(cell "$rc" "$tris") |"
    fi
done
