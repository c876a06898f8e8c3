#!/usr/bin/env bash
# make figures end to end at a reduced size (tests/bench/figures.sh with
# FIG_SMALL=1): every chart and table is written, the charts are PNG, the
# replay's speed-ups are there for every NC count, and refracting costs
# more than never bending; Tables 2 and 3 as the paper ran them are written.
. "$(dirname "$0")/../lib.sh"
board_ready figures_small || exit 0
out=$(mktemp -d /tmp/links1-figures-small.XXXXXX)
trap 'rm -rf "$out"' EXIT
if ! FIG_SMALL=1 FIG_OUT="$out" FIG_RUN_LIMIT_S="$BOARD_RUN_LIMIT_S" \
    bash tests/bench/figures.sh >"$out/log" 2>&1; then
    echo "FAIL figures_small: $(tail -n 2 "$out/log" | tr '\n' ' ')"
    exit 0
fi
echo "PASS figures_small"
bad=
for f in fig7.png fig10.png; do
    [ "$(head -c 8 "$out/$f" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || bad="$bad $f"
done
[ -z "$bad" ] && echo "PASS figures_small_png" || echo "FAIL figures_small_png: not PNG:$bad"
# fig7.dat: one row per replayed NC count (7); every speed-up at N NCs is
# above 1 and at most N (more NCs than work gain nothing, none gains more
# than N), and the replays of the paper's rule and of the board's never slow
# down as NCs are added up to 64.
rows=$(grep -vc '^#' "$out/fig7.dat")
why=$(awk '!/^#/ {
    n = $1
    for (c = 2; c <= 5; c++) {
        if ($c == "NaN" && c == 2) continue
        if (n == 1 && $c != 1) { print "the 1-NC row is not 1 in column " c; exit }
        if (n > 1 && !($c > 1 && $c <= n * 1.0001)) { print n " NCs: speed-up " $c " in column " c " not in (1, " n "]"; exit }
    }
    if (n <= 64 && prev != "" && ($3 < prev || $4 < prev4)) { print n " NCs: a replay slowed down, " $3 ", " $4 " after " prev ", " prev4; exit }
    prev = $3; prev4 = $4
}' "$out/fig7.dat")
if [ "$rows" = 7 ] && [ -z "$why" ]; then
    echo "PASS figures_small_fig7_rows"
else
    echo "FAIL figures_small_fig7_rows: ${why:-$rows rows, want 7}: $(tr '\n' ';' <"$out/fig7.dat")"
fi
if grep -Eq 'Refracting takes [0-9.]+x' "$out/table3.md" &&
    awk '/Refracting takes/ { v = $3 + 0 } END { exit !(v > 1) }' "$out/table3.md"; then
    echo "PASS figures_small_table3_refraction_costs_more"
else
    echo "FAIL figures_small_table3_refraction_costs_more: $(tail -n 1 "$out/table3.md")"
fi
# Tables 2 and 3 as the paper ran them (fig9.scn in paper mode): every type
# of Table 2 is there; each speed-up makes the frame no slower at the
# coarser area count, and at the finer one by at most 2% (there, in this
# reduced run's small areas, the Y lists' set-up per area costs about what
# they save since the box test was written out: +Y 10.1 s against boxes
# alone 10.0 s); all clipping together is faster than boxes alone and
# than none at both; refracting costs more than never bending; Tables 2
# and 3 as the paper ran them are written.
why=$(awk -F'|' '/^\| .*type [1-4]/ {
    n++; a = $4 + 0; b = $6 + 0
    if (n > 1 && (a > pa * 1.0001 || b > pb * 1.02)) { print "a speed-up slowed the frame:" $0; exit }
    if (n == 1) { fa = a; fb = b }
    if (n == 2) { ba = a; bb = b }
    pa = a; pb = b
} END { if (n != 4) print n " rows of types, want 4"; else if (!(pa < fa && pb < fb)) print "all clipping is not faster than none"; else if (!(pa <= ba && pb <= bb)) print "all clipping is not faster than boxes alone" }' \
    "$out/table2-paper.md" 2>&1)
if [ -s "$out/table2-paper.md" ] && [ -z "$why" ] &&
    awk '/Refracting takes/ { v = $3 + 0 } END { exit !(v > 1) }' "$out/table3-paper.md"; then
    echo "PASS figures_small_paper_tables"
else
    echo "FAIL figures_small_paper_tables: ${why:-refraction: $(tail -n 1 "$out/table3-paper.md" 2>&1)}"
fi
