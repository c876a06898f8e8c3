#!/usr/bin/env bash
# bench_boot.sh: guest instructions each core executes for one idle boot
# (report-in, then shutdown), counted exactly by the TCG plugin
# build/insn-count.so.  Deterministic work, unlike wall-clock time on shared
# host cores.
set -eu
cd "$(dirname "$0")/../.."
NCS=${NCS:-8}
echo "bench_boot: links1 boot --ncs $NCS --count-insns"
build/links1 boot --ncs "$NCS" --quiet --count-insns
