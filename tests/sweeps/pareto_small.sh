#!/usr/bin/env bash
# tests/sweeps/pareto_small.sh: the Pareto chart at reduced size
# (PARETO_SMALL=1 pareto.sh: 40x30, depth 2): both charts are written as
# PNG; every board point counted NC instructions and gave the host's image
# of the same arithmetic byte for byte (float, soft, double, fixed, and
# float and fixed escalated); soft float costs the NCs more instructions per
# pixel than the VFP, and bending transmitted rays more than not bending
# them; escalated fixed point is closer to the reference than plain fixed
# point (its lost pixels traced in double: it may cost more instructions
# or fewer, as a lost pixel stops its own rays).
#   PASS pareto_small_NAME  or  FAIL pareto_small_NAME: why
. "$(dirname "$0")/../board/lib.sh"
board_ready pareto_small || exit 0
out=build/test-images/pareto-small
rm -rf "$out"
mkdir -p "$out"
if ! PARETO_SMALL=1 PARETO_RUN_LIMIT_S="$BOARD_RUN_LIMIT_S" \
    bash tests/sweeps/pareto.sh --out "$out" >"$out.log" 2>&1; then
    echo "FAIL pareto_small: pareto.sh failed: $(tail -n 1 "$out.log")"
    exit 0
fi
echo "PASS pareto_small"
bad=
for f in pareto.png pareto-board.png; do
    [ "$(head -c 8 "$out/$f" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] ||
        bad="$bad $f"
done
[ -z "$bad" ] && echo "PASS pareto_small_png" || echo "FAIL pareto_small_png: not PNG:$bad"
tsv=$out/pareto-board.tsv
rows=$(tail -n +2 "$tsv" | wc -l)
wrong=$(awk -F'\t' 'NR > 1 && !($2 > 0 && $7 == "yes") { printf "%s (%s insns, same image: %s); ", $1, $2, $7 }' "$tsv")
if [ "$rows" -eq 7 ] && [ -z "$wrong" ]; then
    echo "PASS pareto_small_board_counted_and_exact ($rows configurations)"
else
    echo "FAIL pareto_small_board_counted_and_exact: $rows rows; $wrong"
fi
# cost CONFIG: its NC instructions per pixel
cost() { awk -F'\t' -v n="$1" '$1 == n { print $2 }' "$tsv"; }
f=$(cost "float d2 adaptive") s=$(cost "soft d2 adaptive") r=$(cost "float d2 adaptive, refraction off")
if awk -v f="$f" -v s="$s" 'BEGIN { exit !(f > 0 && s > 2 * f) }'; then
    echo "PASS pareto_small_soft_costs_more (soft $s, VFP $f instructions per pixel)"
else
    echo "FAIL pareto_small_soft_costs_more: soft '$s', VFP '$f' instructions per pixel"
fi
if awk -v f="$f" -v r="$r" 'BEGIN { exit !(r > 0 && f > r) }'; then
    echo "PASS pareto_small_refraction_costs_more (bending $f, not bending $r)"
else
    echo "FAIL pareto_small_refraction_costs_more: bending '$f', not bending '$r'"
fi
x=$(cost "fixed Q12.19 d2 adaptive") xe=$(cost "fixed Q12.19 d2 adaptive, escalated")
# psnr CONFIG: its PSNR against the reference
psnr() { awk -F'\t' -v n="$1" '$1 == n { print $3 }' "$tsv"; }
q=$(psnr "fixed Q12.19 d2 adaptive") qe=$(psnr "fixed Q12.19 d2 adaptive, escalated")
if awk -v x="$x" -v xe="$xe" -v q="$q" -v qe="$qe" 'BEGIN { exit !(x > 0 && xe > 0 && qe > q) }'; then
    echo "PASS pareto_small_escalated_closer (fixed $x instructions a pixel at $q dB, escalated $xe at $qe dB)"
else
    echo "FAIL pareto_small_escalated_closer: fixed '$x' at '$q' dB, escalated '$xe' at '$qe' dB"
fi
