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
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/render_lib.sh"
CHECKS="farm_hosts_both_used farm_hosts_frames farm_hosts_killed_mid_frame
        farm_hosts_kill_frames farm_hosts_kill_summary"
board_ready $CHECKS || exit 0
why=""
[ "$(id -u)" -eq 0 ] || why="the throw-away sshd needs root"
for t in parallel rsync ssh ssh-keygen /usr/sbin/sshd; do
    [ -n "$why" ] || command -v $t >/dev/null || why="$t is not installed (install-deps.sh)"
done
if [ -n "$why" ]; then
    for c in $CHECKS; do echo "FAIL $c: $why"; done
    exit 0
fi
SIZE=48x36
T=$RENDER_TMP
S=$T/ssh
mkdir -p "$S" /run/sshd
chmod 700 "$S"
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
ssh-keygen -q -t ed25519 -N '' -f "$S/hostkey"
ssh-keygen -q -t ed25519 -N '' -f "$S/userkey"
cp "$S/userkey.pub" "$S/authorized_keys"
chmod 600 "$S/authorized_keys"
cat >"$S/sshd_config" <<EOF
Port $port
ListenAddress 127.0.0.1
HostKey $S/hostkey
AuthorizedKeysFile $S/authorized_keys
PasswordAuthentication no
PermitRootLogin prohibit-password
StrictModes no
UsePAM no
PidFile $S/sshd.pid
EOF
cat >"$S/client_config" <<EOF
Host fakehost
  HostName 127.0.0.1
  Port $port
  IdentityFile $S/userkey
  StrictHostKeyChecking no
  UserKnownHostsFile /dev/null
  LogLevel ERROR
  BatchMode yes
EOF
export PARALLEL_SSH="ssh -F $S/client_config"
printf ':\nfakehost\n' >"$T/hosts"

sshd_pid=""
start_sshd() {
    rm -f "$S/sshd.pid"
    /usr/sbin/sshd -f "$S/sshd_config" -E "$S/sshd.log"
    for _ in $(seq 50); do [ -s "$S/sshd.pid" ] && break; sleep 0.1; done
    sshd_pid=$(cat "$S/sshd.pid" 2>/dev/null)
}
# tree PID: PID and every process under it
tree() {
    local p=$1 c
    echo "$p"
    for c in $(ps -o pid= --ppid "$p" 2>/dev/null); do tree "$c"; done
}
stop_sshd() {
    [ -n "$sshd_pid" ] && kill -9 $(tree "$sshd_pid") 2>/dev/null
    sshd_pid=""
}
trap 'stop_sshd; rm -rf "$RENDER_TMP"' EXIT
start_sshd
if [ -z "$sshd_pid" ] || ! $PARALLEL_SSH fakehost true; then
    cat "$S/sshd.log" 2>/dev/null
    for c in $CHECKS; do echo "FAIL $c: the throw-away sshd on port $port did not answer"; done
    exit 0
fi
render_board farm_hosts_ref "$T/ref.ppm" scenes/anim.scn -o "$T/ref.ppm" --size $SIZE \
    --frames 0:3 || exit 0

frames_same() { # NAME DIR: all four frames equal the board's
    local bad="" f
    for f in 0 1 2 3; do cmp -s "$T/ref-000$f.ppm" "$2/frame-000$f.ppm" || bad+=" $f"; done
    if [ -z "$bad" ]; then echo "PASS $1"; else echo "FAIL $1: frame(s)$bad missing or not the board's"; fi
}

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
frames_same farm_hosts_frames "$H/both \"d\""

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
            stop_sshd
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
[ -e "$T/killed" ] && sshd_pid="" # killed in the killer's subshell
frames_same farm_hosts_kill_frames "$T/kill"
if [ $rc -eq 0 ] && grep -q '4 frame(s) rendered now, 0 kept from before, 0 missing' "$T/farm_hosts_kill.log"; then
    echo "PASS farm_hosts_kill_summary"
else
    echo "FAIL farm_hosts_kill_summary: exit $rc: $(grep 'rendered now' "$T/farm_hosts_kill.log")"
fi
