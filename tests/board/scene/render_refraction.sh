#!/usr/bin/env bash
# --refraction off (transmission never bends, at any depth; the paper's
# Table 3): the board's image equals the host build's, bit for bit, and
# differs from the refracting image where the glass is seen.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_refraction || exit 0
SIZE=80x60
ref="$RENDER_TMP/ref-glass-off.ppm"
"$LINKS1" ref scenes/glass.scn -o "$ref" --arith float --size $SIZE --refraction off \
    >"$RENDER_TMP/ref-off.log" 2>&1
out="$RENDER_TMP/glass-off.ppm"
on="$RENDER_TMP/glass-on.ppm"
if render_board render_refraction_off "$out" scenes/glass.scn -o "$out" --ncs 2 --size $SIZE \
    --refraction off; then
    render_same render_refraction_off_board_is_host "$ref" "$out"
fi
if render_board render_refraction_on "$on" scenes/glass.scn -o "$on" --ncs 2 --size $SIZE; then
    # The share of pixels within 1/255 on every channel: the glass covers
    # well over 5% of the frame.
    same=$("$LINKS1" compare "$on" "$out" 2>&1 | grep -o 'every channel: [0-9.]*%' | grep -o '[0-9.]*')
    if [ -n "$same" ] && awk -v s="$same" 'BEGIN { exit !(s < 95) }'; then
        echo "PASS render_refraction_off_differs (${same}% of pixels alike)"
    else
        echo "FAIL render_refraction_off_differs: refracting and not refracting alike in '${same:-?}%' of pixels"
    fi
    rays() { grep -o "[0-9]* refraction" "$RENDER_TMP/$1.log" | grep -o '[0-9]*'; }
    if [ "$(rays render_refraction_off)" = 0 ] && [ "$(rays render_refraction_on)" -gt 0 ]; then
        echo "PASS render_refraction_off_traces_no_refracted_ray"
    else
        echo "FAIL render_refraction_off_traces_no_refracted_ray: refracted rays off '$(rays render_refraction_off)', on '$(rays render_refraction_on)'"
    fi
fi
