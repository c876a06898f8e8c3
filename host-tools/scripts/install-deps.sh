#!/usr/bin/env bash
# install-deps.sh [run]: makes sure the Debian packages links1 needs are
# present: with "run" only what `make run` needs (build links1 and the float
# firmware, render on the board), else everything (the tests, benchmarks,
# farm, fuzzers, charts and films too).  As root it installs what is missing
# with apt-get; otherwise it prints the exact command to run and fails.
set -eu
need_pkgs=(make gcc libc6-dev libpng-dev libassimp-dev gcc-arm-none-eabi
           picolibc-arm-none-eabi qemu-system-arm)
# libpng-dev, libassimp-dev: links1 reads and writes PNG and reads models.
if [ "${1:-}" != run ]; then
    need_pkgs+=(libnewlib-arm-none-eabi povray python3 clang libclang-rt-dev
                gdb-multiarch gnuplot-nox ffmpeg parallel rsync openssh-server
                openssh-client time slurmctld slurmd slurm-client munge passwd
                util-linux)
fi
# parallel, rsync, openssh-*: `links1 farm` hands frames to hosts through GNU parallel
# (its --return copies frames back with rsync over ssh); the farm test starts a
# throw-away sshd on localhost.  slurm*, munge: `links1 farm --slurm` submits
# sbatch job arrays; its test starts a throw-away one-node cluster.
# ffmpeg: `links1 render --frames A:B -o FILM.mp4` pipes the frames to its CLI.
# time: GNU time, the wall and CPU seconds tests/bench/bench_farm.sh reads.
# gnuplot-nox: the charts of `make figures` and `make sweeps`, PNG without X.
# clang: the fuzz harnesses (tests/fuzz/); libclang-rt-dev holds libFuzzer's
# and the sanitizers' runtimes, which clang only recommends.  gdb-multiarch:
# `make gdb`.  passwd, util-linux: useradd and runuser, the throw-away second
# account of the tests that play another local user.
missing=()
for p in "${need_pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
        missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -ne 0 ]; then
    echo "links1: missing Debian packages: ${missing[*]}" >&2
    echo "links1: install them with:" >&2
    echo "    sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
    exit 1
fi
echo "links1: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
