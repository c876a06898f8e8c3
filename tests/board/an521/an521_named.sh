#!/usr/bin/env bash
# Named an521 boards (links1 board start --machine an521, render --board,
# board list/status/stop): a set of three QEMUs (board 0: DM and RC, two NC
# boards) started once renders equal to the host build with no --machine
# given; list shows the set and each NC board; an NC board's QEMU killed
# shows as gone in status, and the next render is still equal (the RC's
# watchdog gives its areas to the others); stop ends every QEMU of the set
# and removes its state; a set whose board 0 died is reported and removed
# by list, its NC boards stopped with it.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
checks=(an521_named_start an521_named_render an521_named_list an521_named_nc_gone
    an521_named_render_nc_gone an521_named_stop an521_named_stale)
if [ ! -r "$FW_DIR/an521/links1-float.elf" ]; then
    for n in "${checks[@]}"; do echo "FAIL $n: firmware $FW_DIR/an521/links1-float.elf is not built (run make)"; done
    exit 0
fi
board_ready "${checks[@]}" || exit 0
export LINKS1_BOARDS="$RENDER_TMP/boards"
# Every QEMU a record names (board 0's and the NC boards').
set_pids() { # NAME
    awk '/^pid/ {print $2} /^nc_pids/ {for (i = 2; i <= NF; i++) print $i}' \
        "$LINKS1_BOARDS/$1/board" 2>/dev/null
}
# Whatever happens, no QEMU of this test outlives it.
trap 'for d in "$LINKS1_BOARDS"/*/; do [ -e "$d/board" ] && kill -9 $(set_pids "$(basename "$d")") 2>/dev/null; done; rm -rf "$RENDER_TMP"' EXIT
# A QEMU that has exited may linger as a zombie: alive means it still has a
# command line.
qemu_alive() { tr '\0' ' ' <"/proc/$1/cmdline" 2>/dev/null | grep -q qemu; }
wait_gone() { # PID
    for ((i = 0; i < 200; i++)); do
        qemu_alive "$1" || return 0
        sleep 0.05
    done
    return 1
}
SIZE=64x48
scene=scenes/demo.scn
ref=$(render_ref $scene float $SIZE)

render_run start board start --machine an521 --ncs 4 --name s1 --quiet
pids=($(set_pids s1))
alive=0
for p in "${pids[@]}"; do qemu_alive "$p" && alive=$((alive + 1)); done
if [ ${#pids[@]} -eq 3 ] && [ $alive -eq 3 ]; then
    echo "PASS an521_named_start"
else
    echo "FAIL an521_named_start: the record of s1 names ${#pids[@]} QEMUs (want 3: board 0 and two NC boards), $alive of them running"
fi
render_run render1 render --board s1 --quiet $scene --size $SIZE -o "$RENDER_TMP/r1.ppm"
render_same an521_named_render "$ref" "$RENDER_TMP/r1.ppm"

render_run list1 board list
if grep -q '^board s1: running, an521, 3 boards (board 0: DM and RC, QEMU pid '"${pids[0]:-x}"';.* 2 of 2 NC boards running' "$RENDER_TMP/list1.log" &&
    grep -q "^board s1: NC board 1 (NCs 2, 3): running, QEMU pid ${pids[1]:-x}\$" "$RENDER_TMP/list1.log" &&
    grep -q "^board s1: NC board 2 (NCs 4, 5): running, QEMU pid ${pids[2]:-x}\$" "$RENDER_TMP/list1.log"; then
    echo "PASS an521_named_list"
else
    echo "FAIL an521_named_list: board list does not show s1 as an an521 set with both NC boards running"
fi

# NC board 2's QEMU killed: status shows it gone, the set still runs.
[ -n "${pids[2]:-}" ] && kill -9 "${pids[2]}"
wait_gone "${pids[2]:-0}"
render_run status1 board status s1
if grep -q "^board s1: NC board 2 (NCs 4, 5): its QEMU (pid ${pids[2]:-x}) is gone\$" "$RENDER_TMP/status1.log" &&
    grep -q '^board s1: running, an521, .* 1 of 2 NC boards running' "$RENDER_TMP/status1.log"; then
    echo "PASS an521_named_nc_gone"
else
    echo "FAIL an521_named_nc_gone: board status does not show NC board 2 (pid ${pids[2]:-?}) gone and 1 of 2 running"
fi
render_run render2 render --board s1 $scene --size $SIZE -o "$RENDER_TMP/r2.ppm"
if grep -q 'NC 4 (watchdog), NC 5 (watchdog)' "$RENDER_TMP/render2.log"; then
    render_same an521_named_render_nc_gone "$ref" "$RENDER_TMP/r2.ppm"
else
    echo "FAIL an521_named_render_nc_gone: the render does not say the RC's watchdog found NCs 4 and 5 gone"
fi

render_run stop board stop s1
left=0
for p in "${pids[@]}"; do wait_gone "$p" || left=$((left + 1)); done
if grep -q 'board s1 stopped' "$RENDER_TMP/stop.log" && [ $left -eq 0 ] &&
    [ ${#pids[@]} -eq 3 ] && [ ! -e "$LINKS1_BOARDS/s1" ]; then
    echo "PASS an521_named_stop"
else
    echo "FAIL an521_named_stop: board stop s1 left $left QEMU(s) of the set running, or its state"
fi

# A set whose board 0 died: list reports it, stops its NC board, removes it.
render_run start2 board start --machine an521 --ncs 2 --name s2 --quiet
pids=($(set_pids s2))
[ -n "${pids[0]:-}" ] && kill -9 "${pids[0]}"
wait_gone "${pids[0]:-0}"
render_run list2 board list
if [ ${#pids[@]} -eq 2 ] &&
    grep -q "board s2: its board 0's QEMU (pid ${pids[0]}, the DM and the RC) is gone" "$RENDER_TMP/list2.log" &&
    wait_gone "${pids[1]}" && [ ! -e "$LINKS1_BOARDS/s2" ]; then
    echo "PASS an521_named_stale"
else
    echo "FAIL an521_named_stale: the set s2 whose board 0 (pid ${pids[0]:-?}) died was not reported, its NC board (pid ${pids[1]:-?}) stopped and its state removed"
fi
