#!/usr/bin/env bash
# Each speed-up switched off on the board (Y clipping, X clipping, bounding
# boxes, the hierarchy, then all four), the paper's clipping lists instead
# of clipping in the hierarchy, and the paper's rule of asking for areas
# once finished, give the same image, bit for bit, as the host build; and
# the rays traced are the same in number, while the primitive tests the
# speed-ups save are not.  The lists and the paper's rule also on an SPD
# tetra of 4,096 triangles in fixed point.  All without escalation
# (--no-escalate): which pixels are in doubt, and so escalated and their
# rays traced again, can depend on what a walk goes through.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_switches || exit 0
SIZE=96x72
ref=$RENDER_TMP/city-float-plain.ppm
"$LINKS1" ref build/scenes/city.scn --arith float --no-escalate --size $SIZE -o "$ref" \
    >"$ref.log" 2>&1
for sw in none no-yclip no-xclip no-bbox no-hierarchy all clip-lists clip-tree ask-finished; do
    name=render_city_$sw
    out="$RENDER_TMP/$name.ppm"
    case $sw in
    none) args=() ;;
    all) args=(--no-yclip --no-xclip --no-bbox --no-hierarchy) ;;
    ask-finished) args=(--ask finished) ;;
    clip-lists) args=(--clip lists) ;;
    clip-tree) args=(--clip tree) ;;
    *) args=(--$sw) ;;
    esac
    render_board $name "$out" build/scenes/city.scn -o "$out" --ncs 2 --size $SIZE --no-escalate \
        "${args[@]}" ||
        continue
    render_same $name "$ref" "$out"
done
# The rays (primary, shadow, reflection, ...) do not depend on the switches.
rays() { grep -o 'rays [^;]*' "$RENDER_TMP/render_city_$1.log"; }
if [ -n "$(rays none)" ] && [ "$(rays none)" = "$(rays all)" ]; then
    echo "PASS render_switches_same_rays"
else
    echo "FAIL render_switches_same_rays: with speed-ups '$(rays none)', without '$(rays all)'"
fi
prims() { grep -o 'primitive ([0-9]* by primary' "$RENDER_TMP/render_city_$1.log" | grep -o '[0-9]*'; }
if [ -n "$(prims none)" ] && [ -n "$(prims all)" ] && [ "$(prims none)" -lt "$(prims all)" ]; then
    echo "PASS render_switches_save_tests"
else
    echo "FAIL render_switches_save_tests: primary-ray primitive tests with speed-ups '$(prims none)', without '$(prims all)'"
fi
SPD="$(dirname "$LINKS1")/links1-spd"
tetra="$RENDER_TMP/tetra6.nff"
if "$SPD" tetra 6 -o "$tetra" >"$tetra.log" 2>&1; then
    tref=$(render_ref "$tetra" fixed 64x48)
    for sw in default clip-tree clip-lists; do
        name=render_tetra6_fixed_$sw
        out="$RENDER_TMP/$name.ppm"
        args=()
        [ $sw = clip-lists ] && args=(--clip lists --ask finished)
        [ $sw = clip-tree ] && args=(--clip tree)
        render_board $name "$out" "$tetra" -o "$out" --ncs 4 --size 64x48 --arith fixed \
            "${args[@]}" || continue
        render_same $name "$tref" "$out"
    done
else
    echo "FAIL render_tetra6_fixed: links1-spd tetra 6 failed: $(tail -n 1 "$tetra.log")"
fi
