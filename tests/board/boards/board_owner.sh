#!/usr/bin/env bash
# What only the user may reach, on a real board: QEMU's gdb stub (--gdb) is
# a unix socket in the board's state directory, never a TCP port, and gdb
# attaches to it; the old form `--gdb PORT` is refused with a clear error;
# a named board that dies during `render --board` gives a message naming
# it, exit status 1 and no temporary file left; `render -o OUT` does not
# write through a link planted at a predictable temporary name, and leaves
# nothing behind when it cannot write OUT.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
checks=(board_owner_gdb_unix_socket board_owner_gdb_attach board_owner_gdb_port_refused
    board_owner_dead_board board_owner_out_link board_owner_out_error)
board_ready "${checks[@]}" || exit 0
export LINKS1_BOARDS="$RENDER_TMP/boards"
trap 'for f in "$LINKS1_BOARDS"/*/board; do [ -e "$f" ] && kill -9 "$(awk "/^pid/ {print \$2}" "$f")" 2>/dev/null; done; rm -rf "$RENDER_TMP"' EXIT

# ---- the gdb stub: a unix socket in the board's directory
sock="$LINKS1_BOARDS/g/gdb.sock"
"$LINKS1" board start --name g --ncs 1 --gdb --timeout 60 >"$RENDER_TMP/gstart.log" 2>&1 &
starter=$!
for _ in $(seq 100); do [ -S "$sock" ] && break; sleep 0.1; done
pid=$(render_board_pid g)
cmdline=$(tr '\0' ' ' <"/proc/${pid:-0}/cmdline" 2>/dev/null)
echo "--- QEMU: $cmdline"
if [ -S "$sock" ] && [[ $cmdline == *"-gdb unix:$sock,server=on,wait=off"* ]] &&
    [[ $cmdline != *tcp:* ]] && grep -q "gdb stub on $sock" "$RENDER_TMP/gstart.log"; then
    echo "PASS board_owner_gdb_unix_socket"
else
    echo "FAIL board_owner_gdb_unix_socket: no gdb socket $sock, or QEMU's -gdb is not that unix socket (or a tcp: port), or board start did not name it"
fi
# gdb attaches, reads the cores, and detaching lets them run: the board comes up.
if command -v gdb-multiarch >/dev/null; then
    timeout 60 gdb-multiarch -q -batch -ex "target remote $sock" -ex "info threads" \
        -ex detach >"$RENDER_TMP/gdb.log" 2>&1
fi
wait $starter
rc=$?
sed 's/^/    /' "$RENDER_TMP/gstart.log" "$RENDER_TMP/gdb.log" 2>/dev/null
if [ $rc -eq 0 ] && grep -q 'Thread 1.3' "$RENDER_TMP/gdb.log" &&
    render_run grender render --board g --quiet scenes/demo.scn --size 32x24 -o "$RENDER_TMP/g.ppm"; then
    echo "PASS board_owner_gdb_attach"
else
    echo "FAIL board_owner_gdb_attach: gdb-multiarch did not attach through $sock (3 threads), or the board did not come up after it detached (start exit $rc)"
fi
render_run gstop board stop g
if ! render_run gport board start --name g2 --ncs 1 --gdb 1234 --timeout 2 &&
    grep -q -- '--gdb takes no port' "$RENDER_TMP/gport.log" &&
    ! render_run gport2 board start --name g2 --ncs 1 --gdb=1234 --timeout 2 &&
    grep -q -- '--gdb takes no port' "$RENDER_TMP/gport2.log"; then
    echo "PASS board_owner_gdb_port_refused"
else
    echo "FAIL board_owner_gdb_port_refused: --gdb 1234 / --gdb=1234 were not refused with '--gdb takes no port'"
fi
render_run gport3 board stop g2

# ---- a board that dies during render --board
render_run dstart board start --name d --ncs 1 --quiet
pid=$(render_board_pid d)
mkdir -p "$RENDER_TMP/dout"
"$LINKS1" render --board d --quiet scenes/demo.scn --size 320x240 -o "$RENDER_TMP/dout/d.png" \
    >"$RENDER_TMP/drender.log" 2>&1 &
victim=$!
sleep 1.5
[ -n "$pid" ] && kill -9 "$pid"
wait $victim
rc=$?
echo "--- render --board d, its QEMU killed (exit $rc)"; sed 's/^/    /' "$RENDER_TMP/drender.log"
left=$(ls -A "$RENDER_TMP/dout")
if [ $rc -eq 1 ] && grep -q 'board d' "$RENDER_TMP/drender.log" && [ -z "$left" ]; then
    echo "PASS board_owner_dead_board"
else
    echo "FAIL board_owner_dead_board: exit $rc (want 1), no message naming board d, or left: $left"
fi
render_run dlist board list

# ---- render -o OUT: no write through a planted link, nothing left on error
render_run ostart board start --name o --ncs 1 --quiet
mkdir -p "$RENDER_TMP/out"
echo "the victim's" >"$RENDER_TMP/victim.txt"
ln -s "$RENDER_TMP/victim.txt" "$RENDER_TMP/out/o.ppm.part"
render_run orender render --board o --quiet scenes/demo.scn --size 32x24 -o "$RENDER_TMP/out/o.ppm"
ref=$(render_ref scenes/demo.scn float 32x24)
if [ "$(cat "$RENDER_TMP/victim.txt")" = "the victim's" ] && cmp -s "$ref" "$RENDER_TMP/out/o.ppm"; then
    echo "PASS board_owner_out_link"
else
    echo "FAIL board_owner_out_link: the planted link's target was written, or OUT differs from the host build"
fi
rm -f "$RENDER_TMP/out/o.ppm.part"
mkdir -p "$RENDER_TMP/out/isdir.ppm"
render_run oerror render --board o --quiet scenes/demo.scn --size 32x24 -o "$RENDER_TMP/out/isdir.ppm"
rc=$?
left=$(ls -A "$RENDER_TMP/out" | grep -v '^o.ppm$' | grep -v '^isdir.ppm$')
if [ $rc -ne 0 ] && [ -z "$left" ] && [ -z "$(ls -A "$RENDER_TMP/out/isdir.ppm")" ]; then
    echo "PASS board_owner_out_error"
else
    echo "FAIL board_owner_out_error: exit $rc, or left behind: $left"
fi
render_run ostop board stop o
