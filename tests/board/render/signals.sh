#!/usr/bin/env bash
# Signals leave nothing (issue 37, item 5) and the counting files are
# private (hole 3).  With TMPDIR a fresh directory of the test's own:
#   render a film (SIGINT), render a film with --count-insns (SIGTERM),
#   an an521 render with --count-insns (SIGHUP), ref --auto (SIGTERM):
#   each exits 128+N, leaves no temporary file (TMPDIR empty, no .OUT.*
#   beside the film) and no child of its running;
#   a render whose $QEMU is a wrapper script that starts the emulator as
#   its child, not by exec (SIGTERM): the emulator ends with it;
#   a render given SIGTSTP (^Z): its QEMU stops too, and runs again after
#   SIGCONT;
#   ref --auto killed with SIGKILL: its children end (the
#   parent-death signal) and the next run sweeps the directory it left;
#   while an an521 render counts, every counting file QEMU is told of is
#   in one directory of the user's, mode 0700;
#   the counting plugin refuses a link another user planted at its file
#   (O_EXCL | O_NOFOLLOW): the link's target keeps its bytes.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../other_user_lib.sh"
CHECKS="signals_render_film_int signals_render_insns_term signals_wrapper_qemu_term
signals_tstp_stops_qemu signals_an521_counts_private
signals_an521_hup signals_ref_auto_term signals_ref_auto_kill_children signals_ref_auto_sweep
signals_plugin_refuses_link"
board_ready $CHECKS || exit 0
command -v ffmpeg >/dev/null || { checks_fail "ffmpeg is not installed" $CHECKS; exit 0; }
T=$(mktemp -d /tmp/links1-signals-test.XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR=$T/tmp
mkdir -m 700 "$TMPDIR" "$T/out"
# Each command with SIGINT, SIGHUP and SIGTERM at their default (a script's
# background job has SIGINT ignored, and links1 keeps a signal ignored).
L1=(env --default-signal=INT,HUP,TERM "$LINKS1")

# wait_for SECONDS CMD...: 0 once CMD succeeds, 1 after SECONDS.
wait_for() {
    local end=$((SECONDS + $1)); shift
    while ! "$@"; do
        [ $SECONDS -ge "$end" ] && return 1
        sleep 0.2
    done
}
have() { compgen -G "$1" >/dev/null; } # have GLOB: something matches
children_of() { pgrep -P "$1" | tr '\n' ' '; }
all_gone() { local p; for p in "$@"; do kill -0 "$p" 2>/dev/null && return 1; done; return 0; }
# clean_out: TMPDIR and the output directory emptied for the next command
clean_out() { rm -rf "${TMPDIR:?}"/* "$T"/out/* "$T"/out/.[!.]*; }
# never_started NAME LOG PID: NAME fails, its command (PID, writing LOG)
# never got going; PID killed
never_started() {
    echo "FAIL $1: it never got going: $(tail -n 1 "$2")"
    kill -KILL "$3" 2>/dev/null; wait "$3" 2>/dev/null
}
# ended PID: gone, or a zombie (an orphan waiting for init to reap it)
ended() { local s; s=$(ps -o stat= -p "$1" 2>/dev/null); [ -z "$s" ] || [ "${s#Z}" != "$s" ]; }

# interrupt NAME SIG READY_GLOB CMD...: starts CMD, waits until READY_GLOB
# matches and CMD has a child, sends SIG; checks the exit status, that
# TMPDIR and the output directory hold nothing of it, and that its children
# are gone.
interrupt() {
    local name=$1 sig=$2 ready=$3; shift 3
    local log=$T/$name.log
    "$@" >"$log" 2>&1 &
    local pid=$!
    if ! wait_for 90 bash -c "compgen -G '$ready' >/dev/null && pgrep -P $pid >/dev/null"; then
        echo "FAIL $name: never got going ($ready): $(tail -n 1 "$log")"
        kill -KILL "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
        return 1
    fi
    sleep 1.5
    local kids
    kids=$(children_of "$pid")
    kill -s "$sig" "$pid"
    wait "$pid" 2>/dev/null
    local rc=$? want=$((128 + $(kill -l "$sig")))
    local left
    left=$(ls -A "$TMPDIR" "$T/out" | grep -v -e '^$' -e ':$' | tr '\n' ' ')
    # shellcheck disable=SC2086
    if ! wait_for 5 all_gone $kids; then
        echo "FAIL $name: children $kids still running"
    elif [ "$rc" -ne "$want" ]; then
        echo "FAIL $name: exit status $rc, want $want"
    elif [ -n "$left" ]; then
        echo "FAIL $name: left $left"
    else
        echo "PASS $name (exit $rc, children $kids gone, nothing left)"
    fi
    clean_out
}

# (256x192, and 128x96 counted: the twelve frames take far longer than the
# 1.5 s before the signal, so it lands while the film is still being made;
# 64x48 counted took 1.9 s in all, and a signal sometimes came after it)
interrupt signals_render_film_int INT "$T/out/.a.apng.*" \
    "${L1[@]}" render scenes/fly.scn --frames 0:11 -o "$T/out/a.apng" --size 256x192 --quiet
interrupt signals_render_insns_term TERM "$TMPDIR/links1-insns-*" \
    "${L1[@]}" render scenes/fly.scn --frames 0:11 -o "$T/out/b.apng" --size 128x96 --quiet \
    --count-insns

# A $QEMU that starts the emulator as its child instead of exec'ing it:
# the launcher signals the process group the wrapper leads.
cat >"$T/wrap-qemu.sh" <<EOF
#!/bin/sh
"${QEMU:-qemu-system-arm}" "\$@" &
echo \$! >"$T/wrapped.pid"
wait \$!
EOF
chmod 700 "$T/wrap-qemu.sh"
QEMU=$T/wrap-qemu.sh "${L1[@]}" render scenes/fly.scn --frames 0:11 -o "$T/out/w.apng" \
    --size 256x192 --quiet >"$T/wrap.log" 2>&1 &
pid=$!
if wait_for 90 test -s "$T/wrapped.pid"; then
    sleep 1.5
    q=$(cat "$T/wrapped.pid")
    kill -TERM "$pid"
    wait "$pid" 2>/dev/null
    rc=$?
    if ! wait_for 10 ended "$q"; then
        echo "FAIL signals_wrapper_qemu_term: the wrapper's QEMU (pid $q) still runs"
        kill -KILL "$q"
    elif [ "$rc" -ne 143 ]; then
        echo "FAIL signals_wrapper_qemu_term: exit status $rc, want 143"
    else
        echo "PASS signals_wrapper_qemu_term (the wrapper's QEMU, pid $q, ended with the command)"
    fi
else
    never_started signals_wrapper_qemu_term "$T/wrap.log" "$pid"
fi
clean_out

# ^Z: links1 stops, and so does its QEMU (a process group of its own, out
# of the terminal's reach); continued, QEMU runs again.
"${L1[@]}" render scenes/fly.scn --frames 0:11 -o "$T/out/z.apng" --size 256x192 --quiet \
    >"$T/tstp.log" 2>&1 &
pid=$!
qstate() { ps -o stat= -p "$1" 2>/dev/null | cut -c1; }
if wait_for 90 bash -c "pgrep -P $pid >/dev/null"; then
    sleep 1
    q=$(pgrep -P "$pid" | head -n 1)
    kill -TSTP "$pid"
    wait_for 5 eval '[ "$(qstate "$q")" = T ]' && stopped=1 || stopped=0
    kill -CONT "$pid"
    wait_for 5 eval '[ "$(qstate "$q")" != T ]' && again=1 || again=0
    kill -TERM "$pid"
    wait "$pid" 2>/dev/null
    if [ "$stopped" = 1 ] && [ "$again" = 1 ]; then
        echo "PASS signals_tstp_stops_qemu (QEMU $q stopped with ^Z, running again after SIGCONT)"
    else
        echo "FAIL signals_tstp_stops_qemu: QEMU $q stopped $stopped, running again $again"
    fi
else
    never_started signals_tstp_stops_qemu "$T/tstp.log" "$pid"
fi
clean_out

# an521: the counting files QEMU is told of, while it runs.
an521_private() {
    local pid=$1 q arg f dir bad="" n=0
    for q in $(pgrep -P "$pid"); do
        arg=$(tr '\0' '\n' <"/proc/$q/cmdline" 2>/dev/null | grep -m1 'insn-count.so')
        f=$(echo "$arg" | tr ',' '\n' | sed -n 's/^out=//p')
        [ -n "$f" ] || continue
        n=$((n + 1))
        dir=$(dirname "$f")
        case $dir in "$TMPDIR"/links1-insns-*) ;; *) bad="$bad $f(outside)";; esac
        [ "$(stat -c '%a %u %F' "$dir")" = "700 $(id -u) directory" ] || bad="$bad $dir($(stat -c '%a %u %F' "$dir"))"
        [ -e "$f" ] && bad="$bad $f(exists before QEMU ends)"
    done
    [ "$n" -ge 2 ] || bad="$bad only $n board(s) counting"
    echo "$bad"
}
"${L1[@]}" render scenes/fly.scn --frames 0:11 -o "$T/out/c.apng" --size 64x48 --quiet \
    --machine an521 --ncs 4 --count-insns >"$T/an521.log" 2>&1 &
pid=$!
if wait_for 90 bash -c "[ \$(pgrep -P $pid -f insn-count.so | wc -l) -ge 3 ]"; then
    bad=$(an521_private "$pid")
    [ -z "$bad" ] && echo "PASS signals_an521_counts_private (3 boards, one 0700 directory)" ||
        echo "FAIL signals_an521_counts_private:$bad"
else
    echo "FAIL signals_an521_counts_private: the an521 boards never counted: $(tail -n 1 "$T/an521.log")"
fi
kill -KILL "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
sleep 1; clean_out
interrupt signals_an521_hup HUP "$TMPDIR/links1-insns-*" \
    "${L1[@]}" render scenes/fly.scn --frames 0:11 -o "$T/out/d.apng" --size 64x48 --quiet \
    --machine an521 --ncs 4 --count-insns

# ref --auto (--arith auto's search, over density steps and min_weight
# too): a run that takes a while (demo.scn at 320x240, about 7 s on a
# quiet host; --arith auto alone takes 2 s, too near the 1.5 s wait)
AUTO=("${L1[@]}" ref scenes/demo.scn -o "$T/out/auto.ppm" --auto --size 320x240)
interrupt signals_ref_auto_term TERM "$TMPDIR/links1-auto-*" "${AUTO[@]}"

"${AUTO[@]}" >"$T/kill.log" 2>&1 &
pid=$!
if wait_for 90 bash -c "compgen -G '$TMPDIR/links1-auto-*' >/dev/null && pgrep -P $pid >/dev/null"; then
    kids=""
    for _ in $(seq 100); do # a child it can name: the run starts one after another
        kids=$(children_of "$pid")
        [ -n "${kids// /}" ] && break
        sleep 0.1
    done
    grand=""
    for k in $kids; do grand="$grand $(children_of "$k")"; done
    kill -KILL "$pid"; wait "$pid" 2>/dev/null
    # shellcheck disable=SC2086
    if [ -z "${kids// /}" ]; then
        echo "FAIL signals_ref_auto_kill_children: no child seen in 10 s to watch"
    elif wait_for 10 all_gone $kids $grand; then
        echo "PASS signals_ref_auto_kill_children (children $kids$grand ended with it)"
    else
        echo "FAIL signals_ref_auto_kill_children: still running after SIGKILL of the parent: $kids$grand"
    fi
    stale=$(compgen -G "$TMPDIR/links1-auto-$pid-*")
    "${AUTO[@]}" >"$T/sweep.log" 2>&1 &
    pid2=$!
    if [ -z "$stale" ]; then
        echo "FAIL signals_ref_auto_sweep: the killed run left no directory to sweep"
    elif wait_for 90 have "$TMPDIR/links1-auto-$pid2-*" && [ ! -e "$stale" ]; then
        echo "PASS signals_ref_auto_sweep (the next run removed $(basename "$stale"))"
    else
        echo "FAIL signals_ref_auto_sweep: $(basename "$stale") still there: $(ls "$TMPDIR")"
    fi
    kill -TERM "$pid2"; wait "$pid2" 2>/dev/null
else
    checks_fail "ref --auto never got going: $(tail -n 1 "$T/kill.log")" \
        signals_ref_auto_kill_children signals_ref_auto_sweep
    kill -KILL "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
fi

# Hole 3 as another user would play it: a link at the plugin's file.
other_user_make signals_plugin_refuses_link || exit 0
chmod 711 "$T" # the other user may reach the shared directory in it
other_user_dir "$T/shared"
echo "keep these bytes" >"$T/victim.txt"
as_other ln -s "$T/victim.txt" "$T/shared/counts"
timeout -s TERM 3 "${QEMU:-qemu-system-arm}" -M virt -cpu cortex-a15 -m 256M -display none \
    -nodefaults -kernel "$FW_DIR/links1-float.elf" -d plugin \
    -plugin "build/insn-count.so,out=$T/shared/counts" >"$T/plugin.log" 2>&1
if [ "$(cat "$T/victim.txt")" = "keep these bytes" ] && grep -q 'cannot make the out= file' "$T/plugin.log"; then
    echo "PASS signals_plugin_refuses_link (the link's target kept, the plugin said why)"
else
    echo "FAIL signals_plugin_refuses_link: the target now holds '$(head -c 60 "$T/victim.txt")'; $(tail -n 1 "$T/plugin.log")"
fi
