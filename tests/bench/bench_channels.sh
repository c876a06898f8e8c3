#!/usr/bin/env bash
# bench_channels.sh: the channels' speed on a 10-core board, one boot:
# 64 MiB through the inter-unit serial lines, 8 MiB each way through the
# host link's serial path (tests/bench/bench_link.sh: the fast path).
# Wall-clock figures: the selftest lines print KiB/s.
set -eu
cd "$(dirname "$0")/../.."
echo "bench_channels: links1 selftest --ncs 8 --link serial --mib 64 --bytes 8388608 stress link-sink link-source"
build/links1 selftest --ncs 8 --link serial --quiet --mib 64 --bytes $((8 << 20)) stress link-sink link-source
