#!/usr/bin/env bash
# Anti-aliasing (--aa, options { aa N  aa_threshold T }; docs/renderer.md,
# "Anti-aliasing") on demo.scn at 64x48, depth 1.  The board's image equals the host
# build's byte for byte in float (the default clipping), fixed (the paper's
# lists) and double; the same frame with 1, 3 and 8 NCs and under each
# balancing mode is one image.  On the host: the options block equals the
# command line, bad values are refused before any board boots (exit 2 on
# the command line, 1 in a scene), paper mode turns anti-aliasing off,
# anti-aliasing changes the edges (more distinct colours than without), and
# fixed point's pixels that lost precision, escalated to double (which
# anti-aliases them again from their own corners), are within 1/255 of
# the double build's, where without escalation they are not.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
CHECKS="aa_board_float aa_board_fixed aa_board_double aa_ncs_same aa_balance_same
aa_options_block aa_refused aa_paper_off aa_changes_edges aa_escalated_near_double"
board_ready $CHECKS || exit 0
T=$RENDER_TMP
cp -r scenes/maps "$T/" # demo.scn's maps, for its copies in $T
SIZE=64x48
AA=(--aa 1 --aa-threshold 0.05)

# board_vs_host NAME ARITH [links1 render args...]: the board against the host
board_vs_host() {
    local name=$1 arith=$2
    shift 2
    "$LINKS1" ref scenes/demo.scn --arith "$arith" --size $SIZE "${AA[@]}" \
        -o "$T/$name-ref.ppm" >"$T/$name-ref.log" 2>&1
    render_board "$name" "$T/$name.ppm" scenes/demo.scn --arith "$arith" --size $SIZE \
        "${AA[@]}" -o "$T/$name.ppm" "$@" || return 0
    render_same "$name" "$T/$name-ref.ppm" "$T/$name.ppm"
}
board_vs_host aa_board_float float --ncs 3
board_vs_host aa_board_fixed fixed --ncs 2 --clip lists
board_vs_host aa_board_double double --ncs 2

# same_images NAME REF OUT...: PASS when every OUT equals REF
same_images() {
    local name=$1 ref=$2 out
    shift 2
    for out in "$@"; do
        if [ ! -s "$ref" ] || ! cmp -s "$ref" "$out"; then
            echo "FAIL $name: $out differs from $ref (or is missing)"
            return
        fi
    done
    echo "PASS $name"
}

# the NC count: 1 and 8 against 3 (aa_board_float's)
outs=()
for n in 1 8; do
    out=$T/ncs$n.ppm
    render_board aa_ncs_same "$out" scenes/demo.scn --size $SIZE "${AA[@]}" --ncs $n \
        -o "$out" && outs+=("$out")
done
[ ${#outs[@]} = 2 ] && same_images aa_ncs_same "$T/aa_board_float.ppm" "${outs[@]}"

# the balancing modes against decreasing (the default, aa_board_float's)
outs=()
for m in static dynamic lines; do
    out=$T/balance-$m.ppm
    render_board aa_balance_same "$out" scenes/demo.scn --size $SIZE "${AA[@]}" --ncs 3 \
        --balance $m -o "$out" && outs+=("$out")
done
[ ${#outs[@]} = 3 ] && same_images aa_balance_same "$T/aa_board_float.ppm" "${outs[@]}"

# the options block: the same scene with options { aa 1  aa_threshold 0.05 }
sed 's/^options {/options { aa 1  aa_threshold 0.05 /' scenes/demo.scn >"$T/demo-aa.scn"
if ! grep -q 'aa 1' "$T/demo-aa.scn"; then
    echo "FAIL aa_options_block: scenes/demo.scn has no options block to add to"
else
    "$LINKS1" ref "$T/demo-aa.scn" --arith float --size $SIZE -o "$T/block.ppm" >/dev/null 2>&1
    same_images aa_options_block "$T/aa_board_float-ref.ppm" "$T/block.ppm"
fi

# refused: on the command line (exit 2, one line naming the option), in a
# scene (exit 1, file:line:col naming it); nothing boots
why=""
for bad in "--aa 5" "--aa -1" "--aa-threshold 2" "--aa-threshold x" "--aa 1 --no-aa"; do
    # shellcheck disable=SC2086
    err=$("$LINKS1" render scenes/demo.scn -o "$T/bad.ppm" $bad 2>&1 >/dev/null)
    rc=$?
    opt=${bad%% *}
    [ $rc = 2 ] && [ "$(echo "$err" | wc -l)" = 1 ] && echo "$err" | grep -q -- "--" ||
        why="$why; '$bad': exit $rc '$err'"
    [ "$opt" = "--no-aa" ] || echo "$err" | grep -q -- "$opt" || why="$why; '$bad' not named: '$err'"
done
for bad in "aa 5" "aa -1" "aa_threshold 2" "aa_threshold x"; do
    sed "s/^options {/options { $bad /" scenes/demo.scn >"$T/bad.scn"
    err=$("$LINKS1" ref "$T/bad.scn" -o "$T/bad.ppm" 2>&1 >/dev/null)
    rc=$?
    [ $rc = 1 ] && echo "$err" | grep -q "bad.scn:[0-9]*:[0-9]*: .*${bad%% *}" ||
        why="$why; scene '$bad': exit $rc '$err'"
done
sed 's/^options {/options { paper on  aa 1 /' scenes/demo.scn >"$T/paper-aa.scn"
err=$("$LINKS1" ref "$T/paper-aa.scn" -o "$T/bad.ppm" 2>&1 >/dev/null)
rc=$?
[ $rc = 1 ] && echo "$err" | grep -q "paper mode has no anti-aliasing" ||
    why="$why; aa with paper on: exit $rc '$err'"
if [ -z "$why" ]; then
    echo "PASS aa_refused"
else
    echo "FAIL aa_refused: ${why#; }"
fi

# --paper turns the scene's anti-aliasing off; --aa beside it wins
"$LINKS1" ref "$T/demo-aa.scn" --paper --size $SIZE -o "$T/paper-aa.ppm" >/dev/null 2>&1
"$LINKS1" ref scenes/demo.scn --paper --size $SIZE -o "$T/paper.ppm" >/dev/null 2>&1
"$LINKS1" ref scenes/demo.scn --paper --size $SIZE "${AA[@]}" -o "$T/paper-wins.ppm" \
    >/dev/null 2>&1
if [ -s "$T/paper.ppm" ] && cmp -s "$T/paper.ppm" "$T/paper-aa.ppm" &&
    [ -s "$T/paper-wins.ppm" ] && ! cmp -s "$T/paper.ppm" "$T/paper-wins.ppm"; then
    echo "PASS aa_paper_off"
else
    echo "FAIL aa_paper_off: --paper on a scene with aa is not the scene without it, or --aa beside --paper did nothing"
fi

# distinct colours of a binary PPM
colours() {
    python3 -c '
import sys
d = open(sys.argv[1], "rb").read()
f = d.split(maxsplit=4)
w, h = int(f[1]), int(f[2])
px = d[len(d) - 3 * w * h:]
print(len({px[i:i + 3] for i in range(0, len(px), 3)}))' "$1"
}
"$LINKS1" ref scenes/demo.scn --arith float --size $SIZE -o "$T/plain.ppm" >/dev/null 2>&1
plain=$(colours "$T/plain.ppm" 2>/dev/null)
aa=$(colours "$T/aa_board_float-ref.ppm" 2>/dev/null)
if [ -n "$plain" ] && [ -n "$aa" ] && [ "$aa" -gt "$plain" ] &&
    ! cmp -s "$T/plain.ppm" "$T/aa_board_float-ref.ppm"; then
    echo "PASS aa_changes_edges ($plain distinct colours without, $aa with --aa 1)"
else
    echo "FAIL aa_changes_edges: $plain distinct colours without, '$aa' with --aa 1"
fi

# escalation: fixed point's lost pixels anti-aliased again in double (at
# 96x72, where plain fixed point has pixels beyond 1/255 of double)
ESC_SIZE=96x72
"$LINKS1" ref scenes/demo.scn --arith double --size $ESC_SIZE "${AA[@]}" \
    -o "$T/esc-double.ppm" >/dev/null 2>&1
"$LINKS1" ref scenes/demo.scn --arith fixed --size $ESC_SIZE "${AA[@]}" -o "$T/esc-fixed.ppm" \
    >/dev/null 2>&1
"$LINKS1" ref scenes/demo.scn --arith fixed --size $ESC_SIZE "${AA[@]}" --no-escalate \
    -o "$T/plain-fixed.ppm" >/dev/null 2>&1
if [ -s "$T/esc-double.ppm" ] && [ -s "$T/esc-fixed.ppm" ] &&
    "$LINKS1" compare "$T/esc-double.ppm" "$T/esc-fixed.ppm" --within 1 \
        --min-fraction 1 >/dev/null 2>&1 &&
    ! "$LINKS1" compare "$T/esc-double.ppm" "$T/plain-fixed.ppm" --within 1 \
        --min-fraction 1 >/dev/null 2>&1; then
    echo "PASS aa_escalated_near_double"
else
    echo "FAIL aa_escalated_near_double: escalated fixed is not within 1/255 of double, or plain fixed is"
fi
