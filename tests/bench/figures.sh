#!/usr/bin/env bash
# figures.sh: the paper's figures and tables on equal-speed unit computers
# (docs/results/paper-figures.md): each from board runs traced with
# links1 render --trace and replayed with links1 replay.  Writes into
# FIG_OUT (default docs/figures): fig7.png, fig10.png (gnuplot), and
# fig7.md, fig10.md, table2.md, table3.md (the numbers, with the commands).
#
#   make figures                         # the full size (also in make bench)
#   FIG_SMALL=1 FIG_OUT=DIR bash tests/bench/figures.sh   # the reduced run
#
# The full size: demo.scn at 512x480 (Fig. 7: the board at 1..254 NCs, the
# replay at 1..254), demo.scn with shadows off at 512x480 (Fig. 10), SPD
# tetra 6 (4,096 triangles) at 256x240 (Table 2; the rows without the hierarchy
# traced at 64x60 and scaled), glass.scn at 256x240
# (Table 3).  FIG_SMALL=1 shrinks every size and NC list (well under 30 s).
# Parts "2p" and "3p": Tables 2 and 3 as the paper ran them, in paper mode
# (links1 render --paper): build/scenes/fig9.scn at 512x480 (the row without
# boxes traced at 64x60 and scaled), 16 NCs, simple dynamic balancing on
# 2,400 and 480 scanline areas, Table 2 non-refracting (its 82 s is Table
# 3's non-refracting run).
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SPD=${SPD:-build/links1-spd}
export FW_DIR=${FW_DIR:-build}
OUT=${FIG_OUT:-docs/figures}
LIMIT_S=${FIG_RUN_LIMIT_S:-1800}
if [ "${FIG_SMALL:-0}" = 1 ]; then
    SIZE7=64x48 BOARD7="1 2 4" REPLAY7=1,2,4,8,16,64,254 SIZE10=64x48 K10="16 64 256 1024"
    T2SPD="tetra 3" SIZE2=32x24 SIZE2LOW=16x12 SIZE3=48x36 T2K="480 96"
    SIZE2P=64x60 SIZE2PLOW=16x15 T2PK="300 60"
else
    SIZE7=512x480 BOARD7="1 2 4 8 16 32 64 128 254" REPLAY7=1,2,4,8,16,32,64,128,254 SIZE10=512x480
    K10="64 128 256 512 1024 2048 4096 8192 16384" T2SPD="tetra 6" SIZE2=256x240 SIZE2LOW=64x60
    SIZE3=256x240
    T2K="2400 480"
    SIZE2P=512x480 SIZE2PLOW=64x60 T2PK="2400 480"
fi
SIZE2=${FIG_T2_SIZE:-$SIZE2} SIZE2LOW=${FIG_T2_LOW:-$SIZE2LOW}
PARTS=" ${FIG_PARTS:-7 10 2 3 2p 3p} " # which figures to make
# The tuned replay (docs/results/paper-figures.md): decreasing areas, an NC asking for its
# next area a round trip before it finishes, the DM preparing the frame
# while the previous one renders; per NC count the best smallest-area bound
# K and guided factor G of these (finer final areas pay off until the RC's
# service time limits them).
TUNED=(--balance decreasing --prefetch --pipelined)
TUNED_K="4096 8192 16384 32768" TUNED_G="2 3 4"
[ "${FIG_SMALL:-0}" = 1 ] && TUNED_K=4096 TUNED_G="2 3"
mkdir -p "$OUT"
# FIG_KEEP=DIR keeps the traces and logs there.
if [ -n "${FIG_KEEP:-}" ]; then
    TMP=$FIG_KEEP
    mkdir -p "$TMP"
else
    TMP=$(mktemp -d /tmp/links1-figures.XXXXXX)
    trap 'rm -rf "$TMP"' EXIT
fi
fail() { echo "figures: $*" >&2; exit 1; }

# board LOG links1-render-args...: one board run; exits on failure.  With
# FIG_REUSE=1 and FIG_KEEP, a run whose log is there already is not repeated
# (its trace is kept next to it).
board() {
    local log=$1; shift
    [ "${FIG_REUSE:-0}" = 1 ] && [ -n "${FIG_KEEP:-}" ] && grep -q 'trace of\|NCs total' "$log" \
        2>/dev/null && return 0
    timeout "$LIMIT_S" "$LINKS1" render "$@" >"$log" 2>&1 ||
        fail "links1 render $* failed: $(tail -n 3 "$log")"
}
nc_total() { sed -nE 's/.*NCs total ([0-9]+).*/\1/p' "$1"; }
nc_max() { sed -nE 's/.*max ([0-9]+),.*/\1/p' "$1"; }
# field NAME: the value after NAME on replay lines, one per line.
field() { awk -v k="$1" '$1 == "ncs" { for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }

# ---- Fig. 7: speed-up against NCs ----
if [[ $PARTS == *" 7 "* ]]; then
echo "figures: Fig. 7 (demo.scn $SIZE7)"
T7="$TMP/fig7.trace"
declare -A BOARD_S
one=
for n in $BOARD7; do
    args=(scenes/demo.scn --size "$SIZE7" --ncs "$n" --count-insns -o "$TMP/f7.ppm")
    [ "$n" = 1 ] && args+=(--trace "$T7")
    board "$TMP/b7-$n.log" "${args[@]}"
    [ -z "$one" ] && one=$(nc_total "$TMP/b7-$n.log")
    BOARD_S[$n]=$(awk -v a="$one" -v b="$(nc_max "$TMP/b7-$n.log")" 'BEGIN { printf "%.2f", a / b }')
done
"$LINKS1" replay "$T7" --ncs "$REPLAY7" >"$TMP/r7-default.txt" || fail "replay (defaults)"
# The reproduction: the frame rendered in paper mode (--paper: the paper's
# depth, src/trc, clipping lists, scanline areas, NCs asking once finished),
# traced on 1 NC and replayed with the paper's schedule.
T7P="$TMP/fig7-paper.trace"
board "$TMP/b7-paper.log" scenes/demo.scn --size "$SIZE7" --ncs 1 --paper --count-insns \
    --trace "$T7P" -o "$TMP/f7p.ppm"
grep -q "paper mode: .*ask finished, clip lists" "$TMP/b7-paper.log" ||
    fail "Fig. 7: $TMP/b7-paper.log shows no paper mode"
"$LINKS1" replay "$T7P" --ncs "$REPLAY7" --paper >"$TMP/r7-paper.txt" ||
    fail "replay (paper mode)"
# What-if, tuned: per NC count, the best of TUNED_K x TUNED_G.
: >"$TMP/r7-tuned.txt"
for n in ${REPLAY7//,/ }; do
    bestline=
    for k in $TUNED_K; do
        for g in $TUNED_G; do
            line=$("$LINKS1" replay "$T7" --ncs "$n" "${TUNED[@]}" --areas "$k" --guided "$g" |
                grep '^ncs') || fail "replay (tuned) $n NCs"
            line="$line K $k G $g"
            if [ -z "$bestline" ] || awk -v a="$(echo "$line" | field frame_ms)" \
                -v b="$(echo "$bestline" | field frame_ms)" 'BEGIN { exit !(a < b) }'; then
                bestline=$line
            fi
        done
    done
    echo "$bestline" >>"$TMP/r7-tuned.txt"
done
paste <(field ncs <"$TMP/r7-default.txt") <(field speed-up <"$TMP/r7-paper.txt") \
    <(field speed-up <"$TMP/r7-default.txt") <(field busy <"$TMP/r7-default.txt") \
    <(field frame_ms <"$TMP/r7-default.txt") <(field k <"$TMP/r7-default.txt") \
    <(field factor <"$TMP/r7-default.txt") <(field speed-up <"$TMP/r7-tuned.txt") \
    <(field K <"$TMP/r7-tuned.txt") <(field G <"$TMP/r7-tuned.txt") >"$TMP/r7.tsv"
{
    echo "# ncs board replay-paper-mode replay-board what-if-tuned"
    while read -r n sp sd busy ms k g st tk tg; do
        echo "$n ${BOARD_S[$n]:-NaN} $sp $sd $st"
    done <"$TMP/r7.tsv"
} >"$OUT/fig7.dat"
{
    echo "Fig. 7: speed-up over 1 NC, demo.scn at $SIZE7.  The reproduction, paper mode: links1"
    echo "render scenes/demo.scn --size $SIZE7 --ncs 1 --paper --count-insns --trace TP, replayed"
    echo "with links1 replay TP --ncs N --paper (scanline areas, K = the height, NCs asking once"
    echo "finished).  What the board does by default: links1 render scenes/demo.scn --size $SIZE7"
    echo "--ncs 1 --count-insns --trace T (the board's other NC counts the same without --trace),"
    echo "replayed with links1 replay T --ncs N; what-if, tuned: links1 replay T --ncs N"
    echo "${TUNED[*]} --areas K --guided G, the best K and G for each N."
    echo
    echo "| NCs | board (1-NC total / largest NC) | replay, paper mode (the reproduction) | replay, what the board does (ask ahead) | board: K, factor | board: NCs busy | board: frame s at 1 MIPS | what-if: tuned, pipelined | tuned: K, G |"
    echo "|---|---|---|---|---|---|---|---|---|"
    while read -r n sp sd busy ms k g st tk tg; do
        echo "| $n | ${BOARD_S[$n]:--} | $sp | $sd | $k, $g | $busy | $(awk -v m="$ms" 'BEGIN { printf "%.1f", m / 1000 }') | $st | $tk, $tg |"
    done <"$TMP/r7.tsv"
    echo
    echo "Paper mode's run: $(grep -m1 'paper mode:' "$TMP/b7-paper.log" | sed 's/^links1 render: //')"
} >"$OUT/fig7.md"
gnuplot -e "dat='$OUT/fig7.dat'; out='$OUT/fig7.png'; size='$SIZE7'" \
    tests/bench/plots/fig7.gp || fail "gnuplot fig7"
fi

# ---- Fig. 10: simple dynamic balancing, 64 NCs, shadows off ----
if [[ $PARTS == *" 10 "* ]]; then
echo "figures: Fig. 10 (demo.scn, shadows off, $SIZE10)"
sed 's/^options {/options { shadows off/' scenes/demo.scn >"$TMP/noshadow.scn"
rm -rf "$TMP/maps"
cp -r scenes/maps "$TMP/maps" # the scene's image maps beside it (a link out is refused)
grep -q 'shadows off' "$TMP/noshadow.scn" || fail "no options block in demo.scn to turn shadows off"
T10="$TMP/fig10.trace"
# Paper mode, but with the equal rectangles Fig. 10 measured
# ("等面積の長方形領域") in place of paper mode's scanlines.
board "$TMP/b10.log" "$TMP/noshadow.scn" --size "$SIZE10" --ncs 2 --paper --balance dynamic \
    --areas 1024 --trace "$T10" -o "$TMP/f10.ppm"
grep -q "paper mode: .*ask finished, clip lists" "$TMP/b10.log" ||
    fail "Fig. 10: $TMP/b10.log shows no paper mode"
: >"$TMP/r10.txt"
for k in $K10; do
    "$LINKS1" replay "$T10" --ncs 64 --paper --balance dynamic --areas "$k" | grep '^ncs' >>"$TMP/r10.txt" ||
        fail "replay fig10 K=$k"
done
paste <(field areas <"$TMP/r10.txt") <(field frame_ms <"$TMP/r10.txt") \
    <(field busy <"$TMP/r10.txt") <(field rc_busy <"$TMP/r10.txt") >"$TMP/r10.tsv"
best=$(sort -g -k2 "$TMP/r10.tsv" | head -1)
first=$(head -1 "$TMP/r10.tsv")
awk '{ printf "%s %.3f\n", $1, $2 / 1000 }' "$TMP/r10.tsv" >"$OUT/fig10.dat"
{
    echo "Fig. 10: simple dynamic balancing on 64 NCs, demo.scn with shadows off at $SIZE10"
    echo "in paper mode with the equal rectangles the paper measured (trace: links1 render"
    echo "NOSHADOW.scn --size $SIZE10 --ncs 2 --paper --balance dynamic --areas 1024 --trace T;"
    echo "replay: links1 replay T --ncs 64 --paper --balance dynamic --areas K)."
    echo
    echo "$(grep -m1 'paper mode:' "$TMP/b10.log" | sed 's/^links1 render: //')"
    echo
    echo "| areas | frame s at 1 MIPS | NCs busy | RC busy |"
    echo "|---|---|---|---|"
    awk '{ printf "| %s | %.1f | %s | %s |\n", $1, $2 / 1000, $3, $4 }' "$TMP/r10.tsv"
    echo
    echo "Best at $(echo "$best" | cut -f1) areas, $(awk -v a="$(echo "$first" | cut -f2)" \
        -v b="$(echo "$best" | cut -f2)" 'BEGIN { printf "%.2f", a / b }')x faster than at" \
        "$(echo "$first" | cut -f1) areas (the paper: best at 1,024, about 2x over 64)."
} >"$OUT/fig10.md"
gnuplot <<GP || fail "gnuplot fig10"
set terminal pngcairo size 800,560
set output "$OUT/fig10.png"
set title "Fig. 10: simple dynamic balancing, 64 NCs (demo.scn, shadows off, $SIZE10)"
set xlabel "areas"; set ylabel "frame time, s (units at 1 MIPS)"
set logscale x 2; set grid; set key top right
plot "$OUT/fig10.dat" using 1:2 title "replay" with linespoints pt 7
GP
fi

# ---- Table 2: the speed-ups one by one, 16 NCs ----
# A row without screen clipping has no per-area set-up: one trace (dynamic,
# the first K) prices both K from its pixels.  A row with clipping is traced
# once per K with that grid, so every replayed area, set-up included, is
# one the board drew (the replay's "exact" count).  The rows without the
# hierarchy (hours of emulation at full size) are traced at SIZE2LOW, the
# same camera, and replayed with --scale F: each pixel of the full frame
# costs what its traced pixel did (docs/trace.md).
if [[ $PARTS == *" 2 "* ]]; then
echo "figures: Table 2 (SPD $T2SPD, $SIZE2; rows without the hierarchy at $SIZE2LOW)"
W2=${SIZE2%x*} H2=${SIZE2#*x} WL=${SIZE2LOW%x*} HL=${SIZE2LOW#*x}
SCALE2=$((W2 / WL))
[ $((WL * SCALE2)) = "$W2" ] && [ $((HL * SCALE2)) = "$H2" ] ||
    fail "Table 2: $SIZE2 is not $SIZE2LOW times a whole number"
"$SPD" $T2SPD -o "$TMP/t2.scn" --size "$SIZE2" >"$TMP/spd.log" 2>&1 || fail "links1-spd $T2SPD"
"$SPD" $T2SPD -o "$TMP/t2low.scn" --size "$SIZE2LOW" >"$TMP/spd.log" 2>&1 || fail "links1-spd $T2SPD"
prims=$(sed -nE 's/.*: ([0-9]+) spheres, ([0-9]+) triangles.*/\1 spheres, \2 triangles/p' "$TMP/spd.log")
rows=("none|--no-bbox --no-hierarchy --no-yclip --no-xclip"
      "bounding boxes only|--no-hierarchy --no-yclip --no-xclip"
      "+ hierarchy|--no-yclip --no-xclip" "+ Y clipping|--no-xclip --clip lists"
      "+ X clipping (all, the paper's lists)|--clip lists"
      "all, clipping in the hierarchy instead (the board's default)|")
set -- $T2K
{
    echo "Table 2: SPD $T2SPD ($prims, the compiler's automatic hierarchy) at $SIZE2,"
    echo "16 NCs, simple dynamic balancing, NCs asking once finished; frame s at 1 MIPS, the DM"
    echo "preparing during the previous frame (trace: links1 render T2.scn --ncs 2 SWITCHES --ask finished --balance dynamic --areas K"
    echo "--trace T, rows without clipping once with K = $1, the others once per K; replay:"
    echo "links1 replay T --ncs 16 --balance dynamic --areas K --pipelined).  Rows marked * were"
    echo "traced at $SIZE2LOW and replayed with --scale $SCALE2 (each pixel priced at its traced"
    echo "pixel's instructions; their NC instructions are the scaled frame's)."
    echo
    echo "| speed-ups | NC instructions (M) | $1 areas: frame s | vs none | $2 areas: frame s | vs none |"
    echo "|---|---|---|---|---|---|"
} >"$OUT/table2.md"
none1= none2=
r=0
for row in "${rows[@]}"; do
    r=$((r + 1))
    sw=${row#*|} name=${row%%|*} scn="$TMP/t2.scn" scale=1
    if [[ $sw == *--no-hierarchy* ]]; then
        scn="$TMP/t2low.scn" scale=$SCALE2 name="$name *"
    fi
    ta="$TMP/t2-$r-$1.trace" tb="$TMP/t2-$r-$2.trace"
    board "$TMP/b2-$r-$1.log" "$scn" --ncs 2 $sw --ask finished --balance dynamic --areas "$1" \
        --trace "$ta" -o "$TMP/t2.ppm"
    if [[ $sw == *--no-yclip*--no-xclip* ]]; then
        tb=$ta
    else
        board "$TMP/b2-$r-$2.log" "$scn" --ncs 2 $sw --ask finished --balance dynamic \
            --areas "$2" --trace "$tb" -o "$TMP/t2.ppm"
    fi
    "$LINKS1" replay "$ta" --scale $scale --ncs 16 --balance dynamic --areas "$1" --pipelined \
        >"$TMP/r2a.txt" || fail "replay table 2"
    "$LINKS1" replay "$tb" --scale $scale --ncs 16 --balance dynamic --areas "$2" --pipelined \
        >"$TMP/r2b.txt" || fail "replay table 2"
    a=$(field frame_ms <"$TMP/r2a.txt") b=$(field frame_ms <"$TMP/r2b.txt")
    [ -z "$none1" ] && none1=$a none2=$b
    insns=$(awk -v s=$scale '$1 == "area" { u += $11; t += $15 - $11 }
        END { printf "%.1f", (u + t * s * s) / 1e6 }' "$ta")
    awk -v n="$name" -v a="$a" -v b="$b" -v na="$none1" -v nb="$none2" -v m="$insns" \
        'BEGIN { printf "| %s | %s | %.1f | %.1fx | %.1f | %.1fx |\n", n, m, a / 1000, na / a, b / 1000, nb / b }' \
        >>"$OUT/table2.md"
done
fi

# ---- Table 3: refracting against refractionless transmission ----
if [[ $PARTS == *" 3 "* ]]; then
echo "figures: Table 3 (glass.scn, $SIZE3)"
{
    echo "Table 3: glass.scn at $SIZE3, its own depth (max_depth 6), 16 NCs, decreasing"
    echo "balancing; frame s at 1 MIPS (trace: links1 render scenes/glass.scn --size $SIZE3 --ncs 2"
    echo "[--refraction off] --trace T; replay: links1 replay T --ncs 16 --pipelined)."
    echo
    echo "| transmission | frame s | NC instructions (M) | refracted rays |"
    echo "|---|---|---|---|"
} >"$OUT/table3.md"
for mode in on off; do
    board "$TMP/b3-$mode.log" scenes/glass.scn --size "$SIZE3" --ncs 2 --refraction "$mode" \
        --count-insns --trace "$TMP/t3-$mode.trace" -o "$TMP/t3.ppm"
    "$LINKS1" replay "$TMP/t3-$mode.trace" --ncs 16 --pipelined >"$TMP/r3.txt" || fail "replay table 3"
    ms=$(field frame_ms <"$TMP/r3.txt")
    eval "ms_$mode=$ms"
    awk -v n="$([ $mode = on ] && echo refracting || echo 'never bending (--refraction off)')" \
        -v ms="$ms" -v t="$(nc_total "$TMP/b3-$mode.log")" \
        -v r="$(grep -o '[0-9]* refraction,' "$TMP/b3-$mode.log" | grep -o '[0-9]*')" \
        'BEGIN { printf "| %s | %.1f | %.1f | %s |\n", n, ms / 1000, t / 1e6, r }' >>"$OUT/table3.md"
done
awk -v a="$ms_on" -v b="$ms_off" 'BEGIN { printf "\nRefracting takes %.2fx the time of never bending (the paper: 212 s against 82 s, 2.6x).\n", a / b }' >>"$OUT/table3.md"
fi
# ---- Tables 2 and 3 as the paper ran them: fig9.scn in paper mode ----
# The paper's types: 1 all clipping (X, Y, boxes), 2 Y and boxes, 3 boxes
# alone, 4 none; each traced on the board in paper mode (--paper: lines
# areas, asking when finished, the clipping lists, a fixed depth) with
# refraction off (the paper's Table 2 time, 82 s, is Table 3's
# non-refracting run), replayed on 16 NCs with simple dynamic balancing on
# scanline areas.  Type 4 is traced at SIZE2PLOW and replayed with --scale.
if [[ $PARTS == *" 2p "* || $PARTS == *" 3p "* ]]; then
echo "figures: Tables 2 and 3 as the paper ran them (fig9.scn, paper mode, $SIZE2P)"
W2=${SIZE2P%x*} H2=${SIZE2P#*x} WL=${SIZE2PLOW%x*} HL=${SIZE2PLOW#*x}
SCALE2P=$((W2 / WL))
[ $((WL * SCALE2P)) = "$W2" ] && [ $((HL * SCALE2P)) = "$H2" ] ||
    fail "Table 2 (paper): $SIZE2P is not $SIZE2PLOW times a whole number"
read -r K1 K2 <<<"$T2PK"
P2=(build/scenes/fig9.scn --paper --ncs 2 --count-insns)
# prow NAME TYPE SWITCHES: traces (once per K with clipping, once without),
# replays at both K into the table.
prow() {
    local name=$1 type=$2 sw=$3 size=$SIZE2P scale=1 ta tb
    [[ $sw == *--no-bbox* ]] && size=$SIZE2PLOW scale=$SCALE2P name="$name *"
    ta="$TMP/p2-$type-$K1.trace" tb="$TMP/p2-$type-$K2.trace"
    board "$TMP/bp2-$type-$K1.log" "${P2[@]}" --size "$size" $sw --areas "$K1" --trace "$ta" \
        -o "$TMP/p2.ppm"
    grep -q "paper mode: .*ask finished, clip lists" "$TMP/bp2-$type-$K1.log" ||
        fail "Table 2 (paper): $TMP/bp2-$type-$K1.log shows no paper mode"
    if [[ $sw == *--no-yclip*--no-xclip* ]]; then
        tb=$ta
    else
        board "$TMP/bp2-$type-$K2.log" "${P2[@]}" --size "$size" $sw --areas "$K2" --trace "$tb" \
            -o "$TMP/p2.ppm"
    fi
    "$LINKS1" replay "$ta" --scale $scale --ncs 16 --balance lines --areas "$K1" --ask finished \
        --pipelined >"$TMP/rp2a.txt" || fail "replay table 2 (paper)"
    "$LINKS1" replay "$tb" --scale $scale --ncs 16 --balance lines --areas "$K2" --ask finished \
        --pipelined >"$TMP/rp2b.txt" || fail "replay table 2 (paper)"
    local a b insns
    a=$(field frame_ms <"$TMP/rp2a.txt") b=$(field frame_ms <"$TMP/rp2b.txt")
    [ "$type" = 4 ] && p_none1=$a p_none2=$b
    insns=$(awk -v s=$scale '$1 == "area" { u += $11; t += $15 - $11 }
        END { printf "%.1f", (u + t * s * s) / 1e6 }' "$ta")
    echo "$type|$name|$insns|$a|$b" >>"$TMP/p2.rows"
}
: >"$TMP/p2.rows"
prow "none (type 4)" 4 "--refraction off --no-bbox --no-yclip --no-xclip"
prow "bounding boxes (type 3)" 3 "--refraction off --no-yclip --no-xclip"
prow "+ Y clipping (type 2)" 2 "--refraction off --no-xclip"
prow "+ X clipping: all (type 1)" 1 "--refraction off"
prims=$(sed -nE 's/.* ([0-9]+) primitives in ([0-9]+) clusters.*/\1 primitives, \2 clusters/p' \
    build/scenes/fig9.scn | head -1)
{
    echo "Table 2 as the paper ran it: build/scenes/fig9.scn ($prims, by hand) at $SIZE2P, paper mode"
    echo "(links1 render --paper: src/trc by angle, depth fixed at 5, no automatic hierarchy, the"
    echo "clipping lists, NCs asking once finished), refraction off, 16 NCs, simple dynamic"
    echo "balancing on scanline areas; frame s at 1 MIPS, the DM preparing during the previous frame."
    echo "Trace: links1 render build/scenes/fig9.scn --paper --ncs 2 --count-insns --refraction off SWITCHES"
    echo "--areas K --trace T (rows without clipping once, K = $K1); replay: links1 replay T --ncs 16"
    echo "--balance lines --areas K --ask finished --pipelined.  The row marked * was traced at"
    echo "$SIZE2PLOW and replayed with --scale $SCALE2P."
    echo
    echo "| clipping | NC instructions (M) | $K1 areas: frame s | vs none | $K2 areas: frame s | vs none |"
    echo "|---|---|---|---|---|---|"
    while IFS='|' read -r type name insns a b; do
        awk -v n="$name" -v a="$a" -v b="$b" -v na="$p_none1" -v nb="$p_none2" -v m="$insns" \
            'BEGIN { printf "| %s | %s | %.1f | %.1fx | %.1f | %.1fx |\n", n, m, a / 1000, na / a, b / 1000, nb / b }'
    done <"$TMP/p2.rows"
    echo
    echo "The paper (Table 2, s): type 1 82 and 86, type 2 111 and 200, type 3 340 and 340, type 4"
    echo "8499 and 8430 (2,400 and 480 areas)."
} >"$OUT/table2-paper.md"
# Table 3 on the same scene: type 1 at the first K, refracting against the
# non-refracting run of Table 2.
"$LINKS1" replay "$TMP/p2-1-$K1.trace" --ncs 16 --balance lines --areas "$K1" --ask finished \
    --pipelined >"$TMP/rp3off.txt" || fail "replay table 3 (paper)"
board "$TMP/bp3-on.log" "${P2[@]}" --size "$SIZE2P" --refraction on --areas "$K1" \
    --trace "$TMP/p3-on.trace" -o "$TMP/p3.ppm"
"$LINKS1" replay "$TMP/p3-on.trace" --ncs 16 --balance lines --areas "$K1" --ask finished \
    --pipelined >"$TMP/rp3on.txt" || fail "replay table 3 (paper)"
{
    echo "Table 3 as the paper ran it: the run of Table 2's type 1 ($K1 areas) against the same"
    echo "with refraction on (links1 render build/scenes/fig9.scn --paper --ncs 2 --count-insns --refraction"
    echo "on|off --areas $K1 --trace T; replay as Table 2)."
    echo
    echo "| transmission | frame s | NC instructions (M) | refracted rays |"
    echo "|---|---|---|---|"
    for mode in on off; do
        [ $mode = on ] && log="$TMP/bp3-on.log" r="$TMP/rp3on.txt" n="refracting"
        [ $mode = off ] && log="$TMP/bp2-1-$K1.log" r="$TMP/rp3off.txt" n="never bending (--refraction off)"
        awk -v n="$n" -v ms="$(field frame_ms <"$r")" -v t="$(nc_total "$log")" \
            -v rr="$(grep -o '[0-9]* refraction,' "$log" | grep -o '[0-9]*')" \
            'BEGIN { printf "| %s | %.1f | %.1f | %s |\n", n, ms / 1000, t / 1e6, rr }'
    done
    awk -v a="$(field frame_ms <"$TMP/rp3on.txt")" -v b="$(field frame_ms <"$TMP/rp3off.txt")" \
        'BEGIN { printf "\nRefracting takes %.2fx the time of never bending (the paper: 212 s against 82 s, 2.6x).\n", a / b }'
} >"$OUT/table3-paper.md"
fi

want="fig7.png fig10.png fig7.md fig10.md table2.md table3.md"
[[ $PARTS == *" 2p "* || $PARTS == *" 3p "* ]] && want="$want table2-paper.md table3-paper.md"
for f in $want; do
    [[ $PARTS == *" 7 "* ]] || [[ $f != fig7* ]] || continue
    [[ $PARTS == *" 10 "* ]] || [[ $f != fig10* ]] || continue
    [[ $PARTS == *" 2 "* ]] || [[ $f != table2.md ]] || continue
    [[ $PARTS == *" 3 "* ]] || [[ $f != table3.md ]] || continue
    [ -s "$OUT/$f" ] || fail "$OUT/$f was not written"
done
echo "figures: written to $OUT"
for f in fig7.md fig10.md table2.md table3.md table2-paper.md table3-paper.md; do
    [ -s "$OUT/$f" ] && cat "$OUT/$f"
done
exit 0
