#!/usr/bin/env bash
# check_layers.sh: every #include "..." of the project's sources against the
# rules of docs/layers.md (between its layers:begin and layers:end marks).
#   check_layers.sh [ROOT]   ROOT defaults to the repository
# Prints one line per wrong include (FILE:LINE: FOLDER may not include PATH)
# and "check-layers: N files, N includes, N wrong"; exits 1 when any is wrong.
set -eu
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
cd "$root"
rules=docs/layers.md
[ -r "$rules" ] || { echo "check-layers: $root/$rules is missing" >&2; exit 2; }
files=$(find boot kernel drivers roles render fixed proto linker scenes host-tools tests \
    -type f \( -name '*.c' -o -name '*.h' -o -name '*.S' -o -name '*.ld' \) 2>/dev/null | sort)
awk -v rulesfile="$rules" '
BEGIN {
    on = 0
    while ((getline line < rulesfile) > 0) {
        if (line ~ /<!-- layers:begin -->/) { on = 1; continue }
        if (line ~ /<!-- layers:end -->/) { on = 0; continue }
        if (!on || line ~ /^[ \t]*$/) continue
        n = split(line, w, /[ \t]+/)
        i = 1; while (i <= n && w[i] == "") i++
        if (w[i] == "private") {
            hdr = w[i + 1]; priv[hdr] = ""
            for (j = i + 2; j <= n; j++) if (w[j] != "") priv[hdr] = priv[hdr] " " w[j]
            continue
        }
        folder = w[i]; nrules++; rule[nrules] = folder; allow[folder] = folder
        for (j = i + 1; j <= n; j++) if (w[j] != "") allow[folder] = allow[folder] " " w[j]
    }
    if (nrules == 0) { print "check-layers: no rules in " rulesfile > "/dev/stderr"; exit 2 }
}
# the longest rule folder that is a prefix of path
function row(path,    k, best) {
    best = ""
    for (k = 1; k <= nrules; k++)
        if (index(path, rule[k]) == 1 && length(rule[k]) > length(best)) best = rule[k]
    return best
}
function allowed(list, inc,    m, a, k) {
    m = split(list, a, " ")
    for (k = 1; k <= m; k++) {
        if (a[k] == "") continue
        if (a[k] ~ /\/$/ ? index(inc, a[k]) == 1 : inc == a[k]) return 1
    }
    return 0
}
FNR == 1 {
    nfiles++
    r = row(FILENAME)
    if (r == "") { printf "%s: no row of %s covers this folder\n", FILENAME, rulesfile; bad++ }
}
/^[ \t]*#[ \t]*include[ \t]*"/ {
    inc = $0; sub(/^[^"]*"/, "", inc); sub(/".*$/, "", inc)
    nincs++
    if (inc !~ /\//) next                     # a file beside it
    r = row(FILENAME)
    if (inc in priv && !allowed(priv[inc], FILENAME)) {
        printf "%s:%d: %s is private to%s\n", FILENAME, FNR, inc, priv[inc]; bad++; next
    }
    if (r != "" && !allowed(allow[r], inc)) {
        printf "%s:%d: %s may not include %s\n", FILENAME, FNR, r, inc; bad++
    }
}
END {
    printf "check-layers: %d files, %d includes, %d wrong\n", nfiles, nincs, bad + 0
    exit bad ? 1 : 0
}' $files
