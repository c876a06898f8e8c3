#!/usr/bin/env bash
# tests/bench/bench_flags.sh: what a precision flag means, before and after
# checking it (links1 ref --mark-lost, and --check-lost --mark-lost).  For
# each scene and arithmetic (float; fixed Q12.19 and the other fixed
# formats' host builds), the flags are scored against the double build
# with links1 compare --flags: precision, the share of flagged pixels that
# are really beyond 2/255 of double; recall, the share of pixels beyond
# 2/255 (edges moved by under a pixel aside) that were flagged.  Host only,
# one run (counts, not times).
#   bash tests/bench/bench_flags.sh [OUT-DIR]   (default build/bench-flags)
#   FLAG_SCENES="demo glass molecule" FLAG_SIZE=320x240
set -eu
cd "$(dirname "$0")/../.."
out=${1:-build/bench-flags}
SCENES=${FLAG_SCENES:-demo glass molecule}
SIZE=${FLAG_SIZE:-320x240}
mkdir -p "$out"
progs="links1-ref-float links1-ref-fixed links1-ref-fixed14 links1-ref-fixed16 links1-ref-fixed18"
make -s --no-print-directory build/links1 build/links1-ref-double $(printf 'build/%s ' $progs)

# score REF PLAIN MARKED: "flagged<TAB>precision %<TAB>recall %" of compare --flags
score() {
    local log
    log=$(build/links1 compare "$1" "$2" --flags "$3" --min-precision 0 --min-recall 0 2>&1 || true)
    local flagged prec rec
    flagged=$(echo "$log" | sed -nE 's/.*: ([0-9]+) of [0-9]+ pixels flagged.*/\1/p' | head -n 1)
    prec=$(echo "$log" | sed -nE 's/.*precision ([0-9.]+)%.*/\1/p' | head -n 1)
    rec=$(echo "$log" | sed -nE 's/.*recall ([0-9.]+)%.*/\1/p' | head -n 1)
    printf '%s\t%s\t%s' "${flagged:-?}" "${prec:-?}" "${rec:-?}"
}

tsv=$out/flags.tsv
printf 'scene\tprogram\tflags\tflagged\tprecision_pct\trecall_pct\n' >"$tsv"
for s in $SCENES; do
    ref=$out/$s-double.ppm
    build/links1-ref-double "scenes/$s.scn" --size "$SIZE" -o "$ref" >/dev/null 2>&1
    for p in $progs; do
        plain=$out/$s-$p.ppm
        build/$p "scenes/$s.scn" --size "$SIZE" -o "$plain" >/dev/null 2>&1
        build/$p "scenes/$s.scn" --size "$SIZE" --mark-lost -o "$out/$s-$p-marked.ppm" \
            >"$out/$s-$p-marked.log" 2>&1
        build/$p "scenes/$s.scn" --size "$SIZE" --check-lost --mark-lost \
            -o "$out/$s-$p-checked.ppm" >"$out/$s-$p-checked.log" 2>&1
        printf '%s\t%s\tbounds\t%s\n' "$s" "$p" "$(score "$ref" "$plain" "$out/$s-$p-marked.ppm")" >>"$tsv"
        printf '%s\t%s\tchecked\t%s\n' "$s" "$p" "$(score "$ref" "$plain" "$out/$s-$p-checked.ppm")" >>"$tsv"
    done
done
column -t -s$'\t' "$tsv"
