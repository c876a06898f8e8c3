#!/usr/bin/env bash
# Two idle boots (report in, then shut down) with --count-insns, on 10 and on
# 66 cores: every core's guest instruction count must repeat within 1%, or
# within 256 instructions a core of the board (IDLE_EVENT_ALLOWANCE).  A
# core that waits by looping instead of sleeping (for a lock, at report-in,
# at shutdown) executes as many instructions as the wait lasts, which differs
# from run to run by hundreds of thousands a millisecond; a core asleep in
# WFI executes none.  A core asleep in WFE wakes once for each event another
# core sends while it waits, and how many of them fall in its wait depends
# on how the host schedules the vCPUs: core 0, which waits for 65 cores to
# report in, was once 9,338 instructions (2%) apart between two boots on a
# loaded host, which the allowance takes and a loop would not stay under.
. "$(dirname "$0")/../lib.sh"
sizes=(10 66)
IDLE_EVENT_ALLOWANCE=256 # instructions a core of the board: WFE wake-ups
names=()
for n in "${sizes[@]}"; do names+=("idle_insns$n"); done
board_ready "${names[@]}" || exit 0

# idle_counts N: one boot; prints "core count" per core, nothing if it failed.
idle_counts() {
    local out rc
    out=$(timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" boot --ncs "$(($1 - 2))" --quiet --count-insns 2>&1)
    rc=$?
    echo "--- $LINKS1 boot --ncs $(($1 - 2)) --quiet --count-insns (exit $rc)" >&2
    echo "$out" | sed 's/^/    /' >&2
    [ $rc -eq 0 ] || return 1
    echo "$out" | awk '$1 == "core" && $3 ~ /^(DM|RC|NC)$/ && $4 ~ /^[0-9]+$/ { print $2, $4 }'
}

for n in "${sizes[@]}"; do
    a=$(idle_counts "$n") || { echo "FAIL idle_insns$n: the first boot failed"; continue; }
    b=$(idle_counts "$n") || { echo "FAIL idle_insns$n: the second boot failed"; continue; }
    verdict=$(join <(echo "$a" | sort) <(echo "$b" | sort) | awk -v n="$n" -v per=$IDLE_EVENT_ALLOWANCE '
        { cores++
          hi = $2 > $3 ? $2 : $3; lo = $2 > $3 ? $3 : $2
          if ((hi - lo) * 100 > hi && hi - lo > n * per) { bad++; if (bad <= 4) why = why sprintf(" core %d: %d then %d;", $1, $2, $3) }
          d = hi ? (hi - lo) / hi : 0; if (d > worst) { worst = d; wc = $1 } }
        END {
          if (cores != n) printf "FAIL %d of %d cores counted in both boots", cores, n
          else if (bad) printf "FAIL %d core(s) differ by more than 1%% and %d instructions:%s", bad, n * per, why
          else printf "PASS largest difference %.3f%% (core %d)", worst * 100, wc }')
    echo "idle_insns$n: $verdict" >&2
    case $verdict in
    PASS*) echo "PASS idle_insns$n" ;;
    *) echo "FAIL idle_insns$n: ${verdict#FAIL }" ;;
    esac
done
