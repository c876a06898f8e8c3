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
#   FLAG_SCENES="demo glass molecule" FLAG_SIZE=320x240 FLAG_PROGS="links1-ref-fixed12 ..."
# A scene named FAMILY:KNOB is a sweep family's (tests/sweeps/families.sh);
# FLAG_FAMILIES=1 scores every family at every knob instead (at FLAG_SIZE,
# default 160x120 then) and ends with each family's worst precision and
# recall per program over its knobs.
set -eu
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
out=${1:-build/bench-flags}
. tests/sweeps/families.sh
if [ "${FLAG_FAMILIES:-0}" = 1 ]; then
    SCENES=""
    for f in "${families[@]}"; do
        IFS='|' read -r fam knobs _ <<<"$f"
        for k in $knobs; do SCENES+=" $fam:$k"; done
    done
    SIZE=${FLAG_SIZE:-160x120}
else
    SCENES=${FLAG_SCENES:-demo glass molecule}
    SIZE=${FLAG_SIZE:-320x240}
fi
mkdir -p "$out"
family_work "$out" # the family scenes' maps below their directory
progs=${FLAG_PROGS:-links1-ref-float links1-ref-fixed links1-ref-fixed18 links1-ref-fixed16 links1-ref-fixed14 links1-ref-fixed12}
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
    scn="$(scene_of $s)"
    case $s in *:*)
        scn=$out/${s/:/-}.scn
        family_scene "${s%%:*}" "${s#*:}" "$SIZE" >"$scn" ;;
    esac
    ref=$out/$s-double.ppm
    if ! build/links1-ref-double "$scn" --size "$SIZE" -o "$ref" >"$out/$s-double.log" 2>&1; then
        # a knob the double build refuses (a sweep's refused cell): no reference
        printf '%s\tlinks1-ref-double\trefused\t-\t-\t-\n' "$s" >>"$tsv"
        continue
    fi
    # plain and marked: the arithmetic's own pixels (--no-escalate):
    # escalated, they would be double's and no flag could be scored
    for p in $progs; do
        plain=$out/$s-$p.ppm
        if ! build/$p "$scn" --size "$SIZE" --no-escalate -o "$plain" >"$out/$s-$p.log" 2>&1; then
            printf '%s\t%s\trefused\t-\t-\t-\n' "$s" "$p" >>"$tsv" # the format refuses the scene
            continue
        fi
        build/$p "$scn" --size "$SIZE" --no-escalate --mark-lost -o "$out/$s-$p-marked.ppm" \
            >"$out/$s-$p-marked.log" 2>&1 || true
        build/$p "$scn" --size "$SIZE" --check-lost --mark-lost \
            -o "$out/$s-$p-checked.ppm" >"$out/$s-$p-checked.log" 2>&1 || true
        printf '%s\t%s\tbounds\t%s\n' "$s" "$p" "$(score "$ref" "$plain" "$out/$s-$p-marked.ppm")" >>"$tsv"
        printf '%s\t%s\tchecked\t%s\n' "$s" "$p" "$(score "$ref" "$plain" "$out/$s-$p-checked.ppm")" >>"$tsv"
    done
done
column -t -s$'\t' "$tsv"
if [ "${FLAG_FAMILIES:-0}" = 1 ]; then
    # each family's worst over its knobs, per program and kind of flag:
    # precision where something was flagged, recall where a pixel was beyond
    echo
    awk -F'\t' 'NR > 1 && $3 != "refused" {
            split($1, a, ":"); k = a[1] "\t" $2 "\t" $3
            if (!(k in minp)) { minp[k] = "-"; minr[k] = "-"; order[++n] = k }
            if ($4 + 0 > 0 && $5 != "?" && $5 != "" && (minp[k] == "-" || $5 + 0 < minp[k] + 0)) minp[k] = $5
            if ($6 != "?" && $6 != "" && $6 != "-" && (minr[k] == "-" || $6 + 0 < minr[k] + 0)) minr[k] = $6
        }
        END {
            print "family\tprogram\tflags\tworst precision %\tworst recall %"
            for (i = 1; i <= n; i++) print order[i] "\t" minp[order[i]] "\t" minr[order[i]]
        }' "$tsv" | tee "$out/flags-families.tsv" | column -t -s$'\t'
fi
