#!/usr/bin/env bash
# tests/sweeps/auto.sh: `--arith auto` on every sweep scene
# (docs/results/arith-auto.md).  For each scene of families.sh at
# SIZE (default 160x120) and each unit computer (--fpu vfp, --fpu none):
#   pick   what `links1 ref --arith auto` chose from its pre-render
#   truth  every candidate rendered at SIZE by its host build, PSNR against
#          the double build of the same scene; cost: NC instructions per
#          pixel of the same render on the board (links1 render
#          --count-insns, 2 NCs; the host's fixed formats other than Q12.19
#          take the fixed firmware's count), measured for every firmware
#          that has a candidate at or above TARGET dB; with VFP also float
#          and fixed Q12.19 escalated (--escalate, the -esc firmware)
#   best   the cheapest candidate at or above TARGET dB at SIZE
# Writes DIR/auto.tsv (every scene) and DIR/auto.md (a row a family:
# tests/sweeps/auto_summary.sh) and
# prints the summary: scenes where the pick keeps
# TARGET dB, and the largest cost of the pick over the best.
#   bash tests/sweeps/auto.sh [--out DIR]
# (LINKS1=DIR/links1 FW_DIR=DIR: a copy of build/ that no rebuild touches
# while it runs.)
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
BIN=$(dirname "$LINKS1") # links1-ref-* next to it
export FW_DIR=${FW_DIR:-build}
SIZE=${SIZE:-160x120}
TARGET=${TARGET:-40}
out=build/sweeps-auto
[ "${1:-}" = --out ] && out=$2
mkdir -p "$out/work"
tsv=$out/auto.tsv
. tests/sweeps/families.sh
family_work "$out/work" # the scenes and their maps

# label|host build|firmware whose cost it takes|esc (escalated: --escalate
# on both, the -esc firmware; with VFP only, as --arith auto's)
cands=("float|float|float|" "soft|float|soft|" "fixed Q12.19|fixed|fixed|")
add_host_fixed_cands '|'
cands+=("float escalated|float|float|esc" "fixed Q12.19 escalated|fixed|fixed|esc")

psnr() { # REF IMG
    "$LINKS1" compare "$1" "$2" --min-fraction 0 2>&1 | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p'
}
esc_flag() { # [esc]: a candidate's escalation, on the host as on the board
    [ -n "${1:-}" ] && echo --escalate || echo --no-escalate
}
board_cost() { # SCENE FIRMWARE [esc]: NC instructions per pixel
    local log=$out/work/board.log
    timeout 900 "$LINKS1" render "$1" --arith "$2" "$(esc_flag "${3:-}")" --ncs 2 --count-insns \
        -o "$out/work/board.png" >"$log" 2>&1 || { echo -; return; }
    local total
    total=$(grep -o 'NCs total [0-9]*' "$log" | grep -o '[0-9]*$')
    awk -v t="$total" -v s="$SIZE" 'BEGIN { split(s, d, "x"); printf "%.0f", t / (d[1] * d[2]) }'
}

printf 'family\tknob\tfpu\tpick\tpick_psnr\tpick_cost\tbest\tbest_psnr\tbest_cost\tpick_over_best\tcandidates\n' >"$tsv"
rm -f "$out"/work/*.png.done # a run stopped part way leaves its marks
for entry in "${families[@]}"; do
    IFS='|' read -r family knobs _ _ <<<"$entry"
    for knob in $knobs; do
        scn=$out/work/$family-$knob.scn
        family_scene "$family" "$knob" "$SIZE" >"$scn" || exit 1
        ref=$out/work/double.png
        if ! "$LINKS1" ref "$scn" --arith double -o "$ref" >"$out/work/double.log" 2>&1; then
            for fpu in vfp none; do
                printf '%s\t%s\t%s\trefused in every arithmetic\t\t\t\t\t\t\t\n' "$family" "$knob" \
                    "$fpu" >>"$tsv"
            done
            continue
        fi
        # every candidate's PSNR at SIZE; the cost of each firmware needed
        declare -A p=() cost=()
        for c in "${cands[@]}"; do
            IFS='|' read -r label build fw esc <<<"$c"
            img=$out/work/$build${esc:+-esc}.png
            [ -f "$img.done" ] || {
                "$BIN/links1-ref-$build" "$scn" "$(esc_flag "$esc")" -o "$img" >/dev/null 2>&1 &&
                    touch "$img.done"
            }
            p[$label]=$([ -f "$img.done" ] && psnr "$ref" "$img" || echo refused)
            if [ "${p[$label]}" != refused ] && awk -v q="${p[$label]}" -v t="$TARGET" 'BEGIN { exit !(q >= t) }' &&
                [ -z "${cost[$fw$esc]:-}" ]; then
                cost[$fw$esc]=$(board_cost "$scn" "$fw" "$esc")
            fi
        done
        rm -f "$out"/work/*.png.done
        for fpu in vfp none; do
            log=$out/work/auto-$fpu.log
            pick=-
            if "$LINKS1" ref "$scn" --arith auto --fpu "$fpu" --target-db "$TARGET" \
                    -o "$out/work/auto.png" >"$log" 2>&1; then
                pick=$(sed -nE 's/.*--arith auto picks (.*): the cheapest.*/\1/p' "$log")
            fi
            best=- list=
            for c in "${cands[@]}"; do
                IFS='|' read -r label _ fw esc <<<"$c"
                [ "$fpu" = none ] && { [ "$label" = float ] || [ -n "$esc" ]; } && continue
                list="$list$label ${p[$label]} dB ${cost[$fw$esc]:--}; "
                if awk -v q="${p[$label]}" -v t="$TARGET" 'BEGIN { exit !(q != "refused" && q >= t) }' &&
                    [ "${cost[$fw$esc]:--}" != - ]; then
                    if [ "$best" = - ] || [ "${cost[$fw$esc]}" -lt "$bestc" ] ||
                        { [ "${cost[$fw$esc]}" -eq "$bestc" ] &&
                          awk -v a="${p[$label]}" -v b="${p[$best]}" 'BEGIN { exit !(a > b) }'; }; then
                        best=$label bestc=${cost[$fw$esc]}
                    fi
                fi
            done
            pfw=- pesc=
            for c in "${cands[@]}"; do
                IFS='|' read -r label _ fw esc <<<"$c"
                [ "$label" = "$pick" ] && pfw=$fw pesc=$esc
            done
            pc=-
            if [ "$pfw" != - ]; then
                [ -z "${cost[$pfw$pesc]:-}" ] && cost[$pfw$pesc]=$(board_cost "$scn" "$pfw" "$pesc")
                pc=${cost[$pfw$pesc]}
            fi
            ratio=$(awk -v a="$pc" -v b="${bestc:-}" -v best="$best" \
                'BEGIN { if (a == "-" || best == "-") print "-"; else printf "%.2f", a / b }')
            [ "$pick" = - ] && pick="none: $(tail -n 1 "$log" | sed 's/.*--arith auto: //')"
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$family" "$knob" "$fpu" "$pick" \
                "${p[$pick]:--}" "$pc" "$best" "${p[$best]:--}" "${bestc:--}" "$ratio" "$list" >>"$tsv"
            bestc=
        done
        unset p cost
    done
done

# summary: per unit computer, scenes with a pick, picks below TARGET, the worst ratio
for fpu in vfp none; do
    awk -F'\t' -v f="$fpu" -v t="$TARGET" 'NR > 1 && $3 == f {
        n++
        if ($4 ~ /^refused/) { refused++; next }
        if ($4 ~ /^none/) { nopick++; if ($7 != "-") missed++; next }
        picks++
        if ($5 + 0 < t) below++
        if ($10 != "-" && $10 + 0 > worst) { worst = $10 + 0; where = $1 " " $2 }
        if ($7 == "-") nobest++
    }
    END {
        printf "auto --fpu %s: %d scenes; %d refused in every arithmetic; %d picks, %d of them below %s dB at full size; %d scenes without a pick (%d where some candidate reaches %s dB at full size); pick over the cheapest at %s dB: at most %.2fx (%s)\n",
            f, n, refused, picks, below, t, nopick, missed, t, t, worst, where
    }' "$tsv"
done

# the summary, one row a family (docs/figures/sweep-auto.md; every row stays in the .tsv)
bash tests/sweeps/auto_summary.sh "$tsv" "\`--arith auto\` on the sweep scenes at $SIZE (tests/sweeps/auto.sh)" >"$out/auto.md"
echo "auto: $tsv, $out/auto.md"
