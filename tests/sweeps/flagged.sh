#!/usr/bin/env bash
# tests/sweeps/flagged.sh: the sweeps at reduced size (sweep.sh --quick):
# for every family, knob and arithmetic, the scene is either refused with
# a message, or every pixel beyond 2/255 of the double build was counted
# and painted as lost precision, or is explained by a move of less than a
# pixel: it lies next to an edge of the double image (a jump over 24/255
# in its 3x3 neighbourhood) or is within 2/255 of a pixel next to it there
# (links1 compare --silhouette --moved: an outline, a texel edge or an
# object thinner than a pixel moved by less than a pixel).  None may be
# left.
#   PASS flagged_FAMILY_KNOB_ARITH  or  FAIL ...: N% of pixels wrong, unflagged, unexplained
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/sweeps
rm -rf "$out"
if ! bash tests/sweeps/sweep.sh --quick --out "$out" >"$out.log" 2>&1; then
    echo "FAIL flagged_sweep: sweep.sh failed: $(tail -n 1 "$out.log")"
    exit 0
fi
awk -F'\t' 'NR > 1 {
    name = "flagged_" $1 "_" $2 "_" $3
    if ($4 ~ /^refused: ./) print "PASS " name " (refused: " substr($4, 10, 60) "...)"
    else if ($4 != "ok") print "FAIL " name ": status " $4
    else if ($10 == "-" || $10 == "") print "FAIL " name ": the double build gave no reference"
    else if ($10 + 0 > 0) print "FAIL " name ": " $10 "% of pixels beyond 2/255, not flagged and not explained by a move under a pixel"
    else print "PASS " name " (" $8 " pixels flagged, " $9 "% unflagged beyond 2/255, all next to an edge or a moved pixel)"
}' "$out/sweep.tsv"

# The refusal messages name the problem and the numbers.
want() { # NAME FAMILY KNOB ARITH TEXT
    local status
    status=$(awk -F'\t' -v f="$2" -v k="$3" -v a="$4" '$1 == f && $2 == k && $3 == a { print $4 }' \
        "$out/sweep.tsv")
    case $status in
        *"$5"*) echo "PASS $1" ;;
        *) echo "FAIL $1: '$status' does not say '$5'" ;;
    esac
}
want refuse_span_double cluster_scale 0.01 double \
    "scene spans 0.121; double resolves 2^-52 of a value (lengths scaled by 2^1), but secondary rays start 0.001 from a surface, so a scene needs a span of at least 0.5"
want refuse_cluster_scale_fixed cluster_scale 0.01 fixed \
    "scene spans 0.121; fixed Q12.19 resolves 2^-19 (lengths scaled by 2^1), but secondary rays start 0.001 from a surface, so a scene needs a span of at least 0.5"
