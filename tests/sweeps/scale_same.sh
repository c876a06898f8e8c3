#!/usr/bin/env bash
# tests/sweeps/scale_same.sh: lengths scaled to the scene (docs/renderer.md).
# The sweep's scene of three shapes on a floor (make_scene.py scale), 64x48:
#   - scaled by 2^k, k from -10 to +10, it gives the image of scale 1 bit
#     for bit in double, float and fixed (the loader scales the lengths back
#     exactly, and the tolerances apply to the scene as stored);
#   - at every scale from 1e-3 to 1e3 (and 1e6), fixed Q12.19 gives the
#     image of fixed at scale 1 within SCALE_SAME_PCT (1%) of pixels beyond
#     2/255 and SCALE_SAME_DB (40 dB) PSNR: the text's decimal scales round
#     differently to binary32;
#   - a scene its clusters shrink below its coordinates is still refused,
#     with a message that names its span and the scaling.
#   PASS scale_same_...  or  FAIL ...
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SCALE_SAME_PCT=1
SCALE_SAME_DB=40
out=build/test-images/scale_same
rm -rf "$out"
mkdir -p "$out"
render() { # KNOB ARITH [FAMILY]: prints the image path, or nothing when refused
    local scn=$out/${3:-scale}-$1.scn img=$out/${3:-scale}-$1-$2.png
    python3 tests/sweeps/make_scene.py "${3:-scale}" "$1" --size 64x48 >"$scn" || return
    "$LINKS1" ref "$scn" --arith "$2" -o "$img" >"$img.log" 2>&1 && echo "$img"
}
for arith in double float fixed; do
    one=$(render 1 $arith)
    for knob in 0.0009765625 0.015625 0.5 2 8 64 1024; do
        img=$(render $knob $arith)
        if [ -z "$one" ] || [ -z "$img" ]; then
            echo "FAIL scale_same_exact_${knob}_$arith: refused: $(tail -n 1 "$out/scale-$knob-$arith.png.log")"
        elif cmp -s "$one" "$img"; then
            echo "PASS scale_same_exact_${knob}_$arith"
        else
            echo "FAIL scale_same_exact_${knob}_$arith: differs from scale 1: $("$LINKS1" compare "$one" "$img" 2>&1 | tail -n 1)"
        fi
    done
done
one=$out/scale-1-fixed.png
for knob in 0.001 0.003 0.01 0.03 0.1 0.3 3 10 30 100 300 1000 1000000; do
    img=$(render $knob fixed)
    if [ -z "$img" ]; then
        echo "FAIL scale_same_fixed_$knob: refused: $(tail -n 1 "$out/scale-$knob-fixed.png.log")"
        continue
    fi
    r=$("$LINKS1" compare "$one" "$img" --within 2 --min-fraction 0 2>&1)
    within=$(echo "$r" | sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p')
    psnr=$(echo "$r" | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
    [ -n "$psnr" ] || psnr=999 # identical images print no PSNR
    if [ -z "$within" ]; then
        echo "FAIL scale_same_fixed_$knob: links1 compare: $(echo "$r" | tail -n 1)"
    elif awk -v w="$within" -v p="$psnr" -v pct=$SCALE_SAME_PCT -v db=$SCALE_SAME_DB \
            'BEGIN { exit !(100 - w <= pct && p >= db) }'; then
        echo "PASS scale_same_fixed_$knob ($(awk -v w="$within" 'BEGIN { printf "%.2f", 100 - w }')% beyond 2/255, PSNR $psnr dB)"
    else
        echo "FAIL scale_same_fixed_$knob: against scale 1, $(awk -v w="$within" 'BEGIN { printf "%.2f", 100 - w }')% of pixels beyond 2/255, PSNR $psnr dB"
    fi
done
# still refused: a cluster scaled by 0.01 shrinks the scene to a span of
# 0.12 while its coordinates reach 4..8 (lengths scaled by 2, so the ray
# offset is 0.001 of them)
for arith in double fixed; do
    img=$(render 0.01 $arith cluster_scale)
    msg=$(tail -n 1 "$out/cluster_scale-0.01-$arith.png.log")
    case $arith in
        double) want="scene spans 0.121; double resolves 2^-52 of a value (lengths scaled by 2^1), but secondary rays start 0.001 from a surface, so a scene needs a span of at least 0.5" ;;
        fixed) want="scene spans 0.121; fixed Q12.19 resolves 2^-19 (lengths scaled by 2^1), but secondary rays start 0.001 from a surface, so a scene needs a span of at least 0.5" ;;
    esac
    # shellcheck disable=SC2254
    case $msg in
        *$want*) [ -z "$img" ] && echo "PASS scale_same_refused_cluster_$arith" ||
            echo "FAIL scale_same_refused_cluster_$arith: rendered" ;;
        *) echo "FAIL scale_same_refused_cluster_$arith: '$msg' does not say '$want'" ;;
    esac
done
