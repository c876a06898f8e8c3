#!/usr/bin/env bash
# bench_big.sh: scenes of a quarter of a million triangles on the board
# (issue 8): SPD tetra 9 (262,144 triangles) and teapot 64 (269,824), each
# compiled (the compiler's own figures: bytes compiled, blob bytes on the
# board, each NC's clip lists), rendered on the board (links1 render
# --arith float --ncs 8 --count-insns at BENCH_BIG_SIZE, default 160x120)
# and on the host (links1 ref --arith float), the two images compared.
# One run each; prints a markdown table.  Takes many minutes.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SPD=${SPD:-build/links1-spd}
export FW_DIR=${FW_DIR:-build}
SIZE=${BENCH_BIG_SIZE:-160x120}
LIMIT_S=${BENCH_RUN_LIMIT_S:-3600}
make -s --no-print-directory build/links1 build/links1-ref-float build/links1-spd all >&2
TMP=$(mktemp -d /tmp/links1-bench-big.XXXXXX)
trap 'rm -rf "$TMP"' EXIT

echo "### Quarter-million-triangle scenes on the board ($SIZE, float, 8 NCs, one run)"
echo
echo "| scene | triangles | clusters | compiled bytes | blob bytes (board) | NC clip lists | board s | NC insns/ray | image vs host |"
echo "|---|---|---|---|---|---|---|---|---|"
for db in tetra-9 teapot-64; do
    scene="$TMP/$db.nff" # (teapot 64's text scene would pass 64 MiB)
    "$SPD" "${db%-*}" "${db#*-}" -o "$scene" --size "$SIZE" 2>"$TMP/spd.log" ||
        { echo "bench_big: links1-spd $db failed: $(cat "$TMP/spd.log")" >&2; exit 1; }
    "$LINKS1" compile "$scene" -o "$TMP/$db.l1s" >"$TMP/c.log" 2>&1 ||
        { echo "bench_big: compile $db failed: $(cat "$TMP/c.log")" >&2; exit 1; }
    read -r bytes prims clusters blob nc < <(sed -E -n \
        's/.*: ([0-9]+) bytes \(([0-9]+) primitives, ([0-9]+) clusters\); on the board: blob ([0-9]+) bytes of [0-9]+, NC clip lists ([0-9]+) bytes.*/\1 \2 \3 \4 \5/p' "$TMP/c.log")
    t0=$(date +%s.%N)
    if timeout "$LIMIT_S" "$LINKS1" render --quiet --count-insns "$TMP/$db.l1s" -o "$TMP/b.ppm" \
        --arith float --ncs 8 >"$TMP/b.log" 2>&1; then
        t1=$(date +%s.%N)
        secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.0f", b - a }')
        "$LINKS1" ref "$TMP/$db.l1s" -o "$TMP/r.ppm" --arith float >"$TMP/r.log" 2>&1
        rays=$(sed -n 's/.*rays: \([0-9]*\) primary, \([0-9]*\) shadow, \([0-9]*\) reflection, \([0-9]*\) refraction, \([0-9]*\) transmission.*/\1 \2 \3 \4 \5/p' "$TMP/r.log" |
               awk '{ print $1 + $2 + $3 + $4 + $5 }')
        ipr=$(grep 'NCs total' "$TMP/b.log" | sed -E 's/.*NCs total ([0-9]+).*/\1/' |
              awk -v r="$rays" '{ printf "%.0f", $1 / r }')
        same=differs
        cmp -s "$TMP/b.ppm" "$TMP/r.ppm" && same=same
    else
        secs="failed: $(tail -n 1 "$TMP/b.log")" ipr=- same=-
    fi
    echo "| $db | $prims | $clusters | $bytes | $blob | $nc | $secs | $ipr | $same |"
done
