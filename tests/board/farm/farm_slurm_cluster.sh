# tests/board/farm/farm_slurm_cluster.sh (sourced): a throw-away Slurm cluster of
# one node on this machine, for `links1 farm --slurm` (tests/board/farm/farm_slurm.sh):
# its own munged (own key and socket), slurmctld and slurmd, on free ports,
# every file in one directory.  Needs root and Debian's slurmctld, slurmd,
# slurm-client and munge (install-deps.sh).
#
#   farm_slurm_why            why it cannot run here ("" when it can)
#   farm_slurm_start DIR      config, key and state in DIR (made, mode 700),
#                             the daemons started; exports SLURM_CONF; returns
#                             1 (with the daemons' logs on stdout) when the
#                             node is not idle within 30 s
#   farm_slurm_stop           every daemon of it killed

farm_slurm_why() {
    local t
    [ "$(id -u)" -eq 0 ] || { echo "the throw-away Slurm cluster runs its daemons as root"; return; }
    for t in munged slurmctld slurmd sbatch sinfo; do
        command -v $t >/dev/null || { echo "$t is not installed (install-deps.sh)"; return; }
    done
}

farm_slurm_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

farm_slurm_start() {
    local S=$1 p1 p2
    farm_slurm_dir=$S
    mkdir -p "$S/state" "$S/spool" "$S/log"
    chmod 700 "$S"
    p1=$(farm_slurm_port)
    p2=$(farm_slurm_port)
    head -c 1024 /dev/urandom >"$S/munge.key"
    chmod 600 "$S/munge.key"
    munged -f --socket="$S/munge.sock" --key-file="$S/munge.key" --log-file="$S/log/munged.log" \
        --pid-file="$S/munged.pid" --seed-file="$S/munged.seed" || return 1
    cat >"$S/slurm.conf" <<EOF2
ClusterName=links1farm
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$p1
SlurmdPort=$p2
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$S/munge.sock
StateSaveLocation=$S/state
SlurmdSpoolDir=$S/spool
SlurmctldPidFile=$S/slurmctld.pid
SlurmdPidFile=$S/slurmd.pid
SlurmctldLogFile=$S/log/slurmctld.log
SlurmdLogFile=$S/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=farmnode NodeAddr=127.0.0.1 NodeHostname=localhost CPUs=2 State=UNKNOWN
PartitionName=farm Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF2
    export SLURM_CONF=$S/slurm.conf
    slurmctld -f "$SLURM_CONF" || return 1
    slurmd -f "$SLURM_CONF" -N farmnode || return 1
    for _ in $(seq 60); do
        sinfo -h -o %T 2>/dev/null | grep -qx idle && return 0
        sleep 0.5
    done
    tail -n 20 "$S"/log/*.log
    echo "the throw-away Slurm node did not come up idle in 30 s"
    return 1
}

farm_slurm_stop() {
    local S=${farm_slurm_dir:-} f
    [ -n "$S" ] || return 0
    for f in slurmd slurmctld munged; do
        [ -s "$S/$f.pid" ] && kill -9 "$(cat "$S/$f.pid")" 2>/dev/null
    done
    farm_slurm_dir=""
}
