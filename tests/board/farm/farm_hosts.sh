#!/usr/bin/env bash
# links1 farm across two "hosts" on one machine: this one (':') and a
# throw-away sshd on 127.0.0.1 at a free port (its own host key and user
# key, made here), reached by GNU parallel through $PARALLEL_SSH.  First
# run: both hosts take frames, each frame of scenes/anim.scn comes back into
# DIR equal to one board's render (scene and DIR named with spaces, quotes
# and $).  Second run: the sshd and everything
# under it are killed while that host renders a frame; parallel retries the
# frame on the other host and every frame still arrives, equal to the
# board's.  Needs root (sshd) and openssh-server, parallel and rsync.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
. "$(dirname "$0")/farm_sshd.sh"
CHECKS="farm_hosts_both_used farm_hosts_frames farm_hosts_bands farm_hosts_killed_mid_frame
        farm_hosts_kill_frames farm_hosts_kill_summary"
board_ready $CHECKS || exit 0
why=$(farm_sshd_why)
if [ -n "$why" ]; then
    checks_fail "$why" $CHECKS
    exit 0
fi
SIZE=48x36
T=$RENDER_TMP
printf ':\nfakehost\n' >"$T/hosts"
trap 'farm_sshd_stop; rm -rf "$RENDER_TMP"' EXIT
if ! farm_sshd_start "$T/ssh" >"$T/sshd_start.log" 2>&1; then
    cat "$T/sshd_start.log"
    checks_fail "$(tail -n 1 "$T/sshd_start.log")" $CHECKS
    exit 0
fi
sshd_pid=$farm_sshd_pid
render_board farm_hosts_ref "$T/ref.ppm" scenes/anim.scn -o "$T/ref.ppm" --size $SIZE \
    --frames 0:3 || exit 0

# 1. both hosts take frames (the scene and DIR with spaces, quotes and $ in
# their names, quoted by parallel for the remote shell and for rsync)
H="$T/h o'st \"\$x"
mkdir -p "$H"
cp scenes/anim.scn "$H/a \$y 'b'.scn"
cp -r scenes/maps "$H/"
farm farm_hosts_run "$H/a \$y 'b'.scn" --frames 0:3 -o "$H/both \"d\"" --hosts "$T/hosts" \
    --ext ppm -- --size $SIZE
used=$(tail -n +2 "$H/both \"d\"/farm-joblog.tsv" | awk -F'\t' '$7 == 0 { print $2 }' | sort -u | tr '\n' ' ')
if [ "$used" = ": fakehost " ]; then
    echo "PASS farm_hosts_both_used"
else
    echo "FAIL farm_hosts_both_used: hosts with a frame done: '$used'"
fi
farm_frames_same farm_hosts_frames "$H/both \"d\""

# bands of one still frame on both hosts, stitched: the board's frame 1
farm farm_hosts_bands_run scenes/anim.scn --frames 1:1 --bands 6 -o "$T/bands" --hosts "$T/hosts" \
    --ext ppm -- --size $SIZE
if cmp -s "$T/ref-0001.ppm" "$T/bands/frame-0001.ppm"; then
    echo "PASS farm_hosts_bands ($(tail -n +2 "$T/bands/farm-joblog.tsv" | awk -F'\t' '{ print $2 }' | sort | uniq -c | tr -s ' \n' ' '))"
else
    echo "FAIL farm_hosts_bands: 6 bands over both hosts did not stitch into the board's frame 1"
fi

# 2. the ssh host killed while it renders a frame
# job_under_sshd: the comm of a job's process (links1 or its QEMU) somewhere
# under the sshd, if there is one
job_under_sshd() {
    ps -e -o pid=,ppid=,comm= | awk -v root="$sshd_pid" '
        { parent[$1] = $2; comm[$1] = $3 }
        END {
            for (p in comm) {
                if (comm[p] != "links1" && comm[p] !~ /^qemu/) continue
                for (q = parent[p]; q > 1; q = parent[q]) if (q == root) { print comm[p]; exit }
            }
        }'
}
killer() {
    local seen
    for _ in $(seq 1200); do
        seen=$(job_under_sshd)
        if [ -n "$seen" ]; then
            farm_sshd_stop
            echo "killed while $seen ran" >"$T/killed"
            return
        fi
        sleep 0.02
    done
}
killer &
killer_pid=$!
farm farm_hosts_kill scenes/anim.scn --frames 0:3 -o "$T/kill" --hosts "$T/hosts" --ext ppm \
    --retries 3 -- --size $SIZE
rc=$?
wait $killer_pid
if [ -e "$T/killed" ]; then
    echo "PASS farm_hosts_killed_mid_frame ($(cat "$T/killed"))"
else
    echo "FAIL farm_hosts_killed_mid_frame: the ssh host never ran a job to be killed in"
fi
[ -e "$T/killed" ] && farm_sshd_pid="" # killed in the killer's subshell
farm_frames_same farm_hosts_kill_frames "$T/kill"
if [ $rc -eq 0 ] && grep -q '4 frame(s) rendered now, 0 kept from before, 0 missing' "$T/farm_hosts_kill.log"; then
    echo "PASS farm_hosts_kill_summary"
else
    echo "FAIL farm_hosts_kill_summary: exit $rc: $(grep 'rendered now' "$T/farm_hosts_kill.log")"
fi
