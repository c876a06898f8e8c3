# tests/board/farm/farm_sshd.sh (sourced): a throw-away sshd on 127.0.0.1 at a
# free port, with its own host key and user key, for `links1 farm` across
# two "hosts" on one machine (tests/board/farm/farm_hosts.sh,
# tests/bench/bench_farm.sh).  Needs root and openssh-server.
#
#   farm_sshd_why           why it cannot run here ("" when it can)
#   farm_sshd_start DIR     keys and config in DIR (made, mode 700), the
#                           sshd started; exports PARALLEL_SSH so that the
#                           host name "fakehost" reaches it; sets
#                           farm_sshd_pid; returns 1 (with the sshd's log on
#                           stdout) when it does not answer
#   farm_sshd_stop          the sshd and every process under it killed
#   farm_sshd_tree PID      PID and every process under it

farm_sshd_why() {
    local t
    [ "$(id -u)" -eq 0 ] || { echo "the throw-away sshd needs root"; return; }
    for t in parallel rsync ssh ssh-keygen /usr/sbin/sshd; do
        command -v $t >/dev/null || { echo "$t is not installed (install-deps.sh)"; return; }
    done
}

farm_sshd_start() {
    local S=$1 port
    mkdir -p "$S" /run/sshd
    chmod 700 "$S"
    port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
    rm -f "$S/hostkey" "$S/hostkey.pub" "$S/userkey" "$S/userkey.pub"
    ssh-keygen -q -t ed25519 -N '' -f "$S/hostkey"
    ssh-keygen -q -t ed25519 -N '' -f "$S/userkey"
    cp "$S/userkey.pub" "$S/authorized_keys"
    chmod 600 "$S/authorized_keys"
    cat >"$S/sshd_config" <<EOF2
Port $port
ListenAddress 127.0.0.1
HostKey $S/hostkey
AuthorizedKeysFile $S/authorized_keys
PasswordAuthentication no
PermitRootLogin prohibit-password
StrictModes no
UsePAM no
PidFile $S/sshd.pid
EOF2
    cat >"$S/client_config" <<EOF2
Host fakehost
  HostName 127.0.0.1
  Port $port
  IdentityFile $S/userkey
  StrictHostKeyChecking no
  UserKnownHostsFile /dev/null
  LogLevel ERROR
  BatchMode yes
EOF2
    export PARALLEL_SSH="ssh -F $S/client_config"
    rm -f "$S/sshd.pid"
    /usr/sbin/sshd -f "$S/sshd_config" -E "$S/sshd.log"
    for _ in $(seq 50); do [ -s "$S/sshd.pid" ] && break; sleep 0.1; done
    farm_sshd_pid=$(cat "$S/sshd.pid" 2>/dev/null)
    if [ -z "$farm_sshd_pid" ] || ! $PARALLEL_SSH fakehost true; then
        cat "$S/sshd.log" 2>/dev/null
        echo "the throw-away sshd on port $port did not answer"
        return 1
    fi
}

farm_sshd_tree() {
    local p=$1 c
    echo "$p"
    for c in $(ps -o pid= --ppid "$p" 2>/dev/null); do farm_sshd_tree "$c"; done
}

farm_sshd_stop() {
    [ -n "${farm_sshd_pid:-}" ] && kill -9 $(farm_sshd_tree "$farm_sshd_pid") 2>/dev/null
    farm_sshd_pid=""
}
