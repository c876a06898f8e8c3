#!/usr/bin/env bash
# tests/images/adaptive.sh: adaptive depth (options { min_weight W }).
#   adaptive_zero_SCENE_ARITH: --min-weight 0 gives exactly the image of the
#     depth limit alone, the bytes recorded in adaptive_golden.txt before
#     adaptive depth existed, in every host arithmetic;
#   adaptive_default_SCENE_ARITH: the default threshold (1/512) traces fewer
#     secondary rays than threshold 0 and stays within 2/255 of its image on
#     every pixel (scenes with reflections and refractions);
#   adaptive_refuse: a threshold outside 0..1 is refused, naming the range.
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/adaptive
mkdir -p "$out"
golden=tests/images/adaptive_golden.txt
size=96x72

# secondary SUMMARY: reflection + refraction + transmission rays of a ref log
secondary() {
    sed -nE 's/.* ([0-9]+) reflection, ([0-9]+) refraction, ([0-9]+) transmission.*/\1 \2 \3/p' "$1" |
        awk '{ print $1 + $2 + $3 }'
}

grep -v '^#' "$golden" | while read -r name arith want; do
    img="$out/$name-$arith-w0.ppm"
    if ! build/links1 ref "scenes/$name.scn" --arith "$arith" --size $size --min-weight 0 \
            -o "$img" 2>"$img.log"; then
        echo "FAIL adaptive_zero_${name}_$arith: $(tail -n 1 "$img.log")"
        continue
    fi
    got=$(cksum <"$img" | cut -d' ' -f1)
    if [ "$got" = "$want" ]; then
        echo "PASS adaptive_zero_${name}_$arith"
    else
        echo "FAIL adaptive_zero_${name}_$arith: image CRC $got, the depth limit alone gave $want"
    fi
done

for name in glass demo; do
    for arith in double float fixed; do
        zero="$out/$name-$arith-w0.ppm"
        img="$out/$name-$arith-default.ppm"
        check=adaptive_default_${name}_$arith
        if ! build/links1 ref "scenes/$name.scn" --arith "$arith" --size $size -o "$img" \
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
