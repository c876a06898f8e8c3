#!/usr/bin/env bash
# bench_soak.sh: the long run of issue 12 without a system-down (a
# benchmark, not a test): an animation of SOAK_FRAMES (200) frames on
# SOAK_NCS (64) NCs in one links1 render run, one NC failing every 10
# frames (--inject-faults 1:SEED --inject-every 10, kinds mixed: undefined
# instruction, data abort, hang with interrupts off, silent stop).  Prints
# how many frames equal the host build's, the memory high-water marks at
# frames 1, 100 and 200, the NCs failed and areas re-issued, the link's
# repaired damage and the wall time, with --link-noise SOAK_NOISE (1e-4, each
# byte both ways; 0 for none) on the host link.  The animation is
# scenes/anim.scn stretched to SOAK_FRAMES frames.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
FRAMES=${SOAK_FRAMES:-200}
NCS=${SOAK_NCS:-64}
EVERY=${SOAK_EVERY:-10}
SIZE=${SOAK_SIZE:-96x72}
SEED=${SOAK_SEED:-1}
NOISE=${SOAK_NOISE:-1e-4}
LIMIT_S=${BENCH_RUN_LIMIT_S:-7200}
TMP=$(mktemp -d /tmp/links1-bench-soak.XXXXXX)
trap 'rm -rf "$TMP"' EXIT
last=$((FRAMES - 1))
sed -e "s/frames 4/frames $FRAMES/" -e "s/key 3 /key $last /" \
    -e "s/key 1 /key $((last / 3)) /" scenes/anim.scn >"$TMP/soak.scn"
cp -r scenes/maps "$TMP/maps"
"$LINKS1" ref "$TMP/soak.scn" -o "$TMP/ref.ppm" --arith float --size "$SIZE" \
    --frames "0:$last" >"$TMP/ref.log" 2>&1 || { echo "bench_soak: host reference failed"; exit 1; }
t0=$(date +%s)
timeout "$LIMIT_S" "$LINKS1" render "$TMP/soak.scn" -o "$TMP/board.ppm" --ncs "$NCS" \
    --size "$SIZE" --frames "0:$last" --inject-faults "1:$SEED" --inject-every "$EVERY" \
    --link-noise "$NOISE:$SEED" >"$TMP/board.log" 2>&1
rc=$?
t1=$(date +%s)
same=0
for ((f = 0; f < FRAMES; f++)); do
    n=$(printf '%04d' $f)
    cmp -s "$TMP/ref-$n.ppm" "$TMP/board-$n.ppm" && same=$((same + 1))
done
hw() { grep "^links1 render: frame $1 " "$TMP/board.log" | grep -o 'memory high-water.*'; }
failed=$(grep -o '[0-9]* NC(s) failed during the frame' "$TMP/board.log" | awk '{s += $1} END {print s + 0}')
reissued=$(grep -o '[0-9]* area(s) re-issued' "$TMP/board.log" | awk '{s += $1} END {print s + 0}')
watchdog=$(grep 'failed during the frame' "$TMP/board.log" | grep -o '(watchdog)' | wc -l)
echo "bench_soak: $FRAMES frames of $SIZE on $NCS NCs, one NC failing every $EVERY frames, link noise $NOISE (seed $SEED): links1 render exit $rc"
echo "bench_soak: frames equal to the host build: $same of $FRAMES"
echo "bench_soak: NCs failed: $failed ($watchdog by the watchdog); areas re-issued: $reissued"
echo "bench_soak: frame 1:   $(hw 0)"
echo "bench_soak: frame $((FRAMES / 2)): $(hw $((FRAMES / 2 - 1)))"
echo "bench_soak: frame $FRAMES: $(hw $last)"
echo "bench_soak: link: $(grep -o 'link errors: .*' "$TMP/board.log" | tail -1)"
grep 'the host link gave up' "$TMP/board.log" | sed 's/^/bench_soak: /'
echo "bench_soak: wall time $((t1 - t0)) s ($(awk -v s=$((t1 - t0)) -v n=$FRAMES 'BEGIN {printf "%.1f", s / n}') s per frame)"
[ $rc -eq 0 ] && [ $same -eq $FRAMES ]
