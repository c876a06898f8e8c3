#!/usr/bin/env bash
# Paper mode on the board (docs/scene-format.md, "Paper mode"): the scene of
# the paper's Tables 2 and 3 (build/scenes/fig9.scn, hand-made clusters) rendered
# with `options { paper on }` and with --paper.  The line paper mode prints
# names every setting; the board ran what it names (the RC's area count and
# schedule in the summary, the NCs' per-area set-up of the clipping lists in
# the trace against clipping in the tree, the compiled scene's clusters
# those of the author); the image equals the host build's, bit for bit, and
# the two ways of asking for paper mode give the same image.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_paper_line render_paper_schedule render_paper_clusters render_paper_same \
    render_paper_flag_same render_paper_lists || exit 0
SIZE=64x60 H=60
# the scene with options { paper on }
scn="$RENDER_TMP/fig9-paper.scn"
sed 's/^options { max_depth 5 }/options { max_depth 5  paper on }/' build/scenes/fig9.scn >"$scn"
grep -q 'paper on' "$scn" || echo "FAIL render_paper_line: no options block in build/scenes/fig9.scn"
ref=$(render_ref "$scn" float $SIZE)
out="$RENDER_TMP/paper.ppm" log="$RENDER_TMP/render_paper.log"
if render_board render_paper "$out" "$scn" -o "$out" --ncs 2 --size $SIZE \
    --trace "$RENDER_TMP/lists.trace"; then
    line=$(grep -m1 'paper mode:' "$log")
    # every setting by name, with the values paper mode takes
    miss=
    for want in "src/trc by angle" "depth fixed at 5 (min_weight 0)" \
        "areas lines K $H (whole scanlines)" "ask finished" "clip lists" "auto_hierarchy off"; do
        [[ $line == *"$want"* ]] || miss="$miss '$want'"
    done
    [ -z "$miss" ] && echo "PASS render_paper_line" ||
        echo "FAIL render_paper_line: missing$miss in: ${line:-no paper mode line}"
    # the RC's schedule: the areas the board handed out, as the line says
    k=$(echo "$line" | sed -n 's/.*areas lines K \([0-9]*\).*/\1/p')
    sum=$(grep -m1 'NCs, [0-9]* areas (' "$log")
    if [ -n "$k" ] && [[ $sum == *" $k areas (lines, K $k, asking when finished, clipping lists)"* ]]; then
        echo "PASS render_paper_schedule"
    else
        echo "FAIL render_paper_schedule: paper mode said K ${k:-?}, the board: $(echo "$sum" | grep -o '[0-9]* areas ([^)]*)')"
    fi
    # links1 replay --paper on this trace replays what the board did (not a
    # what-if); with the default schedule it is a what-if
    rp=$("$LINKS1" replay "$RENDER_TMP/lists.trace" --ncs 2 --paper 2>&1)
    rd=$("$LINKS1" replay "$RENDER_TMP/lists.trace" --ncs 2 --balance decreasing --ask ahead 2>&1)
    if [[ $rp == *"replayed: what the board does; NCs asking when finished"* ]] &&
        [[ $rd == *"replayed: a what-if"* ]]; then
        echo "PASS render_paper_replay_is_the_board"
    else
        echo "FAIL render_paper_replay_is_the_board: --paper: $(echo "$rp" | grep replayed:); default: $(echo "$rd" | grep replayed:)"
    fi
    # the compiled scene's clusters: the author's in paper mode, more with
    # the automatic hierarchy
    nc=$(echo "$line" | sed -n 's/.*clusters \([0-9]*\) (.*/\1/p')
    own=$(sed -nE 's/.* ([0-9]+) primitives in ([0-9]+) clusters.*/\2/p' build/scenes/fig9.scn | head -1)
    auto=$("$LINKS1" compile build/scenes/fig9.scn -o "$RENDER_TMP/auto.l1s" |
        sed -n 's/.*primitives, \([0-9]*\) clusters.*/\1/p')
    if [ -n "$nc" ] && [ "$nc" = "$own" ] && [ -n "$auto" ] && [ "$auto" -gt "$own" ]; then
        echo "PASS render_paper_clusters"
    else
        echo "FAIL render_paper_clusters: paper mode ${nc:-?} clusters, the scene's own ${own:-?}, with the automatic hierarchy ${auto:-?}"
    fi
    render_same render_paper_same "$ref" "$out"
else
    echo "FAIL render_paper_line: no render"
    echo "FAIL render_paper_schedule: no render"
    echo "FAIL render_paper_clusters: no render"
    echo "FAIL render_paper_same: no render"
fi
# --paper on the command line: the same image; with --clip tree beside it,
# the NCs' per-area set-up (the Y lists built) is far smaller than with the
# paper's lists, so the lists were what the NCs ran.
out2="$RENDER_TMP/flag.ppm"
if render_board render_paper_flag "$out2" build/scenes/fig9.scn -o "$out2" --paper --ncs 2 \
    --size $SIZE --clip tree --trace "$RENDER_TMP/tree.trace"; then
    render_same render_paper_flag_same "$out" "$out2"
    setup() { awk '$1 == "area" { s += $11 } END { print s + 0 }' "$1" 2>/dev/null; }
    sl=$(setup "$RENDER_TMP/lists.trace") st=$(setup "$RENDER_TMP/tree.trace")
    if grep -q 'clip tree' "$RENDER_TMP/render_paper_flag.log" && [ "${sl:-0}" -gt $((10 * ${st:-0})) ]; then
        echo "PASS render_paper_lists"
    else
        echo "FAIL render_paper_lists: area set-up with the lists ${sl:-?}, in the tree ${st:-?} instructions (or --clip tree not in the line)"
    fi
else
    echo "FAIL render_paper_flag_same: no render"
    echo "FAIL render_paper_lists: no render"
fi
