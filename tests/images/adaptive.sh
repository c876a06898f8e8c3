#!/usr/bin/env bash
# tests/images/adaptive.sh: adaptive depth (options { min_weight W }).
#   adaptive_monotone_SCENE_ARITH: the secondary rays traced never grow as
#     the threshold grows (0 .. 1/8), and 1/8 cuts some;
#   adaptive_zero_near_double_SCENE_ARITH: with threshold 0, float and fixed
#     within 2/255 of the double build on 99% of the pixels;
#   adaptive_default_SCENE_ARITH: the default threshold (1/512) traces fewer
#     secondary rays than threshold 0 and stays within 2/255 of its image on
#     every pixel (scenes with reflections and refractions);
#   adaptive_refuse: a threshold outside 0..1 is refused, naming the range.
set -u
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
out=build/test-images/adaptive
mkdir -p "$out"
size=96x72

# secondary SUMMARY: reflection + refraction + transmission rays of a ref log
secondary() {
    sed -nE 's/.* ([0-9]+) reflection, ([0-9]+) refraction, ([0-9]+) transmission.*/\1 \2 \3/p' "$1" |
        awk '{ print $1 + $2 + $3 }'
}

# Every secondary ray the weight threshold could cut: monotone in the
# threshold (a higher threshold never traces more rays), and with threshold
# 0 the float and fixed builds stay within 2/255 of the double build's
# image (the reference is double, not a recorded value).
weights="0 0.000244140625 0.001953125 0.015625 0.125"
for name in demo glass molecule city; do
    for arith in double float fixed; do
        check=adaptive_monotone_${name}_$arith
        prev= rays0= bad= list=
        for w in $weights; do
            img="$out/$name-$arith-w$w.ppm"
            [ "$w" = 0 ] && img="$out/$name-$arith-w0.ppm"
            if ! build/links1 ref "$(scene_of $name)" --arith "$arith" --size $size --min-weight "$w" \
                    -o "$img" 2>"$img.log"; then
                bad="--min-weight $w: $(tail -n 1 "$img.log")"
                break
            fi
            n=$(secondary "$img.log")
            if [ -z "$n" ]; then
                bad="--min-weight $w: no ray count in the summary"
                break
            fi
            list="$list $n"
            [ -z "$rays0" ] && rays0=$n
            if [ -n "$prev" ] && [ "$n" -gt "$prev" ]; then
                bad="--min-weight $w traced $n secondary rays, more than $prev at the threshold below"
            fi
            prev=$n
        done
        if [ -z "$bad" ] && [ "$prev" -ge "$rays0" ]; then
            bad="threshold 1/8 cut no ray ($prev against $rays0 at 0)"
        fi
        if [ -n "$bad" ]; then
            echo "FAIL $check: $bad"
        else
            echo "PASS $check (secondary rays at $weights:$list)"
        fi
    done
    for arith in float fixed; do
        check=adaptive_zero_near_double_${name}_$arith
        if report=$(build/links1 compare "$out/$name-double-w0.ppm" "$out/$name-$arith-w0.ppm" \
                --within 2 --min-fraction 0.99 2>&1); then
            echo "PASS $check ($(grep -o 'within 2/255 on every channel: [0-9.]*%' <<<"$report"))"
        else
            echo "FAIL $check: $(tail -n 2 <<<"$report" | tr '\n' ' ')"
        fi
    done
done

for name in glass demo; do
    for arith in double float fixed; do
        zero="$out/$name-$arith-w0.ppm"
        img="$out/$name-$arith-default.ppm"
        check=adaptive_default_${name}_$arith
        if ! build/links1 ref "$(scene_of $name)" --arith "$arith" --size $size -o "$img" \
                2>"$img.log"; then
            echo "FAIL $check: $(tail -n 1 "$img.log")"
            continue
        fi
        a=$(secondary "$zero.log") b=$(secondary "$img.log")
        if [ -z "$a" ] || [ -z "$b" ] || [ "$b" -ge "$a" ]; then
            echo "FAIL $check: secondary rays ${b:-?} with the default threshold, ${a:-?} with 0"
        elif ! report=$(build/links1 compare "$zero" "$img" --within 2 --min-fraction 1 2>&1); then
            echo "FAIL $check: $(echo "$report" | tail -n 1)"
        else
            echo "PASS $check ($b secondary rays instead of $a)"
        fi
    done
done

if msg=$(build/links1 ref scenes/demo.scn --min-weight 1.5 -o "$out/never.ppm" 2>&1); then
    echo "FAIL adaptive_refuse: --min-weight 1.5 was accepted"
elif echo "$msg" | grep -q "1.5"; then
    echo "PASS adaptive_refuse"
else
    echo "FAIL adaptive_refuse: message '$msg' does not name the value"
fi
printf 'options { min_weight 2 }\nsphere { centre 0 0 0  radius 1 }\n' >"$out/bad.scn"
if msg=$(build/links1 ref "$out/bad.scn" -o "$out/never.ppm" 2>&1); then
    echo "FAIL adaptive_refuse_text: options { min_weight 2 } was accepted"
elif echo "$msg" | grep -q "min_weight must be 0..1, not 2"; then
    echo "PASS adaptive_refuse_text"
else
    echo "FAIL adaptive_refuse_text: message '$msg'"
fi
