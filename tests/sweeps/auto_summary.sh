#!/usr/bin/env bash
# tests/sweeps/auto_summary.sh: the short Markdown summary of a table that
# auto.sh (--arith auto) or auto_model.sh (--auto) writes: one row a
# family; every scene stays in the .tsv (docs/figures/sweep-auto.md and
# sweep-auto-model.md are this script's output, the .tsv of the same name
# beside each).  Columns 1-10 of both tables: family, knob, fpu (vfp or
# none), pick, its PSNR at full size, its NC instructions per pixel, the
# cheapest at the target, its PSNR, its cost, pick / cheapest.
#   bash tests/sweeps/auto_summary.sh TSV TITLE >OUT.md
set -eu
tsv=$1
title=$2
[ -r "$tsv" ] || { echo "auto_summary.sh: $tsv: cannot read it" >&2; exit 1; }
printf '%s: a row a family (every scene: the .tsv of this name).\n\n' "$title"
awk -F'\t' '
function arith(p) { sub(/,.*/, "", p); return p }
function add(list, key) { # "float 78, soft 13": counts in order of first sight
    if (!((list, key) in seen)) { seen[list, key] = 1; order[list] = order[list] (order[list] == "" ? "" : "\t") key }
    cnt[list, key]++
}
function names(list,    k, n, i, out) { # the counts of a list, as text
    n = split(order[list], k, "\t"); out = ""
    for (i = 1; i <= n; i++) out = out (i > 1 ? ", " : "") k[i] " " cnt[list, k[i]]
    return out == "" ? "-" : out
}
function maxr(a, b) { return (b != "-" && (a == "" || b + 0 > a + 0)) ? b : a }
NR == 1 { next }
{
    f = $1
    if (!(f in scenes)) { fams[++nf] = f; scenes[f] = 0; low[f] = "" }
    if ($3 == "vfp") { scenes[f]++; all++ }
    if ($4 ~ /^refused/) { if ($3 == "vfp") { refused[f]++; allref++ } next }
    if ($4 ~ /^none/) { nopick++; next }
    add("all" SUBSEP $3, arith($4)); picks++
    if (low[f] == "" || $5 + 0 < low[f] + 0) low[f] = $5
    if (lowall == "" || $5 + 0 < lowall + 0) lowall = $5
    r[f, $3] = maxr(r[f, $3], $10); rall[$3] = maxr(rall[$3], $10)
}
END {
    print "| family | scenes | lowest PSNR (dB) | pick / cheapest, VFP | no FPU |"
    print "|---|---|---|---|---|"
    for (i = 1; i <= nf; i++) {
        f = fams[i]
        extra = refused[f] ? " (" refused[f] " refused)" : ""
        printf "| %s | %d%s | %s | %sx | %sx |\n", f, scenes[f], extra, low[f] == "" ? "-" : low[f],
            r[f, "vfp"] == "" ? "-" : r[f, "vfp"], r[f, "none"] == "" ? "-" : r[f, "none"]
    }
    printf "\n%d scenes, %d refused by every build; %d picks, %d without a pick; lowest PSNR of a pick %s dB; pick / cheapest at most %sx with VFP, %sx without an FPU.  Picked with VFP: %s; without an FPU: %s.\n",
        all, allref, picks, nopick, lowall == "" ? "-" : lowall,
        rall["vfp"] == "" ? "-" : rall["vfp"], rall["none"] == "" ? "-" : rall["none"],
        names("all" SUBSEP "vfp"), names("all" SUBSEP "none")
}' "$tsv"
