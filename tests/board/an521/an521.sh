#!/usr/bin/env bash
# The same firmware on an521 boards (dual Cortex-M33, one QEMU process per
# board, joined by one shared file): three boards boot and every unit
# computer reports in (the NC boards' through board 0's relay); lines and
# IMSU blocks work across the processes; demo.scn on 4 NCs equals the host
# build in float, soft and fixed; an NC board's QEMU killed in the middle
# of a frame still gives the exact frame; board 0 killed ends the command
# naming it; a scene too big for the machine, and an odd number of NCs,
# are refused with the limit named; double (software on the M33, whose FPU
# is single precision) equals the host's double build.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"

AN_FW=$FW_DIR/an521
an_ready() { # $@ = check names
    if [ ! -r "$AN_FW/links1-float.elf" ]; then
        for n in "$@"; do echo "FAIL $n: firmware $AN_FW/links1-float.elf is not built (run make)"; done
        return 1
    fi
    board_ready "$@"
}

# an_boards PID: "BOARD QEMU-PID" for each an521 board's QEMU below PID (by
# its loader word), from one snapshot of the process table: this test's
# own boards, whatever else runs beside it.
an_boards() {
    ps -eo pid=,ppid=,args= | awk -v top="$1" '
        { pid[NR] = $1; parent[$1] = $2; line[$1] = $0 }
        END {
            for (i = 1; i <= NR; i++) {
                p = pid[i]
                if (!match(line[p], /loader,addr=0x103ffff0,data=[0-9]+,data-len=4/)) continue
                for (q = parent[p]; q != "" && q != top && q > 1; q = parent[q]) ;
                if (q != top) continue
                w = substr(line[p], RSTART, RLENGTH)
                sub(/.*data=/, "", w); sub(/,.*/, "", w)
                print w, p
            }
        }'
}

# How many of the pids given are still an an521 board's QEMU.
an_alive() {
    local pid n=0
    for pid in "$@"; do
        tr '\0' ' ' 2>/dev/null <"/proc/$pid/cmdline" | grep -q "loader,addr=0x103ffff0" &&
            n=$((n + 1))
    done
    echo "$n"
}

# an_render_kill B LOG OUT: renders demo.scn 320x240 on 4 NCs into OUT,
# its output into LOG, and kills board B's QEMU (SIGKILL) 0.3 s after the
# scene is loaded.  The tool's lines are read as they come (stdbuf: a line
# at a time), so the kill follows the load, not the tool's exit.  Sets
# victim (the pid killed, empty when there was none), boards (the pids of
# the run's board QEMUs before the kill) and rc (the tool's).
an_render_kill() {
    local board=$1 log=$2 out=$3 tool
    timeout "$BOARD_RUN_LIMIT_S" stdbuf -oL "$LINKS1" render scenes/demo.scn -o "$out" \
        --machine an521 --ncs 4 --size 320x240 >"$log" 2>&1 &
    tool=$!
    for _ in $(seq 1 300); do
        grep -q ' loaded: ' "$log" 2>/dev/null && break
        sleep 0.1
    done
    sleep 0.3
    local table
    table=$(an_boards "$tool")
    victim=$(awk -v b="$board" '$1 == b { print $2; exit }' <<<"$table")
    [ -n "$victim" ] && kill -KILL "$victim"
    mapfile -t boards < <(awk '{ print $2 }' <<<"$table")
    wait "$tool"
    rc=$?
    sed 's/^/    /' "$log"
}

# Three boards (DM and RC; NCs 2, 3; NCs 4, 5) report in.
if an_ready an521_boot; then
    log=$RENDER_TMP/boot.log
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" boot --machine an521 --ncs 4 --verbose >"$log" 2>&1
    rc=$?
    sed 's/^/    /' "$log"
    want="core 0 DM|core 1 RC|core 2 NC|core 3 NC|core 4 NC|core 5 NC"
    got=$(grep -oE 'core [0-9]+ (DM|RC|NC) reported in' "$log" | sed 's/ reported in//' | sort -t' ' -k2n | paste -sd'|')
    if [ $rc -eq 0 ] && [ "$got" = "$want" ] && grep -q 'board up: 6 unit computers' "$log"; then
        echo "PASS an521_boot"
    else
        echo "FAIL an521_boot: exit $rc, reported '$got' (want '$want')"
    fi
fi

# Lines and IMSU across the boards' processes, on the board as QEMU models
# it (no FPU on core 0: the soft firmware).
if an_ready an521_selftest_boot; then
    board_selftest an521_selftest --machine an521 --ncs 4 --arith soft status ping imsu
fi

# demo.scn on 4 NCs (3 boards) = the host build of the same arithmetic;
# in float the instructions are counted too: every board's counts merged
# under the machine's core numbers, each core's non-zero; in fixed board 0's
# link is noisy (--link-noise 1e-3, seed 3: go-back-N repairs it).
for arith in float soft fixed; do
    name=an521_demo_$arith
    an_ready "$name" || continue
    out=$RENDER_TMP/$name.ppm
    ref=$(render_ref scenes/demo.scn "$arith" 64x48)
    count=()
    [ "$arith" = float ] && count=(--count-insns)
    [ "$arith" = fixed ] && count=(--link-noise 1e-3:3)
    render_board "$name" "$out" scenes/demo.scn -o "$out" --machine an521 --ncs 4 \
        --arith "$arith" --size 64x48 "${count[@]}" || continue
    render_same "$name" "$ref" "$out"
    if [ "$arith" = float ]; then
        cores=$(grep -cE '^  core +[0-5] (DM|RC|NC) +[1-9][0-9]*$' "$RENDER_TMP/$name.log")
        if [ "$cores" -eq 6 ]; then
            echo "PASS an521_counts_merged"
        else
            echo "FAIL an521_counts_merged: $cores of 6 cores with a count: $(grep -A7 'guest instructions per core' "$RENDER_TMP/$name.log" | paste -sd' ')"
        fi
    fi
done

# An NC board's QEMU killed (SIGKILL) in the middle of a frame: the RC's
# watchdog gives its areas to the NCs left, and the frame is exact.
name=an521_nc_board_killed
if an_ready "$name"; then
    out=$RENDER_TMP/$name.ppm log=$RENDER_TMP/$name.log
    ref=$(render_ref scenes/demo.scn float 320x240)
    an_render_kill 1 "$log" "$out"
    if [ -z "$victim" ]; then
        echo "FAIL $name: no QEMU of board 1 to kill"
    elif [ $rc -ne 0 ]; then
        echo "FAIL $name: links1 render exited $rc: $(grep links1 "$log" | tail -n 1)"
    elif ! grep -q 'NC(s) failed during the frame: NC 2 (watchdog), NC 3 (watchdog)' "$log"; then
        echo "FAIL $name: the frame does not name NCs 2 and 3 failed (killed too late?)"
    else
        render_same "$name" "$ref" "$out"
    fi
fi

# Board 0 (the link's board) killed: the command ends naming it, and no
# board's QEMU is left running.
name=an521_board0_killed
if an_ready "$name"; then
    out=$RENDER_TMP/$name.ppm log=$RENDER_TMP/$name.log
    an_render_kill 0 "$log" "$out"
    left=$(an_alive "${boards[@]}")
    if [ -z "$victim" ]; then
        echo "FAIL $name: no QEMU of board 0 to kill"
    elif [ $rc -eq 0 ] || ! grep -q 'an521 board 0 (the DM and the RC): QEMU was killed by signal 9' "$log"; then
        echo "FAIL $name: exit $rc, and board 0 not named: $(grep links1 "$log" | tail -n 2 | paste -sd' ')"
    elif [ "$left" -ne 0 ]; then
        echo "FAIL $name: $left board QEMU(s) left running"
    else
        echo "PASS $name"
    fi
fi

# Refused before any board starts: a scene whose prepared frame does not fit
# the an521 IMSU block (SPD tetra 7: 16,384 triangles), and 3 NCs.
name=an521_refuse_scene
if an_ready "$name"; then
    scn=$RENDER_TMP/tetra7.scn
    build/links1-spd tetra 7 -o "$scn" >/dev/null 2>&1
    msg=$("$LINKS1" render "$scn" -o "$RENDER_TMP/t7.ppm" --machine an521 --ncs 2 --size 32x24 2>&1)
    rc=$?
    echo "    $msg"
    if [ $rc -ne 0 ] && echo "$msg" | grep -qE 'more than the [0-9]+ bytes of AN521_IMSU_BLOCK_BYTES on the an521 machine' &&
        ! echo "$msg" | grep -q 'booting'; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc: $msg"
    fi
fi
name=an521_refuse_odd_ncs
if an_ready "$name"; then
    msg=$("$LINKS1" render scenes/demo.scn -o "$RENDER_TMP/odd.ppm" --machine an521 --ncs 3 --size 32x24 2>&1)
    rc=$?
    echo "    $msg"
    if [ $rc -ne 0 ] && echo "$msg" | grep -q '3 NCs on an521 boards: each NC board carries 2 NCs, so give an even number from 2 to 64'; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc: $msg"
    fi
fi
# double: the M33's FPU is single precision, so the double firmware's
# arithmetic is libgcc's software double, correctly rounded as the host's
name=an521_double_is_host
if an_ready "$name"; then
    ref=$RENDER_TMP/an521-dbl-host.ppm out=$RENDER_TMP/an521-dbl.ppm
    "$LINKS1" ref scenes/demo.scn --arith double --size 64x48 -o "$ref" >"$ref.log" 2>&1
    render_board $name "$out" scenes/demo.scn -o "$out" --machine an521 --ncs 2 --arith double \
        --size 64x48 && render_same $name "$ref" "$out"
fi
