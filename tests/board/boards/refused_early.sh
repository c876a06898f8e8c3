#!/usr/bin/env bash
# tests/board/boards/refused_early.sh (host: no board boots): bad options are
# refused before any QEMU starts, a bad scene before the board started beside
# its compile reports in, and paths with commas reach QEMU whole.  $QEMU is
# a fake that writes its arguments to a file, prints a line to its output
# and fails, so every check also sees whether a QEMU was started at all.
#   - --size 4294967360x48 (2^32 + 64: a number past an int) is refused,
#     not wrapped to 64x48;
#   - --ram 64 (less than the 1024 MiB the firmware lays out) is refused
#     with a message naming the least it takes;
#   - -o in a directory that does not exist is refused at once by render,
#     ref, compile and import;
#   - a state directory with a comma ($LINKS1_BOARDS=.../b,c): the board's
#     UART chardev names its socket with the comma doubled (QEMU's option
#     syntax), and --insn-profile "prof.txt,profile_from=0" adds no plugin
#     option (the plugin writes into the run's private directory);
#   - a board start whose QEMU fails prints the end of QEMU's output and
#     points at no log it removed;
#   - a scene that does not compile is refused naming the problem; the
#     board render starts beside the compile (a QEMU that would run on) is
#     killed, never announced, and no QEMU is left running.
# Prints "PASS name" / "FAIL name: why".
. "$(dirname "$0")/../lib.sh"
checks=(early_size_overflow early_ram_too_small early_out_dir_missing comma_chardev_doubled
    comma_insn_profile_one_file comma_failed_start_shows_log early_scene_refused_board_killed)
board_ready "${checks[@]}" || exit 0
T=$(mktemp -d /tmp/links1-early.XXXXXX)
trap 'rm -rf "$T"' EXIT
cat >"$T/fake-qemu" <<'EOF'
#!/bin/sh
printf '%s\n' "$@" >>"$FAKE_ARGV"
echo "fake qemu: refusing to run (test)" >&2
exit 3
EOF
chmod +x "$T/fake-qemu"
export QEMU="$T/fake-qemu" FAKE_ARGV="$T/argv" LINKS1_BOARDS="$T/boards"

# run NAME LIMIT ARGS...: links1 ARGS under LIMIT seconds, its output in
# $T/NAME.log, its exit status in rc, printed with the output.
run() {
    local name=$1 limit=$2
    shift 2
    timeout "$limit" "$LINKS1" "$@" >"$T/$name.log" 2>&1
    rc=$?
    echo "--- links1 $* (exit $rc)"
    sed 's/^/    /' "$T/$name.log"
}
booted() { [ -e "$T/argv" ]; }

# ---- --size past an int: refused, nothing started
run size 20 render scenes/demo.scn --size 4294967360x48 -o "$T/s.png"
rc1=$rc
run size_ref 20 ref scenes/demo.scn --size 4294967360x48 -o "$T/s.ppm"
if [ $rc1 -eq 2 ] && [ $rc -eq 2 ] && grep -q -- "--size '4294967360x48'" "$T/size.log" &&
    grep -q -- "--size" "$T/size_ref.log" && ! booted && [ ! -e "$T/s.ppm" ]; then
    echo "PASS early_size_overflow"
else
    echo "FAIL early_size_overflow: render exit $rc1, ref exit $rc (want 2 and 2, naming --size), or a QEMU ran / an image was written"
fi

# ---- --ram below what the firmware lays out: refused, naming the least
run ram 20 render scenes/demo.scn --ram 64 --size 32x24 -o "$T/r.png"
rc1=$rc
run ram_board 20 board start --name r --ram 64
if [ $rc1 -eq 2 ] && [ $rc -eq 2 ] && grep -q -- "--ram '64'.*at least 1024" "$T/ram.log" &&
    grep -q -- "at least 1024" "$T/ram_board.log" && ! booted; then
    echo "PASS early_ram_too_small"
else
    echo "FAIL early_ram_too_small: render exit $rc1, board start exit $rc (want 2 and 2, naming the least, 1024), or a QEMU ran"
fi

# ---- -o in a missing directory: refused at once, naming it
ok=1
for cmd in "render scenes/demo.scn --size 32x24" "ref scenes/demo.scn --size 16x12" \
    "compile scenes/demo.scn" "import tests/models/cube.obj --camera auto"; do
    word=${cmd%% *}
    start=$SECONDS
    # shellcheck disable=SC2086
    run "out_$word" 20 $cmd -o "$T/missing/a.out"
    if [ $rc -eq 0 ] || [ $rc -eq 124 ] || ! grep -q "$T/missing: No such file or directory" "$T/out_$word.log" ||
        [ $((SECONDS - start)) -gt 5 ]; then
        ok=0
        why="links1 $word: exit $rc (want 1, or 2 for render's option checks) after $((SECONDS - start)) s, or no message naming $T/missing"
    fi
done
if [ $ok -eq 1 ] && ! booted; then
    echo "PASS early_out_dir_missing"
else
    echo "FAIL early_out_dir_missing: ${why:-a QEMU ran}"
fi

# ---- a comma in the state directory: doubled in the chardev
export LINKS1_BOARDS="$T/b,c"
run comma_start 20 board start --name n --ncs 1 --timeout 5
want="socket,id=link,path=$T/b,,c/n/link.sock,server=on,wait=on"
if grep -qxF -- "$want" "$T/argv" 2>/dev/null && [ $rc -eq 1 ]; then
    echo "PASS comma_chardev_doubled"
else
    echo "FAIL comma_chardev_doubled: QEMU was not given -chardev $want (exit $rc); it got: $(grep -a chardev -A1 "$T/argv" 2>/dev/null | tr '\n' ' ')"
fi
# its QEMU failed: the end of its output shown, no pointer to a removed log
if grep -q "fake qemu: refusing to run" "$T/comma_start.log" &&
    ! grep -q "its output is in" "$T/comma_start.log" && [ ! -e "$T/b,c/n" ]; then
    echo "PASS comma_failed_start_shows_log"
else
    echo "FAIL comma_failed_start_shows_log: QEMU's own output not printed, or a pointer to its removed log, or the state left"
fi

# ---- --insn-profile FILE with a comma: one file, not a plugin option
rm -f "$T/argv"
run prof 20 render scenes/demo.scn --size 32x24 -o "$T/p.png" --insn-profile "$T/prof.txt,profile_from=0"
plugin=$(grep -a -A1 -x -- "-plugin" "$T/argv" 2>/dev/null | tail -n 1)
echo "--- -plugin $plugin"
# the plugin writes its profile in the run's private directory (copied to
# FILE afterwards): FILE's words never reach the plugin's options
if [[ $plugin =~ ,profile=[^,]*/links1-insns-[0-9]+-[^,/]*/profile(,|$) ]] &&
    [[ $plugin != *"profile_from=0"* ]] && [[ $plugin != *"prof.txt"* ]]; then
    echo "PASS comma_insn_profile_one_file"
else
    echo "FAIL comma_insn_profile_one_file: the plugin's profile= argument is not the run's private file, or FILE's comma added an option: $plugin"
fi

# ---- a scene that does not compile: refused, the board started beside
# its compile killed.  This QEMU writes its pid and would run a minute.
cat >"$T/slow-qemu" <<'EOF2'
#!/bin/sh
echo $$ >>"$FAKE_PIDS"
exec sleep 60
EOF2
chmod +x "$T/slow-qemu"
# a model of 65,536 triangles with a bad last line: its compile lasts long
# enough (0.2 s) for that QEMU to have started
"$(dirname "$LINKS1")/links1-spd" tetra 8 -o "$T/bad.nff" >/dev/null 2>&1
echo "zz 1 2 3" >>"$T/bad.nff"
unset LINKS1_BOARDS
start=$SECONDS
QEMU="$T/slow-qemu" FAKE_PIDS="$T/pids" run bad_scene 20 render "$T/bad.nff" -o "$T/bad.png"
took=$((SECONDS - start))
alive=0
while read -r pid; do
    kill -0 "$pid" 2>/dev/null && alive=1 && kill -9 "$pid"
done <"$T/pids" 2>/dev/null
if [ $rc -eq 1 ] && grep -q "bad.nff:262155:1: unknown NFF entity 'zz'" "$T/bad_scene.log" && ! grep -q booting "$T/bad_scene.log" &&
    [ $alive -eq 0 ] && [ -s "$T/pids" ] && [ $took -lt 10 ] && [ ! -e "$T/bad.png" ]; then
    echo "PASS early_scene_refused_board_killed"
else
    echo "FAIL early_scene_refused_board_killed: exit $rc after $took s (want 1, the scene's line named, no 'booting'), QEMU started: $([ -s "$T/pids" ] && echo yes || echo no), left running: $alive"
fi
