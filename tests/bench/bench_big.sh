#!/usr/bin/env bash
# bench_big.sh: scenes of 100,000 triangles and more, end to end on the
# board: SPD tetra 9 (262,144 triangles) and teapot 64 (269,824), written as
# NFF (teapot 64's text scene would pass 64 MiB), and a generated terrain
# of 100,352 triangles imported with the model statement
# (host-tools/gen/make_terrain.py).  Each is compiled, rendered once on the
# board with the defaults,
#   links1 render SCENE --arith float --ncs BENCH_BIG_NCS --size BENCH_BIG_SIZE --count-insns
# (default 64 NCs, 512x480; with --trace for the DM's preparation of the
# frame), and on the host (links1 ref --arith float, escalating as the
# board did), the two images compared byte for byte.  Prints a markdown table: the
# whole command's wall time on this host split as links1 render prints it
# (boot, upload, the DM's load with the frame's preparation, the frame,
# pull), the DM's and the NCs' guest instructions.  One run each; takes
# minutes.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SPD=${SPD:-build/links1-spd}
export FW_DIR=${FW_DIR:-build}
SIZE=${BENCH_BIG_SIZE:-512x480}
NCS=${BENCH_BIG_NCS:-64}
SCENES=${BENCH_BIG_SCENES:-tetra-9 teapot-64 terrain-225}
LIMIT_S=${BENCH_RUN_LIMIT_S:-3600}
make -s --no-print-directory build/links1 build/links1-ref-float build/links1-spd all >&2
TMP=$(mktemp -d /tmp/links1-bench-big.XXXXXX)
trap 'rm -rf "$TMP"' EXIT

# wall FIELD LOG: milliseconds of FIELD in links1 render's wall line
wall() { sed -nE "s/^links1 render: wall .*[ (]$1 ([0-9]+).*/\1/p" "$2" | head -1; }

echo "### Scenes of 100,000 triangles and more on the board ($SIZE, float, $NCS NCs, one run)"
echo
echo "Wall times in seconds on this host (2 cores), as links1 render splits them;"
echo "DM: its load of the scene and preparation of the frame (the preparation in"
echo "brackets); instructions: guest instructions counted by the plugin."
echo
echo "| scene | triangles | clusters | wall s | boot | upload | DM load (prepare) | frame | pull | DM insns per triangle | DM prepare per triangle | NC insns per ray | image vs host |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for db in $SCENES; do
    name=${db%-*} n=${db#*-}
    if [ "$name" = terrain ]; then
        python3 host-tools/gen/make_terrain.py "$n" "$TMP/terrain" ||
            { echo "bench_big: make_terrain.py $n failed" >&2; exit 1; }
        scene="$TMP/terrain/terrain.scn"
    else
        scene="$TMP/$db.nff"
        "$SPD" "$name" "$n" -o "$scene" --size "$SIZE" 2>"$TMP/spd.log" ||
            { echo "bench_big: links1-spd $db failed: $(cat "$TMP/spd.log")" >&2; exit 1; }
    fi
    "$LINKS1" compile "$scene" -o "$TMP/$db.l1s" >"$TMP/c.log" 2>&1 ||
        { echo "bench_big: compile $db failed: $(cat "$TMP/c.log")" >&2; exit 1; }
    read -r prims clusters < <(sed -E -n \
        's/.*: [0-9]+ bytes \(([0-9]+) primitives, ([0-9]+) clusters\).*/\1 \2/p' "$TMP/c.log")
    log="$TMP/b-$db.log"
    if timeout "$LIMIT_S" "$LINKS1" render "$TMP/$db.l1s" -o "$TMP/b.ppm" --arith float \
        --ncs "$NCS" --count-insns --trace "$TMP/$db.trace" >"$log" 2>&1; then
        # the host escalates as the board did: not where the double copy
        # did not fit beside the scene (the render says so)
        esc=()
        grep -q 'escalation off' "$log" && esc=(--no-escalate)
        "$LINKS1" ref "$TMP/$db.l1s" -o "$TMP/r.ppm" --arith float "${esc[@]}" >"$TMP/r.log" 2>&1
        same=differs
        cmp -s "$TMP/b.ppm" "$TMP/r.ppm" && same=same
        rays=$(sed -nE 's/.*rays ([0-9]+) primary, ([0-9]+) shadow, ([0-9]+) reflection, ([0-9]+) refraction, ([0-9]+) transmission.*/\1 \2 \3 \4 \5/p' "$log" |
               awk '{ print $1 + $2 + $3 + $4 + $5 }')
        read -r dm ncs_total < <(sed -nE 's/^  DM ([0-9]+), RC [0-9]+, NCs total ([0-9]+).*/\1 \2/p' "$log")
        prep_ms=$(wall prepare "$log")
        awk -v db="$db" -v p="$prims" -v c="$clusters" \
            -v total="$(sed -nE 's/^links1 render: wall ([0-9]+) ms.*/\1/p' "$log")" \
            -v boot="$(wall boot "$log")" -v up="$(wall upload "$log")" \
            -v load="$(wall load "$log")" -v prep="$prep_ms" -v fr="$(wall frames "$log")" \
            -v pull="$(wall pull "$log")" -v dm="$dm" -v nct="$ncs_total" -v rays="$rays" \
            -v same="$same" -v dmp="$(awk '$1 == "dm_prepare" { print $2 }' "$TMP/$db.trace")" \
            'BEGIN { printf "| %s | %d | %d | %.1f | %.1f | %.1f | %.1f (%.1f) | %.1f | %.1f | %.0f | %s | %.0f | %s |\n",
                     db, p, c, total / 1000, boot / 1000, up / 1000, load / 1000, prep / 1000,
                     fr / 1000, pull / 1000, dm / p, dmp == "" ? "-" : sprintf("%.0f", dmp / p),
                     nct / rays, same }'
    else
        echo "| $db | $prims | $clusters | failed: $(tail -n 1 "$log") | | | | | | | | | |"
    fi
done
