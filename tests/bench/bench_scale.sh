#!/usr/bin/env bash
# bench_scale.sh: cost per ray as scenes grow (issue 8), printed as the
# tables of docs/results/scenes-of-real-size.md.
#   1. one flat cluster of n random spheres, n = 100 .. 100,000: host ns per
#      ray (links1 ref --arith float, tracing time only) with the automatic
#      hierarchy on, and off up to 1,000 (it grows linearly beyond);
#   2. the SPD scenes (links1-spd) balls 1-4, tetra 1-6, mount 6 (a
#      mesh of 8,192 triangles) and the teapot at sizes 2 and 4 (248 and
#      1,024 triangles with the floor; before issue 23's SPD, 4,160 and
#      16,384): host ns/ray, board NC instructions per ray
#      (links1 render --count-insns, float, 8 NCs: all NCs' instructions over
#      the rays the host counts for the same image), and POV-Ray 3.7's trace
#      time on the same scene through links1 export-pov;
#   3. the hierarchy's build time against n (links1 compile, on minus off).
# Host figures are medians of BENCH_RUNS runs (default 3) of the tracing's
# CPU time (BENCH_CLOCK=wall: its wall-clock time).  Sizes:
# BENCH_SIZE (default 320x240) on the host and POV-Ray, BENCH_BOARD_SIZE
# (default 160x120) on the board.  BENCH_QUICK=1 skips the largest cases;
# BENCH_SCALE_PARTS (default "1 2 3") picks the tables, BENCH_SCALE_DBS the
# SPD scenes of the second.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SPD=${SPD:-build/links1-spd}
export FW_DIR=${FW_DIR:-build}
RUNS=${BENCH_RUNS:-3}
SIZE=${BENCH_SIZE:-320x240}
BSIZE=${BENCH_BOARD_SIZE:-160x120}
QUICK=${BENCH_QUICK:-0}
LIMIT_S=${BENCH_RUN_LIMIT_S:-1800}
PARTS=${BENCH_SCALE_PARTS:-1 2 3}
# host times: the tracing's CPU time (BENCH_CLOCK=cpu, default: other
# engineers' boards on the same 2 cores inflate it far less) or wall time
CLOCK_FIELD=2
[ "${BENCH_CLOCK:-cpu}" = wall ] && CLOCK_FIELD=1
part() { case " $PARTS " in *" $1 "*) return 0 ;; esac; return 1; }
make -s --no-print-directory build/links1 build/links1-ref-float build/links1-spd >&2
TMP=$(mktemp -d /tmp/links1-bench-scale.XXXXXX)
trap 'rm -rf "$TMP"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# spheres N OUT: N spheres in one cluster, a jittered sqrt(N) x sqrt(N)
# sheet seen from above at a slant: at every N the sheet fills the view and
# covers about the same part of it, so the rays are alike and only the
# search for the nearest hit grows with N
spheres() {
    awk -v n="$1" -v size="$SIZE" 'BEGIN {
        split(size, wh, "x"); srand(11)
        print "camera { eye 0 14 -13  look_at 0 0 0  up 0 1 0  fov 60 }"
        printf "resolution %d %d\nbackground 0.1 0.1 0.2\n", wh[1], wh[2]
        print "light point { colour 0.8 0.8 0.8  position 10 20 -15 }"
        print "material m { colour 0.9 0.5 0.3  dic 0.15 drc 0.75  src 0.2  phong 20 }"
        side = int(sqrt(n)); if (side * side < n) side++
        step = 24 / side; r = 0.45 * step
        for (i = 0; i < n; i++)
            printf "sphere { material m  centre %.5f %.5f %.5f  radius %.5f }\n",
                   (i % side + 0.5) * step - 12 + (rand() - 0.5) * 0.2 * step,
                   (rand() - 0.5) * step,
                   (int(i / side) + 0.5) * step - 12 + (rand() - 0.5) * 0.2 * step, r
    }' >"$2"
}

# host SCENE [ref args]: "ns_per_ray rays" (median tracing time)
host() {
    local scene=$1; shift
    local t rays log="$TMP/ref.log"
    for _ in $(seq "$RUNS"); do
        "$LINKS1" ref "$scene" -o "$TMP/ref.ppm" --arith float "$@" >"$log" 2>&1 ||
            { echo "bench_scale: links1 ref $scene failed: $(tail -n 1 "$log")" >&2; exit 1; }
        sed -n 's/.*traced in \([0-9.]*\) s (\([0-9.]*\) s CPU).*/\'"$CLOCK_FIELD"'/p' "$log"
    done | median >"$TMP/t"
    rays=$(sed -n 's/.*rays: \([0-9]*\) primary, \([0-9]*\) shadow, \([0-9]*\) reflection, \([0-9]*\) refraction, \([0-9]*\) transmission.*/\1 \2 \3 \4 \5/p' "$log" |
           awk '{ print $1 + $2 + $3 + $4 + $5 }')
    tests=$(sed -n 's/.* \([0-9]*\) box tests, \([0-9]*\) primitive tests.*/\1 \2/p' "$log")
    awk -v t="$(cat "$TMP/t")" -v r="$rays" -v bt="${tests% *}" -v pt="${tests#* }" \
        'BEGIN { printf "%.0f %d %.3f %.1f %.1f\n", t * 1e9 / r, r, t, bt / r, pt / r }'
}

# pov SCENE: POV-Ray's median trace time, seconds (its CPU-seconds, or with
# BENCH_CLOCK=wall the wall time it prints)
pov() {
    "$LINKS1" export-pov "$1" -o "$TMP/p.pov" >/dev/null 2>&1 || { echo "-"; return; }
    local w=${SIZE%x*} h=${SIZE#*x}
    for _ in $(seq "$RUNS"); do
        povray -D +I"$TMP/p.pov" +O"$TMP/p.png" +W"$w" +H"$h" -A +WT1 2>&1 |
            if [ "$CLOCK_FIELD" = 1 ]; then
                sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p'
            else
                grep -A1 'Trace Time:' | sed -n 's/.*with \([0-9.]*\) CPU-seconds.*/\1/p'
            fi
    done | median
}

# board SCENE: NC instructions per ray (float, 8 NCs) at BSIZE
board() {
    local log="$TMP/board.log" rays
    if ! timeout "$LIMIT_S" "$LINKS1" render --count-insns "$1" -o "$TMP/b.ppm" \
        --arith float --ncs 8 --size "$BSIZE" >"$log" 2>&1; then
        echo "-"
        return
    fi
    "$LINKS1" ref "$1" -o "$TMP/bref.ppm" --arith float --size "$BSIZE" >"$TMP/bref.log" 2>&1
    rays=$(sed -n 's/.*rays: \([0-9]*\) primary, \([0-9]*\) shadow, \([0-9]*\) reflection, \([0-9]*\) refraction, \([0-9]*\) transmission.*/\1 \2 \3 \4 \5/p' "$TMP/bref.log" |
           awk '{ print $1 + $2 + $3 + $4 + $5 }')
    local same=differs
    cmp -s "$TMP/b.ppm" "$TMP/bref.ppm" && same=same
    grep 'NCs total' "$log" | sed -E 's/.*NCs total ([0-9]+).*/\1/' |
        awk -v r="$rays" -v s="$same" '{ printf "%.0f (%s)\n", $1 / r, s }'
}

if part 1; then
echo "### Cost per ray, one flat cluster of n spheres (host float, $SIZE, median of $RUNS)"
echo
echo "| n | ns/ray, automatic hierarchy | box + primitive tests/ray | ns/ray, off | tests/ray, off | rays |"
echo "|---|---|---|---|---|---|"
ns="100 1000 10000 100000"
[ "$QUICK" = 1 ] && ns="100 1000 10000"
for n in $ns; do
    spheres "$n" "$TMP/s.scn"
    read -r on rays _ bt pt < <(host "$TMP/s.scn")
    off=- obt=- opt=-
    [ "$n" -le 1000 ] && read -r off _ _ obt opt < <(host "$TMP/s.scn" --no-auto-hierarchy)
    echo "| $n | $on | $bt + $pt | $off | $obt + $opt | $rays |"
done
echo
fi
if part 2; then
echo "### SPD scenes: host float ns/ray ($SIZE), board NC insns/ray ($BSIZE, 8 NCs), POV-Ray 3.7 (-A +WT1)"
echo
echo "| scene | objects | host ns/ray | box + primitive tests/ray | host trace s | POV-Ray trace s | links1 / POV-Ray | board NC insns/ray (image vs host) |"
echo "|---|---|---|---|---|---|---|---|"
dbs=${BENCH_SCALE_DBS:-"balls-1 balls-2 balls-3 balls-4 tetra-1 tetra-2 tetra-3 tetra-4 tetra-5 tetra-6 mount-6 teapot-2 teapot-4"}
for db in $dbs; do
    scene="$TMP/$db.scn" sized=()
    if ! "$SPD" "${db%-*}" "${db#*-}" -o "$scene" --size "$SIZE" 2>"$TMP/spd.log"; then
        # a text scene past its limit (teapot 60): the NFF, sized by the renderer
        scene="$TMP/$db.nff" sized=(--size "$SIZE")
        "$SPD" "${db%-*}" "${db#*-}" -o "$scene" 2>"$TMP/spd.log"
    fi
    # spheres, triangles and (when there are any) cones and cylinders
    objs=$(sed -n 's/.*: \([0-9]*\) spheres, \([0-9]*\) triangles\(, \([0-9]*\) cones.*\)\{0,1\}$/\1 + \2 + 0\4/p' \
        "$TMP/spd.log" | head -1 | bc)
    read -r ns _ t bt ptests < <(host "$scene" "${sized[@]}")
    pt=$(pov "$scene")
    ratio=$(awk -v a="$t" -v b="$pt" 'BEGIN { if (b + 0 > 0) printf "%.2f", a / b; else print "-" }')
    b=-
    if [ "$QUICK" != 1 ] || [ "$objs" -lt 5000 ]; then b=$(board "$scene"); fi
    echo "| $db | $objs | $ns | $bt + $ptests | $t | $pt | $ratio | $b |"
done
echo
fi
part 3 || exit 0
echo "### Build time of the automatic hierarchy (links1 compile, median of $RUNS, on minus off, ${BENCH_CLOCK:-cpu} time)"
echo
echo "| n spheres | compile s, on | compile s, off | build s |"
echo "|---|---|---|---|"
ns="1000 10000 100000"
[ "$QUICK" = 1 ] && ns="1000 10000"
for n in $ns; do
    spheres "$n" "$TMP/s.scn"
    { echo "options { auto_hierarchy off }"; cat "$TMP/s.scn"; } >"$TMP/s-off.scn"
    for v in s s-off; do
        for _ in $(seq "$RUNS"); do
            if [ "$CLOCK_FIELD" = 1 ]; then
                TIMEFORMAT=%R
            else
                TIMEFORMAT='%U %S' # user + system CPU seconds
            fi
            { time "$LINKS1" compile "$TMP/$v.scn" -o "$TMP/$v.l1s" >/dev/null 2>&1 ||
                echo "bench_scale: compile of $n spheres failed" >&2; } 2>&1 |
                awk '{ printf "%.3f\n", $1 + $2 }'
        done | median >"$TMP/$v.t"
    done
    awk -v n="$n" -v a="$(cat "$TMP/s.t")" -v b="$(cat "$TMP/s-off.t")" \
        'BEGIN { printf "| %d | %.3f | %.3f | %.3f |\n", n, a, b, a - b }'
done
