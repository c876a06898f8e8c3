#!/usr/bin/env bash
# tests/bench/bench_farm.sh: what `links1 farm` costs and what H hosts would
# take (docs/farm.md).  Wall time on this machine, so a benchmark, never a
# test: run it with nothing else running.
#
#   1. plain:  links1 render SCENE --frames A:B (one board, the DM preparing
#              each next frame while the current one renders)
#   2. farm, one host (':'):             a job a frame
#   3. farm, two hosts (':' and a throw-away sshd on 127.0.0.1,
#      tests/board/farm/farm_sshd.sh; needs root)
#
# From 1 and 2: the farm's own cost a frame (c = (T1 - Tplain) / F) and its
# share of a plain frame.  The model of H equal, independent hosts:
#   T(H) = s + ceil(F / H) * t1
# with t1 the farmed frame's job time on one host and s the farm's start
# (parallel's, T1 - F * t1).  Checked on this machine with two hosts, which
# share its cores: the model then also bounds the wall by the CPU the jobs
# need, F * cpu1 / cores (cpu1 the CPU seconds of a farmed frame, from run
# 2's user + system time), and the larger of the two is the prediction.
#
#   BENCH_SCENE (scenes/fly.scn) BENCH_FRAMES (0:11) BENCH_SIZE (320x240)
#   BENCH_NCS (8)
set -u
cd "$(dirname "$0")/../.."
. tests/board/farm/farm_sshd.sh
LINKS1=${LINKS1:-build/links1}
scene=${BENCH_SCENE:-scenes/fly.scn} frames=${BENCH_FRAMES:-0:11} size=${BENCH_SIZE:-320x240}
ncs=${BENCH_NCS:-8}
first=${frames%%:*} last=${frames##*:}
F=$((last - first + 1))
cores=$(nproc)
T=$(mktemp -d /tmp/links1-bench-farm.XXXXXX)
trap 'farm_sshd_stop; rm -rf "$T"' EXIT
fail() { echo "bench_farm: $*" >&2; exit 1; }
# timed LOG CMD...: runs CMD, appends "wall user sys" (s) of it and its children to LOG.times
timed() {
    local log=$1; shift
    /usr/bin/time -f '%e %U %S' -o "$log.times" "$@" >"$log" 2>&1
}
field() { awk -v i="$2" '{ print $i }' "$1.times"; }
echo "bench_farm: $scene frames $first..$last ($F), $size, $ncs NCs, $cores host cores, $(date -u +%FT%TZ)"

mkdir -p "$T/plain"
timed "$T/plain.log" "$LINKS1" render "$scene" --frames "$frames" --size "$size" --ncs "$ncs" \
    -o "$T/plain/f.png" || fail "plain render: $(tail -n 2 "$T/plain.log")"
echo : >"$T/hosts1"
timed "$T/one.log" "$LINKS1" farm "$scene" --frames "$frames" -o "$T/one" --hosts "$T/hosts1" -- \
    --size "$size" --ncs "$ncs" || fail "farm on one host: $(tail -n 2 "$T/one.log")"
for ((f = first; f <= last; f++)); do
    cmp -s "$(printf '%s/plain/f-%04d.png' "$T" $f)" "$(printf '%s/one/frame-%04d.png' "$T" $f)" ||
        fail "frame $f farmed on one host is not the plain render's"
done
two=1
why=$(farm_sshd_why)
if [ -n "$why" ]; then
    echo "bench_farm: no two-host run: $why"
    two=0
elif ! farm_sshd_start "$T/ssh" >"$T/sshd.log" 2>&1; then
    echo "bench_farm: no two-host run: $(tail -n 1 "$T/sshd.log")"
    two=0
fi
if [ $two = 1 ]; then
    # what a job on the ssh host costs beyond its work: parallel's remote
    # wrapper, the login, --return's rsync and --cleanup, for an empty job
    echo fakehost >"$T/hostsf"
    mkdir -p "$T/empty"
    (cd "$T/empty" && /usr/bin/time -f '%e' -o "$T/empty.times" parallel --will-cite \
        --sshloginfile "$T/hostsf" -j1 --return 'e-{}' --cleanup --joblog "$T/empty.tsv" \
        'exec touch e-{}' ::: 1 2 3 4 5 6) >/dev/null 2>&1 || fail "an empty job on the ssh host failed"
    c_ssh=$(tail -n +2 "$T/empty.tsv" | awk -F'\t' '{ s += $4; n++ } END { print s / n }')
    printf ':\nfakehost\n' >"$T/hosts2"
    timed "$T/two.log" "$LINKS1" farm "$scene" --frames "$frames" -o "$T/two" --hosts "$T/hosts2" -- \
        --size "$size" --ncs "$ncs" || fail "farm on two hosts: $(tail -n 2 "$T/two.log")"
fi

Tp=$(field "$T/plain.log" 1) T1=$(field "$T/one.log" 1)
cpu1=$(awk -v u="$(field "$T/one.log" 2)" -v s="$(field "$T/one.log" 3)" -v f=$F 'BEGIN { print (u + s) / f }')
# t1: the mean job time of a farmed frame on one host (parallel's joblog, JobRuntime)
t1=$(tail -n +2 "$T/one/farm-joblog.tsv" | awk -F'\t' '{ s += $4; n++ } END { print s / n }')
s0=$(awk -v T="$T1" -v t="$t1" -v f=$F 'BEGIN { x = T - f * t; print (x > 0 ? x : 0) }')
awk -v Tp="$Tp" -v T1="$T1" -v f=$F -v t1="$t1" -v s0="$s0" -v cpu1="$cpu1" 'BEGIN {
    printf "plain render: %.2f s wall, %.3f s a frame\n", Tp, Tp / f
    printf "farm, one host: %.2f s wall, %.3f s a frame; the farm'"'"'s own cost %.3f s a frame, %.1f%% of a plain frame\n", T1, T1 / f, (T1 - Tp) / f, 100 * (T1 - Tp) / Tp
    printf "model: a farmed frame'"'"'s job %.3f s (t1), the farm'"'"'s start %.2f s (s), CPU %.3f s a frame (cpu1)\n", t1, s0, cpu1
    printf "model, H equal independent hosts: T(H) = s + ceil(F/H) * t1:"
    for (h = 1; h <= 16; h *= 2) printf " H=%d %.1f s;", h, s0 + int((f + h - 1) / h) * t1
    printf "\n"
}'
if [ $two = 1 ]; then
    T2=$(field "$T/two.log" 1)
    tail -n +2 "$T/two/farm-joblog.tsv" | awk -F'\t' '{ n[$2]++; s[$2] += $4 }
        END { for (h in n) printf "farm, two hosts: host %s: %d frame(s), %.3f s a job\n", h, n[h], s[h] / n[h] }'
    awk -v T2="$T2" -v T1="$T1" -v f=$F -v t1="$t1" -v s0="$s0" -v cpu1="$cpu1" -v c=$cores \
        -v cs="$c_ssh" 'BEGIN {
        # this host at 1/t1 frames a second, the ssh host at 1/(t1 + cs)
        indep = s0 + f / (1 / t1 + 1 / (t1 + cs))
        cpu = s0 + f * cpu1 / c
        pred = indep > cpu ? indep : cpu
        printf "an empty job on the ssh host: %.3f s (its login, wrapper, rsync back and cleanup)\n", cs
        printf "farm, two hosts on this machine: %.2f s wall (one host %.2f s); predicted %.2f s (hosts at their own pace %.2f s, bound by its %d cores %.2f s): measured / predicted %.2f\n", T2, T1, pred, indep, c, cpu, T2 / pred
    }'
fi
