#!/usr/bin/env bash
# A named board's QEMU is gone and another local user's process now has
# its pid, its command line naming the board's UART socket exactly as the
# QEMU's did (what a reused pid looks like, played here by writing the
# other user's pid into the board's record).  The board counts as not
# running: `board list` reports it gone and removes its state; `board
# start` of that name starts a new board; `render --board` fails at once
# naming the board as not running; `board stop` says the board was not
# running, exits 0 and leaves the other user's process alone (as root it
# could kill it).  As root only: a throw-away second account plays the
# other user (tests/board/other_user_lib.sh); otherwise every check SKIPs.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
. "$(dirname "$0")/../other_user_lib.sh"
checks=(other_user_boards_list other_user_boards_start other_user_boards_render
    other_user_boards_stop)
board_ready "${checks[@]}" || exit 0
export LINKS1_BOARDS="$RENDER_TMP/boards"
trap 'for f in "$LINKS1_BOARDS"/*/board; do [ -e "$f" ] && kill -9 "$(awk "/^pid/ {print \$2}" "$f")" 2>/dev/null; done; rm -rf "$RENDER_TMP"' EXIT
other_user_make "${checks[@]}" || exit 0

# plant NAME: board NAME started, its QEMU killed, and another user's
# process (its command line holding the board's UART chardev, as the
# QEMU's did) written into its record; that process's pid in $other.
plant() {
    local name=$1 dir="$LINKS1_BOARDS/$1" qemu
    render_run "start_$name" board start --name "$name" --ncs 1 --quiet || return 1
    qemu=$(render_board_pid "$name")
    kill -9 "$qemu"
    while [ -e "/proc/$qemu/cmdline" ] && [ -s "/proc/$qemu/cmdline" ]; do sleep 0.1; done
    as_other sh -c 'sleep 300; exit 0' sh "socket,id=link,path=$dir/link.sock,server=on,wait=on" &
    local runner=$!
    disown "$runner"
    other=""
    for _ in $(seq 50); do
        other=$(pgrep -u "$OTHER_USER" -f "path=$dir/link.sock" | head -n 1)
        [ -n "$other" ] && break
        sleep 0.1
    done
    [ -n "$other" ] || return 1
    sed -i "s/^pid .*/pid $other/" "$dir/board"
    echo "--- board $name: its QEMU (pid $qemu) killed; its record now names pid $other, uid $(stat -c %u "/proc/$other") (runner $runner): $(tr '\0' ' ' <"/proc/$other/cmdline")"
}
other_runs() { [ -n "$other" ] && [ -e "/proc/$other" ] && [ "$(stat -c %U "/proc/$other")" = "$OTHER_USER" ]; }

# ---- board list: not running, its stale state removed
if plant l; then
    render_run list board list
    if ! grep -q '^board l: running' "$RENDER_TMP/list.log" && grep -q 'board l: its QEMU.*is gone' "$RENDER_TMP/list.log" &&
        [ ! -e "$LINKS1_BOARDS/l" ] && other_runs; then
        echo "PASS other_user_boards_list"
    else
        echo "FAIL other_user_boards_list: board list called board l running, or did not report it gone and remove $LINKS1_BOARDS/l, or the other user's process ended"
    fi
else
    echo "FAIL other_user_boards_list: could not plant the other user's process"
fi

# ---- board start of that name: starts a new board
if plant s; then
    render_run again board start --name s --ncs 1 --quiet
    rc=$?
    new=$(render_board_pid s)
    if [ $rc -eq 0 ] && [ -n "$new" ] && [ "$new" != "$other" ] && other_runs &&
        render_run slist board list && grep -q "^board s: running, QEMU pid $new" "$RENDER_TMP/slist.log" &&
        render_run sstop board stop s; then
        echo "PASS other_user_boards_start"
    else
        echo "FAIL other_user_boards_start: board start s exited $rc (want 0 with a new QEMU), or the new board is not listed running or did not stop"
    fi
else
    echo "FAIL other_user_boards_start: could not plant the other user's process"
fi

# ---- render --board: fails at once, naming the board as not running
if plant r; then
    start=$SECONDS
    render_run render render --board r --quiet scenes/demo.scn --size 32x24 -o "$RENDER_TMP/r.ppm"
    rc=$?
    secs=$((SECONDS - start))
    if [ $rc -eq 1 ] && [ $secs -lt 10 ] && grep -q 'board r is not running' "$RENDER_TMP/render.log" &&
        [ ! -e "$RENDER_TMP/r.ppm" ] && other_runs; then
        echo "PASS other_user_boards_render"
    else
        echo "FAIL other_user_boards_render: exit $rc after $secs s (want 1 within 10 s, 'board r is not running')"
    fi
else
    echo "FAIL other_user_boards_render: could not plant the other user's process"
fi

# ---- board stop: says it was not running, exits 0, the other process left
if plant t; then
    render_run stop board stop t
    rc=$?
    if [ $rc -eq 0 ] && grep -q 'board t was not running' "$RENDER_TMP/stop.log" &&
        ! grep -q 'board t stopped' "$RENDER_TMP/stop.log" && ! grep -q SIGTERM "$RENDER_TMP/stop.log" &&
        other_runs && [ ! -e "$LINKS1_BOARDS/t" ]; then
        echo "PASS other_user_boards_stop"
    else
        echo "FAIL other_user_boards_stop: exit $rc (want 0, 'board t was not running', no signal sent), or the other user's process was killed, or the state left"
    fi
else
    echo "FAIL other_user_boards_stop: could not plant the other user's process"
fi
