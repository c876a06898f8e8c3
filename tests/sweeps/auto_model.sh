#!/usr/bin/env bash
# tests/sweeps/auto_model.sh: `--auto` (arithmetic, min_weight and density
# steps together) on the sweep scenes (docs/results/arith-auto.md, "--auto").
# For each scene of families.sh at SIZE (default 160x120) and each unit
# computer (--fpu vfp, --fpu none):
#   ref    the double build at the most accurate model: 256 density steps,
#          min_weight 1/4096 (--auto's reference, arith_auto.h)
#   pick   `links1 ref --auto` (its own 64x48 pre-render); its image at SIZE
#          against ref (the pick validated at full size), and its cost: NC
#          instructions per pixel of the same render on the board
#          (links1 render --count-insns, 2 NCs, the pick's firmware and model)
#   best   the cheapest configuration at SIZE over arithmetic (float, soft,
#          fixed Q12.19 and the host's Q13.18, Q15.16, Q17.14, Q19.12 at the fixed
#          firmware's cost) x min_weight (1/4096 .. 1/4, 2x apart) x density
#          steps (--auto's rungs, 2..256; scenes with a density sphere)
#          whose image at SIZE reaches TARGET dB against ref: per build, the
#          largest min_weight that reaches it (and for a density scene, per
#          min_weight the fewest steps), each such configuration counted on
#          the board
# The density_steps scenes differ only in their density_steps option, which
# every render here overrides: their best is found once.
# Writes DIR/auto_model.tsv (every scene) and DIR/auto_model.md (a row a
# family: tests/sweeps/auto_summary.sh) and prints per unit
# computer: picks, picks below TARGET at SIZE, the largest pick / best.
#   bash tests/sweeps/auto_model.sh [--out DIR]
# KNOBS=ends: only the first and last knob of each family (inner: the
# others); FAMILIES="a b":
# only those families, in that order.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
BIN=$(dirname "$LINKS1")
export FW_DIR=${FW_DIR:-build}
SIZE=${SIZE:-160x120}
TARGET=${TARGET:-40}
KNOBS=${KNOBS:-all}
FAMILIES=${FAMILIES:-}
out=build/sweeps-auto-model
[ "${1:-}" = --out ] && out=$2
mkdir -p "$out/work"
work=$out/work
tsv=$out/auto_model.tsv
. tests/sweeps/families.sh
family_work "$out/work" # the scenes and their maps

steps_ladder=(2 3 4 5 6 8 10 12 14 16 18 20 24 28 32 36 40 48 56 64 80 96 112 128 160 192 224 256)
weights=()
for e in 12 11 10 9 8 7 6 5 4 3 2; do weights+=("$(awk -v e=$e 'BEGIN { printf "%.17g", 2 ^ -e }')"); done
wname() { awk -v w="$1" 'BEGIN { printf "1/%d", 1 / w + 0.5 }'; }
# label|host build|firmware whose cost it takes
cands=("float|float|float" "soft|float|soft" "fixed Q12.19|fixed|fixed")
add_host_fixed_cands

psnr() { # REF IMG
    "$LINKS1" compare "$1" "$2" --min-fraction 0 2>&1 | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p'
}
ge() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && a + 0 >= b + 0) }'; }
knob_words() { # STEPS WEIGHT: the model's options
    [ "$density" = 1 ] && printf -- '--density-steps %s ' "$1"
    printf -- '--min-weight %s' "$2"
}
declare -A meets_cache=() cost_cache=()
meets() { # BUILD STEPS WEIGHT: 0 when the build's image at SIZE reaches TARGET
    local key="$1 $2 $3"
    if [ -z "${meets_cache[$key]:-}" ]; then
        local img=$work/truth.png q=refused
        # shellcheck disable=SC2046
        "$BIN/links1-ref-$1" "$scn" --no-escalate $(knob_words "$2" "$3") -o "$img" >/dev/null 2>&1 &&
            q=$(psnr "$ref" "$img")
        meets_cache[$key]=$q
    fi
    ge "${meets_cache[$key]}" "$TARGET"
}
cost() { # FIRMWARE STEPS WEIGHT [--escalate]: NC instructions per pixel at
    # SIZE into k (- when the board failed; no subshell: the count stays in
    # cost_cache); plain unless --escalate
    local key="$1 $2 $3 ${4:-}" esc=${4:---no-escalate}
    if [ -z "${cost_cache[$key]:-}" ]; then
        local log=$work/board.log total
        # shellcheck disable=SC2046
        if timeout 900 "$LINKS1" render "$scn" --arith "$1" "$esc" $(knob_words "$2" "$3") --ncs 2 \
                --count-insns --quiet -o "$work/board.png" >"$log" 2>&1; then
            total=$(grep -o 'NCs total [0-9]*' "$log" | grep -o '[0-9]*$')
            cost_cache[$key]=$(awk -v t="$total" -v s="$SIZE" \
                'BEGIN { split(s, d, "x"); printf "%.0f", t / (d[1] * d[2]) }')
        else
            cost_cache[$key]=-
        fi
    fi
    k=${cost_cache[$key]}
}
# frontier BUILD: into front[], "STEPS WEIGHT" of each configuration of the
# build that reaches TARGET and no other of them is cheaper in both knobs
# (no subshell: the renders stay in meets_cache)
frontier() {
    local b=$1 nw=${#weights[@]} ns=${#steps_ladder[@]}
    front=()
    if [ "$density" = 1 ]; then
        local si=0 j prev=
        for ((j = 0; j < nw; j++)); do
            while ((si < ns)) && ! meets "$b" "${steps_ladder[si]}" "${weights[j]}"; do si=$((si + 1)); done
            ((si < ns)) || break
            # a weight that needs no more steps than the next makes this one dominated
            [ -n "$prev" ] && [ "${prev%% *}" != "${steps_ladder[si]}" ] && front+=("$prev")
            prev="${steps_ladder[si]} ${weights[j]}"
        done
        [ -n "$prev" ] && front+=("$prev")
    else
        local lo=0 hi=$((nw - 1)) mid
        meets "$b" "$steps0" "${weights[0]}" || return 0
        while ((lo < hi)); do # the largest weight that reaches it
            mid=$(((lo + hi + 1) / 2))
            if meets "$b" "$steps0" "${weights[mid]}"; then lo=$mid; else hi=$((mid - 1)); fi
        done
        front+=("$steps0 ${weights[lo]}")
    fi
}

printf 'family\tknob\tfpu\tpick\tpick_psnr\tpick_cost\tbest\tbest_psnr\tbest_cost\tpick_over_best\n' >"$tsv"
declare -A best_of=() # the density scenes' best, per fpu
order=("${families[@]}")
if [ -n "$FAMILIES" ]; then # those families, in that order
    order=()
    for f in $FAMILIES; do
        for entry in "${families[@]}"; do [ "${entry%%|*}" = "$f" ] && order+=("$entry"); done
    done
fi
for entry in "${order[@]}"; do
    IFS='|' read -r family knobs _ _ <<<"$entry"
    read -ra kl <<<"$knobs"
    [ "$KNOBS" = ends ] && kl=("${kl[0]}" "${kl[${#kl[@]} - 1]}")
    [ "$KNOBS" = inner ] && kl=("${kl[@]:1:${#kl[@]}-2}")
    for knob in "${kl[@]}"; do
        scn=$work/$family-$knob.scn
        family_scene "$family" "$knob" "$SIZE" >"$scn" || exit 1
        density=0
        grep -q '^density' "$scn" && density=1
        steps0=$(sed -nE 's/.*density_steps ([0-9]+).*/\1/p' "$scn" | head -n 1)
        steps0=${steps0:-24}
        ref=$work/ref.png
        if ! "$BIN/links1-ref-double" "$scn" $(knob_words 256 "${weights[0]}") -o "$ref" \
                >"$work/ref.log" 2>&1; then
            for fpu in vfp none; do
                printf '%s\t%s\t%s\trefused in every arithmetic\t\t\t\t\t\t\n' "$family" "$knob" \
                    "$fpu" >>"$tsv"
            done
            continue
        fi
        # the caches hold one scene's renders, or the density_steps scenes'
        # (their renders all give their options): emptied on a new scene
        # of any other family and on the first density_steps scene
        if [ "$family" != density_steps ] || [ "${cached_family:-}" != density_steps ]; then
            meets_cache=()
            cost_cache=()
        fi
        cached_family=$family
        for fpu in vfp none; do
            # the truth: the cheapest configuration that reaches TARGET at SIZE
            if [ "$family" = density_steps ] && [ -n "${best_of[$fpu]:-}" ]; then
                IFS='|' read -r best bestq bestc <<<"${best_of[$fpu]}"
            else
                best=- bestq=- bestc=
                for c in "${cands[@]}"; do
                    IFS='|' read -r label build fw <<<"$c"
                    [ "$fpu" = none ] && [ "$label" = float ] && continue
                    frontier "$build"
                    for sw in "${front[@]}"; do
                        read -r s w <<<"$sw"
                        cost "$fw" "$s" "$w"
                        [ "$k" = - ] && continue
                        if [ -z "$bestc" ] || [ "$k" -lt "$bestc" ]; then
                            bestc=$k bestq=${meets_cache[$build $s $w]}
                            best="$label"
                            [ "$density" = 1 ] && best="$best, $s steps"
                            best="$best, min_weight $(wname "$w")"
                        fi
                    done
                done
                [ "$family" = density_steps ] && best_of[$fpu]="$best|$bestq|$bestc"
            fi
            # the pick, rendered at SIZE by links1 ref --auto
            log=$work/auto-$fpu.log
            pick=- pq=- pc=-
            if "$LINKS1" ref "$scn" --auto --fpu "$fpu" --target-db "$TARGET" \
                    -o "$work/auto.png" >"$log" 2>&1; then
                line=$(grep -- '--auto picks' "$log")
                pick=$(sed -nE 's/.*--auto picks (.*): the cheapest.*/\1/p' <<<"$line")
                plabel=$(sed -nE 's/^(.*) with .*/\1/p' <<<"$pick")
                ps=$(sed -nE 's/.* with ([0-9]+) density steps.*/\1/p' <<<"$pick")
                pw=$(sed -nE 's/.*min_weight 1\/([0-9]+).*/\1/p' <<<"$pick")
                pw=$(awk -v d="$pw" 'BEGIN { printf "%.17g", 1 / d }')
                pq=$(psnr "$ref" "$work/auto.png")
                pfw=- pesc=
                for c in "${cands[@]}"; do # an escalated pick costs on the -esc firmware
                    IFS='|' read -r label _ fw <<<"$c"
                    [ "$label" = "$plabel" ] && pfw=$fw
                    [ "$label escalated" = "$plabel" ] && pfw=$fw pesc=--escalate
                done
                [ "$pfw" != - ] && cost "$pfw" "${ps:-$steps0}" "$pw" $pesc && pc=$k
                pick="$plabel"
                [ -n "$ps" ] && pick="$pick, $ps steps"
                pick="$pick, min_weight $(wname "$pw")"
            else
                pick="none: $(tail -n 1 "$log" | sed 's/.*--auto: //')"
            fi
            ratio=$(awk -v a="$pc" -v b="${bestc:-}" \
                'BEGIN { if (a == "-" || b == "" || b == "-") print "-"; else printf "%.2f", a / b }')
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$family" "$knob" "$fpu" "$pick" \
                "$pq" "$pc" "$best" "$bestq" "${bestc:--}" "$ratio" >>"$tsv"
        done
    done
done

for fpu in vfp none; do
    awk -F'\t' -v f="$fpu" -v t="$TARGET" 'NR > 1 && $3 == f {
        n++
        if ($4 ~ /^refused/) { refused++; next }
        if ($4 ~ /^none/) { nopick++; if ($7 != "-") missed++; next }
        picks++
        if ($5 + 0 < t) below++
        if ($10 != "-" && $10 + 0 > worst) { worst = $10 + 0; where = $1 " " $2 }
    }
    END {
        printf "auto_model --fpu %s: %d scenes; %d refused in every arithmetic; %d picks, %d of them below %s dB at full size; %d scenes without a pick (%d where some configuration reaches %s dB); pick over the cheapest configuration at %s dB: at most %.2fx (%s)\n",
            f, n, refused, picks, below, t, nopick, missed, t, t, worst, where
    }' "$tsv"
done
# the summary, one row a family (docs/figures/sweep-auto-model.md; every row stays in the .tsv)
bash tests/sweeps/auto_summary.sh "$tsv" "\`--auto\` on the sweep scenes at $SIZE (tests/sweeps/auto_model.sh)" >"$out/auto_model.md"
echo "auto_model: $tsv, $out/auto_model.md"
