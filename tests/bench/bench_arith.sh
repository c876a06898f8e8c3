#!/usr/bin/env bash
# bench_arith.sh: speed against accuracy of the board's three arithmetics.
# For each scene and arithmetic: the NCs' guest instructions for one frame
# (TCG plugin, --count-insns; the sum over NCs, which does not depend on how
# areas were shared out) and how far the board's image is from the host's
# double reference (fraction of pixels within 1/255 and 2/255 on every
# channel, largest difference).  Prints the table of
# docs/results/speed-vs-accuracy.md ("The three board arithmetics").
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
SIZE=${BENCH_SIZE:-160x120}
NCS=${BENCH_NCS:-4}
LIMIT_S=${BENCH_RUN_LIMIT_S:-900}
TMP=$(mktemp -d /tmp/links1-bench-arith.XXXXXX)
trap 'rm -rf "$TMP"' EXIT

fail() { echo "bench_arith: $*" >&2; exit 1; }

# within REF IMG K: "PERCENT|LARGEST" from links1 compare
within() {
    local line
    line=$("$LINKS1" compare "$1" "$2" --within "$3" --min-fraction 0 2>&1 | grep 'on every channel')
    [ -n "$line" ] || fail "links1 compare $1 $2 printed no summary"
    echo "$line" | sed -E 's/.*: ([0-9.]+)% .*largest difference ([0-9]+).*/\1|\2/'
}

echo "### Speed against accuracy ($SIZE, $NCS NCs, decreasing)"
echo
echo "| scene | arithmetic | NC instructions (M) | vs float | within 1/255 of double | within 2/255 | largest difference |"
echo "|---|---|---|---|---|---|---|"
for scene in scenes/demo.scn scenes/glass.scn scenes/molecule.scn build/scenes/city.scn; do
    name=$(basename "$scene" .scn)
    ref="$TMP/$name-double.ppm"
    "$LINKS1" ref "$scene" --arith double --size "$SIZE" -o "$ref" >/dev/null 2>&1 ||
        fail "links1 ref $scene failed"
    float_total=
    for arith in float soft fixed; do
        img="$TMP/$name-$arith.ppm"
        log="$TMP/$name-$arith.log"
        timeout "$LIMIT_S" "$LINKS1" render --quiet --count-insns "$scene" --arith "$arith" \
            --ncs "$NCS" --size "$SIZE" -o "$img" >"$log" 2>&1 ||
            fail "links1 render $scene --arith $arith failed: $(tail -n 1 "$log")"
        total=$(grep -o 'NCs total [0-9]*' "$log" | grep -o '[0-9]*$')
        [ -n "$total" ] || fail "no instruction counts in $log"
        [ -z "$float_total" ] && float_total=$total
        IFS='|' read -r w1 big < <(within "$ref" "$img" 1)
        IFS='|' read -r w2 _ < <(within "$ref" "$img" 2)
        awk -v n="$name" -v a="$arith" -v t="$total" -v f="$float_total" -v w1="$w1" -v w2="$w2" -v b="$big" \
            'BEGIN { printf "| %s | %s | %.1f | %.2fx | %s%% | %s%% | %s |\n", n, a, t / 1e6, t / f, w1, w2, b }'
    done
done
