#!/usr/bin/env bash
# Haze (`haze { colour R G B  distance D }`, render/haze.h): a bad haze
# block is refused naming its line and the problem, before any render; the
# board's image of scenes/haze.scn equals the host build's byte for byte in
# every arithmetic (float and fixed escalating, as by default, and fixed
# plain with its doubtful pixels painted: the flags agree too); the haze
# changes the image, and a scene without haze is what it was.  The check
# against POV-Ray's fog is tests/images/pov.sh's (pov_haze).
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready haze_parse_second haze_parse_missing haze_parse_distance haze_parse_unknown \
    haze_parse_colour render_haze_float render_haze_soft render_haze_fixed render_haze_double \
    render_haze_fixed_marked render_haze_changes render_haze_export || exit 0
SIZE=64x48
scn=scenes/haze.scn

# refused NAME WANT HAZE-BLOCK: a scene with that block is refused by
# links1 ref, exit 1, the message naming the file, the line and WANT
refused() {
    local name=$1 want=$2 bad=$RENDER_TMP/$1.scn log=$RENDER_TMP/$1.log
    sed "s/^haze .*/$3/" "$scn" >"$bad"
    local line
    line=$(grep -n '^haze\|^# 2nd' "$bad" | head -n 1 | cut -d: -f1)
    "$LINKS1" ref "$bad" -o "$RENDER_TMP/$name.png" >"$log" 2>&1
    local rc=$?
    if [ $rc -eq 1 ] && grep -q "$bad:$line:[0-9]*: .*$want" "$log" && [ ! -e "$RENDER_TMP/$name.png" ]; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc, want 1 and '$bad:$line:COL: ...$want': $(tail -n 1 "$log")"
    fi
}
refused haze_parse_second 'a second haze block' \
    'haze { colour 0.5 0.5 0.5  distance 9 } haze { colour 1 1 1  distance 2 }'
refused haze_parse_missing 'haze needs a colour R G B and a distance D (missing: distance)' \
    'haze { colour 0.5 0.5 0.5 }'
refused haze_parse_distance 'haze distance must be over 0' 'haze { colour 0.5 0.5 0.5  distance 0 }'
refused haze_parse_unknown "unknown haze property 'density'" \
    'haze { colour 0.5 0.5 0.5  distance 9  density 2 }'
refused haze_parse_colour 'haze colour' 'haze { colour 0.5 1.5 0.5  distance 9 }'

# board = host in every arithmetic (2 NCs, decreasing areas)
for a in float soft fixed double; do
    name=render_haze_$a
    out=$RENDER_TMP/$name.ppm
    ref=$(render_ref $scn $a $SIZE)
    render_board $name "$out" $scn -o "$out" --arith $a --ncs 2 --size $SIZE &&
        render_same $name "$ref" "$out"
done

# fixed point's own colours and flags (--mark-lost paints its doubts)
name=render_haze_fixed_marked
ref=$RENDER_TMP/haze-fixed-marked-host.ppm
"$LINKS1" ref $scn --arith fixed --size $SIZE --no-escalate --mark-lost -o "$ref" >"$ref.log" 2>&1
out=$RENDER_TMP/$name.ppm
render_board $name "$out" $scn -o "$out" --arith fixed --ncs 3 --size $SIZE --no-escalate \
    --mark-lost --balance dynamic && render_same $name "$ref" "$out"

# the haze changes the image: without it (the block taken out) most
# pixels differ by more than 8/255
clear=$RENDER_TMP/clear.scn
grep -v '^haze ' $scn >"$clear"
"$LINKS1" ref "$clear" --size $SIZE -o "$RENDER_TMP/clear.ppm" >/dev/null 2>&1
dbl=$(render_ref $scn double $SIZE)
if [ -s "$RENDER_TMP/clear.ppm" ] && ! "$LINKS1" compare "$dbl" "$RENDER_TMP/clear.ppm" \
    --within 8 --min-fraction 0.5 >"$RENDER_TMP/changes.log" 2>&1 &&
    grep -q 'largest difference' "$RENDER_TMP/changes.log"; then
    echo "PASS render_haze_changes"
else
    echo "FAIL render_haze_changes: the image without haze is within 8/255 on half its pixels (or a render failed): $(grep -m1 within "$RENDER_TMP/changes.log")"
fi

# export-pov writes POV-Ray's constant fog with the same distance and colour
pov=$RENDER_TMP/haze.pov
if "$LINKS1" export-pov $scn -o "$pov" --strict >/dev/null 2>&1 &&
    tr '\n' ' ' <"$pov" | grep -q 'fog { *fog_type 1 *distance 9 *color rgb <0.6, 0.65, 0.7> *}'; then
    echo "PASS render_haze_export"
else
    echo "FAIL render_haze_export: no 'fog { fog_type 1 distance 9 color rgb <0.6, 0.65, 0.7> }' in $pov"
fi
