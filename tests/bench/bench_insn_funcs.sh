#!/usr/bin/env bash
# tests/bench/bench_insn_funcs.sh [ARITH] [TOP]: where the NCs' guest
# instructions go, function by function, on the virt board (Cortex-A15)
# and on the an521 boards (Cortex-M33), for one firmware arithmetic
# (default fixed), its own pixels (--no-escalate: the plain firmware).
# Each machine renders demo.scn 160x120 on 2 NCs with
# `links1 render --insn-profile` (the counting plugin's instructions per
# translated block of the NC cores); each block's start address is
# attributed to the function of the firmware ELF that holds it (the
# toolchain's nm, symbols sorted by address).  Prints a Markdown table of
# the TOP (default 15) functions by the larger of the two counts, per
# pixel, and the totals.  Instruction counts repeat exactly on virt; the
# an521 NCs' include the ticks they take while they wait.
set -eu
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
NM=${NM:-arm-none-eabi-nm}
ARITH=${1:-fixed} TOP=${2:-15}
W=160 H=120
out=$(mktemp -d /tmp/links1-bench-funcs.XXXXXX)
trap 'rm -rf "$out"' EXIT

# profile MACHINE ELF: "FUNCTION COUNT" lines, summed per function, into
# $out/MACHINE.funcs.
profile() {
    local m=$1 elf=$2
    # the ELF named is the one booted: escalating, links1 render would boot
    # the -esc firmware, whose functions lie elsewhere
    "$LINKS1" render scenes/demo.scn -o "$out/$m.png" --machine "$m" --arith "$ARITH" \
        --firmware "$elf" --no-escalate --ncs 2 --size ${W}x$H --insn-profile "$out/$m.prof" \
        --quiet >"$out/$m.log" 2>&1 || {
        echo "bench_insn_funcs: links1 render --machine $m failed:" >&2
        tail -n 5 "$out/$m.log" >&2
        exit 1
    }
    bash tests/bench/insn_funcs.sh "$out/$m.prof" "$elf" >"$out/$m.funcs"
}
profile virt "$FW_DIR/links1-$ARITH.elf"
profile an521 "$FW_DIR/an521/links1-$ARITH.elf"
px=$((W * H))
echo "NCs' guest instructions per pixel by function, demo.scn ${W}x$H, 2 NCs, $ARITH"
echo "(bash tests/bench/bench_insn_funcs.sh $ARITH $TOP):"
echo
echo "| function | A15 (virt) | M33 (an521) | M33 - A15 |"
echo "| --- | --- | --- | --- |"
awk -v px=$px -v top="$TOP" '
    FNR == 1 { file++ }
    { v[$1, file] = $2; names[$1] = 1; tot[file] += $2 }
    END {
        n = 0
        for (k in names) {
            a = v[k, 1] + 0; b = v[k, 2] + 0
            key[++n] = k; big[n] = a > b ? a : b
        }
        for (i = 1; i <= n; i++)       # selection of the TOP largest
            for (j = i + 1; j <= n; j++)
                if (big[j] > big[i]) { t = big[i]; big[i] = big[j]; big[j] = t
                                       t = key[i]; key[i] = key[j]; key[j] = t }
        for (i = 1; i <= n && i <= top; i++) {
            a = v[key[i], 1] / px; b = v[key[i], 2] / px
            printf "| %s | %.0f | %.0f | %+.0f |\n", key[i], a, b, b - a
        }
        printf "| (all) | %.0f | %.0f | %+.0f |\n", tot[1] / px, tot[2] / px, (tot[2] - tot[1]) / px
    }' "$out/virt.funcs" "$out/an521.funcs"
