#!/usr/bin/env bash
# --spd-rules (Haines's rules for timing the SPD, docs/results/spd.md) on
# the host and on the board.  The host: the camera rays go through the
# pixel corners ((w+1) x (h+1) of them), the image is 512x512 unless
# --size says otherwise, a transmitting surface whose Ks is 0 spawns
# reflected rays.  The board: its 'spd:' counts (each corner counted once
# over the NCs' areas) and its image equal the host's, in float with the
# NCs' default clipping and in fixed point with the paper's lists.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
SPD="$(dirname "$LINKS1")/links1-spd"
CHECKS="spd_rules_corner_rays spd_rules_default_size spd_rules_transmitter_reflects
spd_rules_board_counts_balls spd_rules_board_image_balls spd_rules_board_counts_mount
spd_rules_board_image_mount"
board_ready $CHECKS || exit 0
T=$RENDER_TMP

# spd_counts LOG: the counts of its 'spd:' line, without the times.
spd_counts() { sed -n 's/^spd: \(eye_hit.* shadow [0-9]*\) preprocess.*/\1/p' "$1"; }

"$SPD" balls 1 -o "$T/balls1.nff" >/dev/null 2>&1
"$SPD" mount 2 -o "$T/mount2.nff" >/dev/null 2>&1

# the host: 65 x 65 corner rays at 64x64 (--no-escalate: an escalated
# pixel's double trace of its corners would count too)
"$LINKS1" ref "$T/balls1.nff" --spd-rules --size 64x64 --arith float --no-escalate \
    -o "$T/balls-ref.ppm" >"$T/balls-ref.log" 2>&1
primary=$(sed -n 's/.*rays: \([0-9]*\) primary.*/\1/p' "$T/balls-ref.log")
hit=$(spd_counts "$T/balls-ref.log" | awk '{print $2}')
if [ "$primary" = 4225 ] && [ -n "$hit" ] && [ "$hit" -le 4225 ]; then
    echo "PASS spd_rules_corner_rays"
else
    echo "FAIL spd_rules_corner_rays: want 4225 camera rays (65 x 65) at 64x64, got '$primary' (eye_hit '$hit')"
fi

# without --size: Haines's 512x512 (and one 'spd:' line)
"$LINKS1" ref "$T/balls1.nff" --spd-rules -o "$T/balls-512.ppm" >"$T/balls-512.log" 2>&1
if grep -q '512x512' "$T/balls-512.log" && [ "$(grep -c '^spd: eye_hit' "$T/balls-512.log")" = 1 ]; then
    echo "PASS spd_rules_default_size"
else
    echo "FAIL spd_rules_default_size: $(grep -m1 'links1' "$T/balls-512.log")"
fi

# a glass sphere with Ks 0 (T 0.9) over a floor: reflected rays under the
# rules, none without them at the same depth and weight
cat >"$T/glass.nff" <<'EOF'
v
from 0 -6 2
at 0 0 0
up 0 0 1
angle 40
hither 1
resolution 32 32
b 0.1 0.2 0.5
l 3 -4 6
f 0.9 0.9 0.9 0.1 0 0 0.9 1.5
s 0 0 0.5 1
f 0.8 0.6 0.3 1 0 0 0 1
p 4
-4 -4 -1
4 -4 -1
4 4 -1
-4 4 -1
EOF
"$LINKS1" ref "$T/glass.nff" --spd-rules -o "$T/glass.ppm" >"$T/glass.log" 2>&1
"$LINKS1" ref "$T/glass.nff" --max-depth 4 --min-weight 0 -o "$T/glass-plain.ppm" \
    >"$T/glass-plain.log" 2>&1
with=$(spd_counts "$T/glass.log" | awk '{print $4}')
refr=$(spd_counts "$T/glass.log" | awk '{print $6}')
without=$(sed -n 's/.* \([0-9]*\) reflection,.*/\1/p' "$T/glass-plain.log")
if [ -n "$with" ] && [ "$with" -ge "${refr:-0}" ] && [ "${refr:-0}" -gt 0 ] && [ "$without" = 0 ]; then
    echo "PASS spd_rules_transmitter_reflects"
else
    echo "FAIL spd_rules_transmitter_reflects: reflect '$with' refract '$refr' under the rules, '$without' reflected without them (want reflect >= refract > 0, and 0)"
fi

# board_vs_host NAME SCENE SIZE ARITH [links1 render args...]
board_vs_host() {
    local name=$1 scene=$2 size=$3 arith=$4
    shift 4
    "$LINKS1" ref "$scene" --spd-rules --size "$size" --arith "$arith" -o "$T/$name-ref.ppm" \
        >"$T/$name-ref.log" 2>&1
    if ! render_board "spd_rules_board_counts_$name" "$T/$name.ppm" "$scene" --spd-rules \
        --size "$size" --arith "$arith" -o "$T/$name.ppm" "$@"; then
        echo "FAIL spd_rules_board_image_$name: the board did not render"
        return
    fi
    local host board
    host=$(spd_counts "$T/$name-ref.log")
    board=$(spd_counts "$T/spd_rules_board_counts_$name.log")
    if [ -n "$host" ] && [ "$host" = "$board" ]; then
        echo "PASS spd_rules_board_counts_$name"
    else
        echo "FAIL spd_rules_board_counts_$name: board '$board', host '$host'"
    fi
    render_same "spd_rules_board_image_$name" "$T/$name-ref.ppm" "$T/$name.ppm"
}
board_vs_host balls "$T/balls1.nff" 64x64 float --ncs 4
board_vs_host mount "$T/mount2.nff" 64x48 fixed --ncs 5 --clip lists
