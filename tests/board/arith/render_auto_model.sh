#!/usr/bin/env bash
# --auto (host-tools/ref/arith_auto.c): the arithmetic, min_weight and
# density steps chosen together for 40 dB against double at the most
# accurate model (256 density steps, min_weight 1/4096).  Its cost is the
# board's NC instruction count (as --arith auto's), so this boots boards.
# At 200x150 the pick is judged from a 160x120 pre-render, and checked here
# against the reference rendered at the full 200x150:
#   thin density features (make_scene.py density_steps): the default 24
#             steps miss 40 dB, so --auto raises them; its image keeps 40 dB
#             at full size; the steps are judged again at full size, where
#             one rung fewer misses 40 dB; the reason names the density steps
#   two fat density blobs: the default 24 steps keep 40 dB, so --auto does
#             not raise them; its image keeps 40 dB
#   no density sphere (scale 1): no steps chosen, min_weight the knob named;
#             its image keeps 40 dB
#   links1 render --auto: the board renders the pick, equal to the host
#             build of the pick with the same model
# and bad uses are refused with the reason named.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready auto_model || exit 0
SIZE=200x150
REF_WEIGHT=0.000244140625 # 1/4096
thin=$RENDER_TMP/thin.scn fat=$RENDER_TMP/fat.scn plain=$RENDER_TMP/plain.scn
python3 host-tools/gen/make_scene.py density_steps 24 --size $SIZE >"$thin"
python3 host-tools/gen/make_scene.py scale 1 --size $SIZE >"$plain"
cat >"$fat" <<EOF
camera { eye 0 2 -6  look_at 0 1 0  up 0 1 0  fov 45 }
resolution ${SIZE%x*} ${SIZE#*x}
background 0.1 0.12 0.2
light point { colour 0.8 0.8 0.75  position 4 8 -5 }
material floor { colour 0.8 0.8 0.75  dic 0.25 drc 0.7 }
material red { colour 0.9 0.2 0.15  dic 0.15 drc 0.75  phong 40 }
box { material floor  min -6 -0.5 -4  max 6 0 8 }
density { material red  threshold 0.5  component -0.6 1 0 1.6 1  component 0.6 1.2 0.3 1.5 1 }
EOF

# auto_run NAME SCENE: links1 ref --auto at SIZE; the pick line into $pick,
# the full-size PSNR against the reference into $db
auto_run() {
    local name=$1 scene=$2 ref=$RENDER_TMP/$1-ref.ppm log=$RENDER_TMP/$1.log
    pick= db=
    "$LINKS1" ref "$scene" --arith double --density-steps 256 --min-weight $REF_WEIGHT \
        -o "$ref" >/dev/null 2>&1 || { echo "FAIL ${name}_runs: the reference failed"; return 1; }
    if ! timeout 600 "$LINKS1" ref "$scene" --auto --fpu vfp -o "$RENDER_TMP/$name.ppm" >"$log" 2>&1; then
        echo "FAIL ${name}_runs: $(tail -n 1 "$log")"
        return 1
    fi
    pick=$(grep -- '--auto picks' "$log")
    LINKS1_AUTO_LOG=$log
    db=$("$LINKS1" compare "$ref" "$RENDER_TMP/$name.ppm" --min-fraction 0 2>&1 |
        sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
    echo "    $pick"
    echo "PASS ${name}_runs (full size: $db dB)"
}
keeps() { # NAME: the full-size image keeps 40 dB
    if awk -v d="$db" 'BEGIN { exit !(d != "" && d + 0 >= 40) }'; then
        echo "PASS ${1}_keeps_40db_full_size ($db dB at $SIZE)"
    else
        echo "FAIL ${1}_keeps_40db_full_size: $db dB at $SIZE against double at 256 steps, min_weight 1/4096"
    fi
}
steps_of() { sed -nE 's/.*--auto picks [^:]* with ([0-9]+) density steps.*/\1/p' <<<"$pick"; }

if auto_run auto_model_thin "$thin"; then
    s=$(steps_of)
    if [ -n "$s" ] && [ "$s" -gt 24 ]; then
        echo "PASS auto_model_thin_raises_steps ($s steps)"
    else
        echo "FAIL auto_model_thin_raises_steps: '$s' steps, want more than the default 24"
    fi
    keeps auto_model_thin
    # the steps were judged again at 200x150: one rung fewer at the pick's
    # arithmetic and min_weight misses 40 dB there
    below=$(sed -nE 's/.*binding: .*density steps \(([0-9]+) give ([0-9.]+) dB\).*/\1 \2/p' <<<"$pick")
    read -r bs bdb <<<"$below"
    w=$(sed -nE 's/.*--auto picks float with [0-9]+ density steps, min_weight 1\/([0-9]+):.*/\1/p' <<<"$pick")
    bq=
    if [ -n "$bs" ] && [ -n "$w" ]; then
        "$LINKS1" ref "$thin" --arith float --density-steps "$bs" \
            --min-weight "$(awk -v d="$w" 'BEGIN { printf "%.17g", 1 / d }')" \
            -o "$RENDER_TMP/thin-below.ppm" >/dev/null 2>&1
        bq=$("$LINKS1" compare "$RENDER_TMP/auto_model_thin-ref.ppm" "$RENDER_TMP/thin-below.ppm" \
            --min-fraction 0 2>&1 | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
    fi
    if grep -q "density steps judged again at the render's $SIZE" "$LINKS1_AUTO_LOG" &&
        awk -v d="$bq" 'BEGIN { exit !(d != "" && d + 0 < 40) }'; then
        echo "PASS auto_model_thin_fewest_steps_full_size ($bs steps give $bq dB at $SIZE; the pick $s)"
    else
        echo "FAIL auto_model_thin_fewest_steps_full_size: judged at $SIZE? $(grep -c "judged again at the render's $SIZE" "$LINKS1_AUTO_LOG"); $bs steps at 1/$w give '$bq' dB there (want < 40): $pick"
    fi
    if grep -qE 'binding: (density steps \([0-9]+ give [0-9.]+ dB\)|min_weight .*then density steps \()' <<<"$pick"; then
        echo "PASS auto_model_thin_names_steps"
    else
        echo "FAIL auto_model_thin_names_steps: the reason does not name the density steps: $pick"
    fi
fi

if auto_run auto_model_fat "$fat"; then
    s=$(steps_of)
    if [ -n "$s" ] && [ "$s" -le 24 ]; then
        echo "PASS auto_model_fat_no_more_steps ($s steps)"
    else
        echo "FAIL auto_model_fat_no_more_steps: '$s' steps, want no more than the default 24"
    fi
    keeps auto_model_fat
fi

if auto_run auto_model_plain "$plain"; then
    if grep -qE -- '--auto picks float with min_weight 1/[0-9]+: the cheapest' <<<"$pick" &&
        grep -qE 'binding: min_weight \(1/[0-9]+ gives [0-9.]+ dB\)' <<<"$pick"; then
        echo "PASS auto_model_plain_names_weight"
    else
        echo "FAIL auto_model_plain_names_weight: want float, no steps, min_weight binding: $pick"
    fi
    keeps auto_model_plain
fi

# links1 render --auto: the board's image is the host build's of the pick
small=$RENDER_TMP/thin-small.scn out=$RENDER_TMP/board.ppm
python3 host-tools/gen/make_scene.py density_steps 24 --size 64x48 >"$small"
if render_board auto_model_render "$out" "$small" -o "$out" --auto --ncs 2; then
    line=$(grep -- '--auto picks' "$RENDER_TMP/auto_model_render.log")
    s=$(sed -nE 's/.*picks float with ([0-9]+) density steps.*/\1/p' <<<"$line")
    w=$(sed -nE 's/.*density steps, min_weight 1\/([0-9]+):.*/\1/p' <<<"$line")
    if [ -n "$s" ] && [ -n "$w" ]; then
        host=$RENDER_TMP/board-host.ppm
        "$LINKS1" ref "$small" --arith float --density-steps "$s" \
            --min-weight "$(awk -v d="$w" 'BEGIN { printf "%.17g", 1 / d }')" -o "$host" >/dev/null 2>&1
        render_same auto_model_render_board_is_host "$host" "$out"
    else
        echo "FAIL auto_model_render_board_is_host: no float pick with steps and min_weight: $line"
    fi
fi

refused() { # NAME WANT args...
    local name=$1 want=$2; shift 2
    local msg rc
    msg=$(timeout 120 "$LINKS1" "$@" 2>&1)
    rc=$?
    if [ $rc -ne 0 ] && [[ $msg == *"$want"* ]]; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc, '$(echo "$msg" | head -n 1)' does not say '$want'"
    fi
}
refused auto_model_refuses_arith "--auto chooses the arithmetic, min_weight and density steps, so it takes no --arith" \
    ref "$small" -o "$RENDER_TMP/x.ppm" --auto --arith fixed
refused auto_model_refuses_steps "so it takes no --density-steps" \
    render "$small" -o "$RENDER_TMP/x.ppm" --auto --density-steps 8
refused auto_model_refuses_target "--target-db '150': want a number" \
    ref "$small" -o "$RENDER_TMP/x.ppm" --auto --target-db 150
"$LINKS1" compile "$small" -o "$RENDER_TMP/small.l1s" >/dev/null 2>&1
refused auto_model_refuses_compiled "--auto sets density steps and min_weight, so it needs a text scene" \
    ref "$RENDER_TMP/small.l1s" -o "$RENDER_TMP/x.ppm" --auto
