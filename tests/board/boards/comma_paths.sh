#!/usr/bin/env bash
# Paths with commas, on a real board: QEMU's option syntax ends a value at
# a ',' and takes ",," for a comma of the value, and the launcher doubles
# every comma of a path it puts into an option (qemu_opt_escape).  With the
# boards' state in a directory named b,c: board start, list, render --board
# and stop work; --gdb's stub listens on gdb.sock there and gdb attaches;
# --insn-profile "prof.txt,profile_from=0" writes a file of that very name
# (no second plugin option, no prof.txt).
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
checks=(comma_board_named comma_gdb comma_insn_profile)
board_ready "${checks[@]}" || exit 0
export LINKS1_BOARDS="$RENDER_TMP/b,c"
trap 'for f in "$LINKS1_BOARDS"/*/board; do [ -e "$f" ] && kill -9 "$(awk "/^pid/ {print \$2}" "$f")" 2>/dev/null; done; rm -rf "$RENDER_TMP"' EXIT
ref=$(render_ref scenes/demo.scn float 32x24)

# ---- a named board in b,c
if render_run start board start --name n --ncs 1 --quiet && render_run list board list &&
    grep -q '^board n: running' "$RENDER_TMP/list.log" &&
    render_run render render --board n --quiet scenes/demo.scn --size 32x24 -o "$RENDER_TMP/n.ppm" &&
    cmp -s "$ref" "$RENDER_TMP/n.ppm" && render_run stop board stop n &&
    grep -q 'board n stopped' "$RENDER_TMP/stop.log" && [ ! -e "$LINKS1_BOARDS/n" ]; then
    echo "PASS comma_board_named"
else
    echo "FAIL comma_board_named: with \$LINKS1_BOARDS=$LINKS1_BOARDS, board start, list, render --board (equal to the host build) or stop failed"
fi

# ---- --gdb: the stub's socket in b,c, gdb attaches and the board comes up
sock="$LINKS1_BOARDS/g/gdb.sock"
"$LINKS1" board start --name g --ncs 1 --gdb --timeout 60 >"$RENDER_TMP/gstart.log" 2>&1 &
starter=$!
for _ in $(seq 100); do [ -S "$sock" ] && break; sleep 0.1; done
if command -v gdb-multiarch >/dev/null; then
    timeout 60 gdb-multiarch -q -batch -ex "target remote $sock" -ex "info threads" \
        -ex detach >"$RENDER_TMP/gdb.log" 2>&1
fi
wait $starter
rc=$?
sed 's/^/    /' "$RENDER_TMP/gstart.log" "$RENDER_TMP/gdb.log" 2>/dev/null
if [ $rc -eq 0 ] && grep -q 'Thread 1.3' "$RENDER_TMP/gdb.log"; then
    echo "PASS comma_gdb"
else
    echo "FAIL comma_gdb: board start --gdb in $LINKS1_BOARDS exited $rc, or gdb-multiarch did not attach through $sock"
fi
render_run gstop board stop g

# ---- --insn-profile FILE with a comma: that file, and no other
prof="$RENDER_TMP/prof.txt,profile_from=0"
if render_run prof render scenes/demo.scn --quiet --ncs 1 --size 32x24 -o "$RENDER_TMP/p.ppm" \
    --insn-profile "$prof" && [ -s "$prof" ] && [ ! -e "$RENDER_TMP/prof.txt" ]; then
    echo "PASS comma_insn_profile"
else
    echo "FAIL comma_insn_profile: render failed, or it did not write $prof (or wrote $RENDER_TMP/prof.txt: the comma split the plugin's argument)"
fi
