#!/usr/bin/env bash
# bench_world.sh: the DM's preparation of an animation's frames in eye
# space (the paper's method, the default) and in world space
# (--world-space: the DM keeps the triangles' world form and the NCs turn
# the camera rays), against the NCs' frame, on SPD tetra scenes where
# something moves (host-tools/gen/make_spin.sh N FRAMES OUT MOVE): the camera
# (the DM keeps every triangle), a small ball in front of the tetrahedron
# (it prepares the ball's cluster again and keeps the triangles) or the
# whole tetrahedron spinning (it prepares everything again).  Per scene, move and mode,
# bench_pipeline.sh traces each frame on the board (float, BENCH_NCS NCs,
# default 64, BENCH_SIZE default 512x480): the DM's preparation of frame 0
# (at the upload), of the later frames (median: what an animation costs a
# frame), and the NCs' frame on equal-speed unit computers (replay at 1
# MIPS, median over the frames), and the RC's forwarding of a later frame
# (links1 render --frames 0:F-1 --count-insns less --frames 0:0, over the
# F-1 later frames: the broadcast block then holds the frame before).
# Guest instructions; one run each.
# Prints a markdown table and draws BENCH_OUT/world-space.png (a temporary
# directory unless BENCH_OUT is given).  BENCH_WORLD_TETRAS picks the
# tetra sizes (default "7 9"), BENCH_WORLD_MOVES the moves (default
# "camera ball spin"), BENCH_WORLD_FRAMES the frames (default 3).
set -u
cd "$(dirname "$0")/../.."
export LINKS1=${LINKS1:-build/links1} FW_DIR=${FW_DIR:-build}
make -s --no-print-directory build/links1 build/links1-spd all >&2
TMP=$(mktemp -d /tmp/links1-bench-world.XXXXXX)
trap 'rm -rf "$TMP"' EXIT
OUT=${BENCH_OUT:-$TMP}
mkdir -p "$OUT"
export BENCH_NCS=${BENCH_NCS:-64} BENCH_SIZE=${BENCH_SIZE:-512x480}
frames=${BENCH_WORLD_FRAMES:-3}
# rc_insns SCENE FRAMES ARGS...: the RC's guest instructions over those frames
rc_insns() {
    local scn=$1 fr=$2
    shift 2
    "$LINKS1" render "$scn" --frames "$fr" --ncs "$BENCH_NCS" --size "$BENCH_SIZE" --count-insns \
        -o "$TMP/rc.ppm" "$@" 2>&1 | awk '$1 == "core" && $3 == "RC" { print $4 }'
}
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR) print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
echo "bench_world: SPD tetra where something moves, $frames frames, float, $BENCH_NCS NCs, $BENCH_SIZE"
echo
echo "| scene | triangles | what moves | preparation | DM frame 0 (upload) | DM later frame (median) | per triangle | RC later frame (mean) | NCs' frame at 1 MIPS (median, M insns) | DM later frame / NCs' frame |"
echo "|---|---|---|---|---|---|---|---|---|---|"
: >"$TMP/world.dat"
cases=""
for n in ${BENCH_WORLD_TETRAS:-7 9}; do
    for move in ${BENCH_WORLD_MOVES:-camera ball spin}; do
        cases="$cases $n:$move"
    done
done
for c in $cases; do
    n=${c%%:*} move=${c#*:}
    scn=$TMP/$move$n.scn
    arg=$move
    [ "$move" = spin ] && arg=""
    bash host-tools/gen/make_spin.sh "$n" "$frames" "$scn" $arg 2>/dev/null || { echo "bench_world: make_spin.sh $n $move failed"; exit 1; }
    tris=$((4 ** n))
    for mode in eye world; do
        args=""
        [ $mode = world ] && args=--world-space
        log=$TMP/$n-$move-$mode.log
        BENCH_ARGS=$args bash tests/bench/bench_pipeline.sh "$scn" >"$log" 2>&1 ||
            { echo "bench_world: tetra $n $move $mode: $(tail -n 1 "$log")"; exit 1; }
        rows=$(awk '$1 ~ /^[0-9]+$/ && NF >= 3' "$log")
        first=$(echo "$rows" | awk 'NR == 1 { print $2 }')
        later=$(echo "$rows" | awk 'NR > 1 { print $2 }' | median)
        ms=$(echo "$rows" | awk '{ print $3 }' | median)
        rc_all=$(rc_insns "$scn" "0:$((frames - 1))" $args)
        rc_one=$(rc_insns "$scn" 0:0 $args)
        [ -n "$first" ] && [ -n "$later" ] && [ -n "$ms" ] && [ -n "$rc_all" ] && [ -n "$rc_one" ] ||
            { echo "bench_world: tetra $n $move $mode: no numbers"; cat "$log"; exit 1; }
        awk -v n="$n" -v t="$tris" -v mv="$move" -v m="$mode" -v f="$first" -v l="$later" -v ms="$ms" \
            -v rc="$(( (rc_all - rc_one) / (frames - 1) ))" 'BEGIN {
            what = mv == "camera" ? "the camera" : mv == "ball" ? "a ball" : "the tetrahedron (spins)"
            printf "| tetra %d | %d | %s | %s | %.1f M | %.2f M | %.1f | %.2f M | %.1f | %.3f |\n", n, t, what, m == "eye" ? "eye space (default)" : "world space (--world-space)", f / 1e6, l / 1e6, l / t, rc / 1e6, ms / 1e3, l / (ms * 1e3) }'
        echo "t$n-$move-$mode $later $(awk -v ms="$ms" 'BEGIN { print ms * 1000 }') $(( (rc_all - rc_one) / (frames - 1) ))" >>"$TMP/world.dat"
    done
done
gnuplot <<GP || { echo "bench_world: gnuplot failed" >&2; exit 1; }
set terminal pngcairo size 1100,560
set output "$OUT/world-space.png"
set title "An animation's later frame on the board: the DM's and the RC's work against the NCs' frame\n(SPD tetra; the camera moves, a ball moves or the tetrahedron spins; float, $BENCH_NCS NCs, $BENCH_SIZE)"
set ylabel "guest instructions"
set logscale y; set yrange [1e4:5e9]; set grid ytics
set style data histograms; set style histogram clustered gap 1; set style fill solid 0.8 border -1
set boxwidth 0.9; set xtics rotate by -30 font ",9"
plot "$TMP/world.dat" using 2:xtic(1) title "DM preparation of a later frame", \
     "" using 4 title "RC's later frame (forwarding, areas, pixels)", \
     "" using 3 title "NCs' frame (replay at 1 MIPS, equal-speed unit computers)"
GP
echo
echo "chart: $OUT/world-space.png"
