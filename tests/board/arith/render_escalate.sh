#!/usr/bin/env bash
# Escalation (links1 render, by default in float and fixed; render/wide.h):
# an NC traces a pixel that lost precision again in double.  The board's
# image and its count of escalated pixels equal the host build's (links1 ref,
# by default too) in float and fixed, with --mark-lost too and over an animation's pipelined frames,
# and on the an521 boards, whose M33s compute the double in software;
# escalated fixed point is within 2/255 of the double build on every pixel
# of demo.scn, where plain fixed point is not; what cannot escalate is
# refused with the reason, before a board boots or by the DM.
# --check-lost (a lost pixel checked in double, flagged only when it is off
# there) gives the host's image with --mark-lost, and flags of which at
# least half are really beyond 2/255 of double, with none missed.
# --no-escalate gives the host's plain image (not the default's), --paper
# implies it, and --escalate with --no-escalate is a usage error.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_escalate_float render_escalate_float_count render_escalate_fixed \
    render_escalate_fixed_count render_escalate_fixed_marked render_escalate_frames \
    render_escalate_fixed_near_double render_escalate_plain_fixed_is_not \
    render_escalate_an521_float render_escalate_an521_float_count render_escalate_an521_fixed \
    render_escalate_an521_fixed_count render_escalate_depth16 render_escalate_refused_soft render_escalate_refused_double \
    render_escalate_refused_auto render_escalate_firmware_without_wide render_check_lost_fixed \
    render_check_lost_flags_mean_it render_no_escalate_fixed render_no_escalate_differs \
    render_paper_no_escalate render_escalate_both_refused || exit 0
SIZE=160x120
scn=scenes/demo.scn

# escalated LOG: the "N pixels escalated" of links1 render (or ref) --verbose
escalated() {
    grep -o '[0-9]* pixels escalated' "$1" | head -n 1 | cut -d' ' -f1
}
# doubted LOG: the "N pixels in doubt" of a summary line
doubted() {
    grep -o '[0-9]* pixels in doubt' "$1" | head -n 1 | cut -d' ' -f1
}

# same_count NAME HOST-LOG BOARD-LOG: the board escalated as many pixels as
# the host, and its summary leaves as many in doubt
same_count() {
    local h b hd bd
    h=$(escalated "$2")
    b=$(escalated "$3")
    hd=$(doubted "$2")
    bd=$(doubted "$3")
    if [ -n "$h" ] && [ "$h" = "$b" ] && [ "$h" -gt 0 ] && [ -n "$hd" ] && [ "$hd" = "$bd" ]; then
        echo "PASS $1"
    else
        echo "FAIL $1: host escalated '${h:-none}' pixels, the board '${b:-none}' (want equal, > 0); in doubt after: host '${hd:-none}', board '${bd:-none}'"
    fi
}

# escalate_same NAME ARITH SIZE [links1 render args...]: the board's
# image by default (escalated: RENDER_TMP/NAME.ppm) and its count of
# escalated pixels equal the host build's by default; the host's plain
# image (--no-escalate) beside, RENDER_TMP/esc-plain-NAME.ppm
escalate_same() {
    local name=$1 a=$2 size=$3 ref=$RENDER_TMP/esc-host-$1.ppm out=$RENDER_TMP/$1.ppm
    local plain=$RENDER_TMP/esc-plain-$1.ppm
    shift 3
    "$LINKS1" ref $scn --arith "$a" --size "$size" --verbose -o "$ref" >"$ref.log" 2>&1
    "$LINKS1" ref $scn --arith "$a" --size "$size" --no-escalate -o "$plain" >"$plain.log" 2>&1
    if render_board "$name" "$out" $scn -o "$out" --arith "$a" --ncs 2 --size "$size" \
        --verbose "$@"; then
        render_same "$name" "$ref" "$out"
        same_count "${name}_count" "$ref.log" "$RENDER_TMP/$name.log"
    else
        echo "FAIL ${name}_count: no board render"
    fi
}

for a in float fixed; do
    escalate_same render_escalate_$a $a $SIZE
done

# --mark-lost paints what the wide arithmetic still lost (fixed: none here)
name=render_escalate_fixed_marked
ref=$RENDER_TMP/esc-host-fixed-marked.ppm
"$LINKS1" ref $scn --arith fixed --size $SIZE --escalate --mark-lost -o "$ref" >"$ref.log" 2>&1
out=$RENDER_TMP/$name.ppm
render_board $name "$out" $scn -o "$out" --arith fixed --ncs 2 --size $SIZE --escalate \
    --mark-lost && render_same $name "$ref" "$out"

# frames of an animation, each prepared (wide blob too) while the one
# before renders
name=render_escalate_frames
ref=$RENDER_TMP/esc-anim-host.ppm
"$LINKS1" ref scenes/anim.scn --arith float --size 64x48 --escalate --frames 0:2 -o "$ref" \
    >"$ref.log" 2>&1
out=$RENDER_TMP/esc-anim.ppm
if render_board $name "$out" scenes/anim.scn -o "$out" --arith float --ncs 2 --size 64x48 \
    --escalate --frames 0:2; then
    bad=""
    for f in 0000 0001 0002; do
        cmp -s "${ref%.ppm}-$f.ppm" "${out%.ppm}-$f.ppm" || bad="$bad $f"
    done
    if [ -z "$bad" ] && [ -s "${out%.ppm}-0002.ppm" ]; then
        echo "PASS $name"
    else
        echo "FAIL $name: frames differ from the host's or are missing:${bad:- none written}"
    fi
fi

# escalated fixed against double: every pixel within 2/255; plain fixed
# is not (so the check above can fail)
dbl=$(render_ref $scn double $SIZE)
plain=$RENDER_TMP/esc-plain-render_escalate_fixed.ppm # links1 ref --no-escalate's
if "$LINKS1" compare "$dbl" "$RENDER_TMP/render_escalate_fixed.ppm" --within 2 \
    --min-fraction 1 >"$RENDER_TMP/near.log" 2>&1; then
    echo "PASS render_escalate_fixed_near_double"
else
    echo "FAIL render_escalate_fixed_near_double: $(grep -m1 within "$RENDER_TMP/near.log")"
fi
if "$LINKS1" compare "$dbl" "$plain" --within 2 --min-fraction 1 >"$RENDER_TMP/plain.log" 2>&1; then
    echo "FAIL render_escalate_plain_fixed_is_not: plain fixed is within 2/255 of double everywhere: the scene tests nothing"
else
    grep -q 'largest difference' "$RENDER_TMP/plain.log" &&
        echo "PASS render_escalate_plain_fixed_is_not" ||
        echo "FAIL render_escalate_plain_fixed_is_not: compare failed: $(tail -n 1 "$RENDER_TMP/plain.log")"
fi

# the an521 boards: their M33s escalate in software double (libgcc's,
# correctly rounded), the image and the count still the host's
for a in float fixed; do
    escalate_same render_escalate_an521_$a $a 64x48 --machine an521
done

# the deepest recursion a scene may ask (max_depth 16): the double
# renderer's stack fits an NC task's, and the image is the host's
name=render_escalate_depth16
deep=$RENDER_TMP/tir16.scn
python3 host-tools/gen/make_scene.py tir_chain 16 --size 64x48 >"$deep"
ref=$RENDER_TMP/esc-host-depth16.ppm
"$LINKS1" ref "$deep" --arith float --escalate -o "$ref" >"$ref.log" 2>&1
out=$RENDER_TMP/$name.ppm
render_board $name "$out" "$deep" -o "$out" --arith float --ncs 2 --escalate &&
    render_same $name "$ref" "$out"

# refusals: a clear reason, no board booted
refused() {
    local name=$1 want=$2 log=$RENDER_TMP/$1.log
    shift 2
    "$LINKS1" render $scn -o "$RENDER_TMP/$name.ppm" --size 32x24 --escalate "$@" >"$log" 2>&1
    local rc=$?
    if [ $rc -ne 0 ] && grep -q -- "$want" "$log" && ! grep -q 'booting' "$log"; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc, want a refusal naming '$want' before any boot: $(tail -n 1 "$log")"
    fi
}
refused render_escalate_refused_soft 'no double to escalate to' --arith soft
refused render_escalate_refused_double 'double is the wide arithmetic itself' --arith double
refused render_escalate_refused_auto 'not --arith auto' --arith auto

# a firmware without the wide renderer: the DM refuses, naming the builds
name=render_escalate_firmware_without_wide
log=$RENDER_TMP/$name.log
"$LINKS1" render $scn -o "$RENDER_TMP/$name.ppm" --size 32x24 --ncs 2 --escalate --quiet \
    --firmware "$FW_DIR/links1-float.elf" >"$log" 2>&1
rc=$?
if [ $rc -ne 0 ] && grep -q 'carries no wide arithmetic\|without a wide arithmetic' "$log" &&
    grep -q 'links1-float-esc.elf' "$log"; then
    echo "PASS $name"
else
    echo "FAIL $name: exit $rc, want the DM's refusal naming the escalating builds: $(tail -n 1 "$log")"
fi

# --check-lost --mark-lost: board = host, and the flags score against double
name=render_check_lost_fixed
ref=$RENDER_TMP/check-host-fixed.ppm
"$LINKS1" ref $scn --arith fixed --size $SIZE --check-lost --mark-lost -o "$ref" >"$ref.log" 2>&1
out=$RENDER_TMP/$name.ppm
render_board $name "$out" $scn -o "$out" --arith fixed --ncs 2 --size $SIZE --check-lost \
    --mark-lost && render_same $name "$ref" "$out"
name=render_check_lost_flags_mean_it
if "$LINKS1" compare "$dbl" "$plain" --flags "$out" --min-precision 0.5 --min-recall 1 \
    >"$RENDER_TMP/$name.log" 2>&1; then
    echo "PASS $name ($(grep -m1 -i 'precision' "$RENDER_TMP/$name.log"))"
else
    echo "FAIL $name: $(grep -i 'precision\|recall' "$RENDER_TMP/$name.log" | head -n 2 | tr '\n' ' ')"
fi

# --no-escalate: the arithmetic's own colours, the host's plain image,
# which the default's escalated image is not
name=render_no_escalate_fixed
out=$RENDER_TMP/$name.ppm
if render_board $name "$out" $scn -o "$out" --arith fixed --ncs 2 --size $SIZE --no-escalate; then
    render_same $name "$plain" "$out"
    if [ -s "$RENDER_TMP/render_escalate_fixed.ppm" ] &&
        ! cmp -s "$out" "$RENDER_TMP/render_escalate_fixed.ppm"; then
        echo "PASS render_no_escalate_differs"
    else
        echo "FAIL render_no_escalate_differs: the default's image is the plain one (or missing)"
    fi
else
    echo "FAIL render_no_escalate_differs: no board render"
fi

# --paper implies --no-escalate: its line says so, and the image is the
# host's plain paper-mode image
name=render_paper_no_escalate
ref=$RENDER_TMP/paper-host.ppm
"$LINKS1" ref $scn --arith fixed --size 48x36 --paper --no-escalate -o "$ref" >"$ref.log" 2>&1
out=$RENDER_TMP/$name.ppm
if render_board $name "$out" $scn -o "$out" --arith fixed --ncs 2 --size 48x36 --paper; then
    if grep -q 'paper mode: .*escalation off' "$RENDER_TMP/$name.log" && cmp -s "$ref" "$out"; then
        echo "PASS $name"
    else
        echo "FAIL $name: want 'escalation off' in the paper line and the host's plain image: $(grep -m1 'paper mode' "$RENDER_TMP/$name.log")"
    fi
fi

name=render_escalate_both_refused
"$LINKS1" render $scn -o "$RENDER_TMP/$name.ppm" --escalate --no-escalate >"$RENDER_TMP/$name.log" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -q 'not both' "$RENDER_TMP/$name.log"; then
    echo "PASS $name"
else
    echo "FAIL $name: exit $rc, want 2 and 'not both': $(tail -n 1 "$RENDER_TMP/$name.log")"
fi

# A scene whose double copy does not fit beside it in the DM's IMSU block
# (SPD tetra 9: 118 MB prepared, 217 MB in double, a 193 MB block) renders
# without escalation, says so, and gives the host's plain image
name=render_escalate_dropped_no_room
nff=$RENDER_TMP/tetra9.nff
ref=$RENDER_TMP/$name-host.ppm
out=$RENDER_TMP/$name.ppm
"$(dirname "$LINKS1")/links1-spd" tetra 9 -o "$nff" >"$nff.log" 2>&1
"$LINKS1" ref "$nff" --arith float --size 32x24 --no-escalate -o "$ref" >"$ref.log" 2>&1
if render_board $name "$out" "$nff" -o "$out" --ncs 2 --size 32x24; then
    if grep -q 'escalation off: the scene.s double copy does not fit' "$RENDER_TMP/$name.log" &&
        cmp -s "$ref" "$out"; then
        echo "PASS $name"
    else
        echo "FAIL $name: want the 'escalation off' line and the host's plain image: $(grep -m1 'escalation' "$RENDER_TMP/$name.log")"
    fi
fi
rm -f "$nff"
