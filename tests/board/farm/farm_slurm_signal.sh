#!/usr/bin/env bash
# links1 farm --slurm stopped by a signal cancels its Slurm job.  A fake
# sbatch (first on PATH, in a private temporary directory) prints the job
# id 4242 as `sbatch --parsable --wait` does at submission, then waits as
# for the job (it execs sleep, so the process that links1 started is the
# one that waits); a fake scancel records its arguments.  SIGTERM to the
# farm once the id is printed: scancel is run with 4242, the farm says so
# and ends promptly by the signal, and no fake sbatch is left; a scancel
# that fails is reported as such.  Nothing here boots a board or needs
# Slurm.
. "$(dirname "$0")/../lib.sh"
CHECKS="farm_slurm_signal_scancel farm_slurm_signal_said farm_slurm_signal_exit
        farm_slurm_signal_no_sbatch_left farm_slurm_signal_scancel_failed"
if [ ! -x "$LINKS1" ]; then
    checks_fail "$LINKS1 is not built (run make)" $CHECKS
    exit 0
fi
T=$(mktemp -d /tmp/links1-farm-signal.XXXXXX) # yours, 0700
farm_pid=""
stop_ours() { # the farm and the fake sbatch, by their ids, if still there
    [ -n "$farm_pid" ] && kill -KILL "$farm_pid" 2>/dev/null
    [ -s "$T/sbatch.pid" ] && kill -KILL "$(cat "$T/sbatch.pid")" 2>/dev/null
    rm -rf "$T"
}
trap stop_ours EXIT
mkdir "$T/bin"
# the fake sbatch: the id, then as long as a round could take
cat >"$T/bin/sbatch" <<EOF
#!/bin/sh
echo 4242
echo "\$\$" >"$T/sbatch.pid"
exec sleep 60
EOF
cat >"$T/bin/scancel" <<EOF
#!/bin/sh
echo "\$*" >>"$T/scancel.args"
exit \$(cat "$T/scancel.rc")
EOF
chmod 700 "$T/bin/sbatch" "$T/bin/scancel"

# stopped NAME SCANCEL_RC: the farm started, sent SIGTERM once the fake
# sbatch printed the id; rc and ms its exit status and how long it took
stopped() {
    rm -f "$T/sbatch.pid" "$T/scancel.args"
    echo "$2" >"$T/scancel.rc"
    PATH="$T/bin:$PATH" "$LINKS1" farm scenes/anim.scn --frames 0:1 -o "$T/out" --slurm \
        -- --size 8x6 >"$T/$1.log" 2>&1 &
    farm_pid=$!
    for _ in $(seq 200); do # up to 10 s for the fake sbatch to start
        [ -s "$T/sbatch.pid" ] && break
        sleep 0.05
    done
    sleep 0.5 # the id read back by the farm
    local t0
    t0=$(date +%s%N)
    kill -TERM "$farm_pid"
    wait "$farm_pid"
    rc=$?
    ms=$((($(date +%s%N) - t0) / 1000000))
    farm_pid=""
    echo "--- PATH=$T/bin:\$PATH $LINKS1 farm scenes/anim.scn --frames 0:1 -o $T/out --slurm" \
        "(scancel exits $2; SIGTERM; exit $rc after $ms ms)"
    sed 's/^/    /' "$T/$1.log"
}

stopped farm 0
args=$(cat "$T/scancel.args" 2>/dev/null)
if [ "$args" = 4242 ]; then
    echo "PASS farm_slurm_signal_scancel"
else
    echo "FAIL farm_slurm_signal_scancel: scancel was run with '$args', want '4242' once"
fi
if grep -q '^links1 farm: stopped: cancelled Slurm job 4242$' "$T/farm.log"; then
    echo "PASS farm_slurm_signal_said"
else
    echo "FAIL farm_slurm_signal_said: no 'links1 farm: stopped: cancelled Slurm job 4242' on stderr"
fi
if [ $rc -ne 0 ] && [ $ms -lt 5000 ]; then
    echo "PASS farm_slurm_signal_exit (exit $rc after $ms ms)"
else
    echo "FAIL farm_slurm_signal_exit: exit $rc after $ms ms, want non-zero within 5 s"
fi
pid=$(cat "$T/sbatch.pid" 2>/dev/null)
if [ -n "$pid" ] && ! kill -0 "$pid" 2>/dev/null; then
    echo "PASS farm_slurm_signal_no_sbatch_left"
else
    echo "FAIL farm_slurm_signal_no_sbatch_left: the fake sbatch (pid ${pid:-unknown}) is still there"
fi

# scancel fails: the farm says the job may still be running
stopped farm_failed 1
if grep -q '^links1 farm: stopped: scancel 4242 failed; Slurm job 4242 may still be running$' \
    "$T/farm_failed.log" && [ "$(cat "$T/scancel.args" 2>/dev/null)" = 4242 ] && [ $rc -ne 0 ]; then
    echo "PASS farm_slurm_signal_scancel_failed"
else
    echo "FAIL farm_slurm_signal_scancel_failed: exit $rc; no 'scancel 4242 failed' on stderr"
fi
