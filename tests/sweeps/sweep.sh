#!/usr/bin/env bash
# tests/sweeps/sweep.sh: where each arithmetic breaks (docs/results/sweeps.md).
#
#   bash tests/sweeps/sweep.sh [--quick] [--out DIR]
#
# For every scene family of make_scene.py, each knob value and each
# arithmetic (double, float = soft on the host, fixed), renders the scene
# with links1 ref (plainly and with --mark-lost) and compares:
#   error  against the double build at the same knob (for the families
#          whose image should not change, families.sh's "same": scale,
#          cluster_scale, density_steps, against the double build at the
#          first knob): share of pixels beyond 2/255, PSNR;
#   flags  against the double build at the same knob with --flagged: the
#          share of pixels beyond 2/255 that were NOT painted as lost, of
#          all pixels and of those not explained by a move of less than a
#          pixel (links1 compare --silhouette --moved: next to an edge of
#          the double image, or within 2/255 of a pixel next to it there:
#          an edge or a thin object moved by less than a pixel flips the
#          pixels along it, in any arithmetic; docs/results/sweeps.md).
# A refused scene is a result too (the refusal names the reason).
# Writes DIR/sweep.tsv (one line per family, knob, arithmetic), DIR/breaks.md
# (the knob where each arithmetic first has more than 1% of pixels beyond
# 2/255, or is refused) and, with gnuplot, DIR/sweep-FAMILY.png.
# --quick: 64x48 pixels, fewer knobs, flags only (make test:
# tests/sweeps/flagged.sh).
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
out=build/sweeps size=160x120 quick=0
while [ $# -gt 0 ]; do
    case $1 in
        --quick) quick=1 size=64x48 ;;
        --out) out=$2; shift ;;
        *) echo "usage: sweep.sh [--quick] [--out DIR]" >&2; exit 2 ;;
    esac
    shift
done
mkdir -p "$out/work"
export MODEL_DIR=$out/work/models # make_scene.py model_scale's glTF files
tsv=$out/sweep.tsv

. tests/sweeps/families.sh # families=(...)
family_work "$out/work" # the scenes and their maps
if [ $quick = 1 ]; then
    families=(
        "scale|1 30 100 1000|scene scale|1|1"
        "scale_down|1 0.03|scene scale|1|1"
        "cluster_scale|1 1000000|cluster scale|1|1"
        "cluster_scale_down|1 0.01 1e-06|cluster scale|1|1"
        "model_scale|1 1e-06|model node scale|1|1"
        "grazing|10 0.5|degrees above the floor|1|0"
        "coincident|0.01 0.0001|gap|1|0"
        "thin_triangles|100 10000|length / width|1|0"
        "tir_chain|2 8|max_depth|0|0"
        "ellipsoid_ratio|10 1000|axis ratio|1|0"
        "map_repeat|10 3000|repeats|1|0"
        "density_steps|64 8|density root-finder steps|1|1"
    )
fi

# field N of the compare summary: "PCT|PSNR" (PCT beyond K/255)
measure() { # REF IMG K [--flagged]
    local r
    r=$("$LINKS1" compare "$1" "$2" --within "$3" --min-fraction 0 ${4:-} 2>&1)
    if [ $? -gt 1 ]; then # compare itself failed: no measure
        echo "-|-"
        return
    fi
    local within psnr
    within=$(echo "$r" | sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p')
    psnr=$(echo "$r" | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
    awk -v w="${within:-0}" -v p="${psnr:-0}" 'BEGIN { printf "%.4f|%s", 100 - w, p }'
}

echo "$size" >"$out/size" # the pixels of every render (flagged.sh)
printf 'family\tknob\tarith\tstatus\tbeyond1_pct\tbeyond2_pct\tpsnr_db\tlost_pixels\tunflagged_beyond2_pct\tunflagged_unexplained_pct\tcompared_pixels\n' >"$tsv"
for entry in "${families[@]}"; do
    IFS='|' read -r family knobs _ _ same_image <<<"$entry"
    for knob in $knobs; do
        scn=$out/work/$family-$knob.scn
        family_scene "$family" "$knob" "$size" >"$scn" || exit 1
        same=$out/work/$family-$knob-double.png
        "$LINKS1" ref "$scn" --arith double -o "$same" >/dev/null 2>&1 || rm -f "$same"
        ref=$same
        [ "$same_image" = 1 ] && ref=$out/work/$family-${knobs%% *}-double.png
        for arith in double float fixed; do
            img=$out/work/$family-$knob-$arith-plain.png
            marked=$out/work/$family-$knob-$arith-marked.png
            log=$out/work/$family-$knob-$arith.log
            [ $quick = 1 ] && img=$marked # the flags only: one render
            if ! "$LINKS1" ref "$scn" --arith $arith --no-escalate -o "$img" $([ $quick = 1 ] && echo --mark-lost) \
                    >"$log" 2>&1; then
                why=$(tail -n 1 "$log" | sed 's/^links1 ref: [^:]*: //' | tr '\t' ' ')
                printf '%s\t%s\t%s\trefused: %s\t\t\t\t\t\t\t\n' "$family" "$knob" "$arith" "$why" >>"$tsv"
                continue
            fi
            lost=$(grep -o '[0-9]* pixels in doubt' "$log" | grep -o '^[0-9]*')
            [ $quick = 1 ] || "$LINKS1" ref "$scn" --arith $arith --no-escalate --mark-lost -o "$marked" >/dev/null 2>&1
            b1=- b2=- psnr=- unflagged=- inner=- compared=-
            if [ -f "$ref" ] && [ $quick = 0 ]; then
                IFS='|' read -r b1 _ < <(measure "$ref" "$img" 1)
                IFS='|' read -r b2 psnr < <(measure "$ref" "$img" 2)
            fi
            if [ -f "$same" ]; then
                IFS='|' read -r unflagged _ < <(measure "$same" "$marked" 2 --flagged)
                # the share of all pixels, not of the unflagged ones
                total=$(("${size%x*}" * "${size#*x}"))
                unflagged=$(awk -v u="$unflagged" -v l="${lost:-0}" -v t="$total" \
                    'BEGIN { printf "%.4f", u * (t - l) / t }')
                # the share of all pixels beyond 2/255, unflagged and unexplained
                # compare's status: 0 (all within 2/255), 1 (some beyond, or
                # nothing compared); anything else is a failure of its own
                report=$("$LINKS1" compare "$same" "$marked" --within 2 --min-fraction 0 --flagged \
                    --silhouette --moved 2>&1)
                crc=$?
                if [ $crc -gt 1 ]; then
                    inner=- compared=-
                else
                    read -r inner compared < <(awk '
                    /pixels compared/ { n = $0; sub(/.*: [0-9]+x[0-9]+, /, "", n); n += 0 }
                    /on every channel/ { w = $0; sub(/.*on every channel: /, "", w); w += 0 }
                    END { if (n == "") print "- -"; else printf "%d %d\n", n * (100 - w) / 100 + 0.5, n }' <<<"$report")
                fi
                total=$(("${size%x*}" * "${size#*x}"))
                inner=$(awk -v c="$inner" -v t="$total" 'BEGIN { if (c == "-") print "-"; else printf "%.4f", 100 * c / t }')
            fi
            printf '%s\t%s\t%s\tok\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$family" "$knob" "$arith" "$b1" "$b2" \
                "$psnr" "${lost:-0}" "$unflagged" "$inner" "$compared" >>"$tsv"
        done
    done
done

# breaking points
{
    echo "| family | double | float (and soft) | fixed |"
    echo "|---|---|---|---|"
    for entry in "${families[@]}"; do
        IFS='|' read -r family _ label _ <<<"$entry"
        row="| $family ($label) |"
        for arith in double float fixed; do
            cell=$(awk -F'\t' -v f="$family" -v a="$arith" '
                $1 == f && $3 == a && !done {
                    if ($4 ~ /^refused/) { print "refused at " $2; done = 1 }
                    else if ($6 != "-" && $6 + 0 > 1) { print $2 " (" $6 "% beyond 2/255)"; done = 1 }
                }
                END { if (!done) print "holds" }' "$tsv")
            row="$row $cell |"
        done
        echo "$row"
    done
} >"$out/breaks.md"

if command -v gnuplot >/dev/null; then
    for entry in "${families[@]}"; do
        IFS='|' read -r family _ label logx _ <<<"$entry"
        for arith in double float fixed; do
            awk -F'\t' -v f="$family" -v a="$arith" '$1 == f && $3 == a && $4 == "ok" && $6 != "-" { print $2, $6, $9 }' \
                "$tsv" >"$out/work/$family-$arith.dat"
        done
        gnuplot <<GP
set terminal pngcairo size 560,360 font ",9" noenhanced
set output "$out/sweep-$family.png"
set title "$family: pixels beyond 2/255 of the double reference"
set xlabel "$label"
set ylabel "% of pixels"
$( [ "$logx" = 1 ] && echo "set logscale x" )
set key top left
set grid
plot "$out/work/$family-double.dat" using 1:2 with linespoints title "double", \
     "$out/work/$family-float.dat" using 1:2 with linespoints title "float / soft", \
     "$out/work/$family-fixed.dat" using 1:2 with linespoints title "fixed Q12.19", \
     "$out/work/$family-fixed.dat" using 1:3 with points pt 6 title "fixed: unflagged", \
     1 with lines dt 2 lc rgb "grey" title "1% (breaks)"
GP
    done
fi
echo "sweep: $tsv, $out/breaks.md"
