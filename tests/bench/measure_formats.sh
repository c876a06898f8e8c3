#!/usr/bin/env bash
# measure_formats.sh: how many fraction bits the fixed format needs.
# Builds the host reference renderer in fixed point with NUM_FRAC_BITS = each
# argument (default 16 17 18 19) into build/fixed-formats/, renders the demo
# and paper-like scenes and compares each with the double reference:
# pixels within 2/255 on every channel (issue 3 asks for 99%).
set -eu
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
bits=${*:-16 17 18 19}
out=build/fixed-formats
mkdir -p "$out"
make -s --no-print-directory build/links1 build/links1-ref-double
srcs=$(make -s --no-print-directory \
    --eval 'print-ref-srcs: ; @echo $(links1-ref-fixed_SRCS) $(SHARED_SRCS)' print-ref-srcs)
scenes="demo glass molecule city"
for s in $scenes; do
    build/links1 ref "$(scene_of $s)" -o "$out/$s-double.png" >/dev/null 2>&1
done
for f in $bits; do
    cc -std=gnu11 -O2 -I. -ffp-contract=off -DLINKS1_NUM_FIXED -DNUM_FRAC_BITS="$f" \
        $srcs -lpng -lm -o "$out/ref-fixed-$f"
    for s in $scenes; do
        "$out/ref-fixed-$f" "$(scene_of $s)" -o "$out/$s-fixed-$f.png" >/dev/null 2>&1
        line=$(build/links1 compare "$out/$s-double.png" "$out/$s-fixed-$f.png" --within 2 \
                   --min-fraction 0.99 | tail -n 1 || true)
        echo "NUM_FRAC_BITS=$f $s:$line"
    done
done
