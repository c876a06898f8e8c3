#!/usr/bin/env bash
# tests/images/accuracy.sh: the arithmetics of the renderer against the
# double-precision reference on the demo and the paper-like scenes:
#   float vs double: at least 99.9% of pixels within 1/255 on every channel
#   fixed vs double: at least 99% of pixels within 2/255 on every channel
# (issue 3).  No silhouette mask: every pixel counts.
# Prints "PASS accuracy_ARITH_SCENE" or "FAIL accuracy_ARITH_SCENE: why".
set -u
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
out=build/test-images/accuracy
mkdir -p "$out"
scenes="demo glass molecule city"
for name in $scenes; do
    scn=$(scene_of "$name")
    if ! err=$(build/links1 ref "$scn" -o "$out/$name-double.png" 2>&1); then
        echo "FAIL accuracy_double_$name: $err"
        continue
    fi
    for arith in float fixed; do
        case $arith in
            float) within=1 need=0.999 ;;
            fixed) within=2 need=0.99 ;;
        esac
        img="$out/$name-$arith.png"
        # --no-escalate: the arithmetic itself (the default escalates its doubts)
        if ! err=$(build/links1 ref "$scn" -o "$img" --arith $arith --no-escalate 2>&1); then
            echo "FAIL accuracy_${arith}_$name: $err"
            continue
        fi
        if report=$(build/links1 compare "$out/$name-double.png" "$img" --within $within \
                        --min-fraction $need); then
            echo "PASS accuracy_${arith}_$name"
        else
            echo "FAIL accuracy_${arith}_$name: $(echo "$report" | tail -n 1)"
        fi
        echo "$report" | sed 's/^/    /'
    done
done
