#!/usr/bin/env bash
# The LINKS-1 channels on a 10-core board, in one boot: status, ping-pong over
# every serial line, IMSU swap and broadcast, 64 MiB through the inter-unit
# lines, 256 KiB each way through the host link's serial path (no byte lost,
# duplicated or reordered; tests/board/link/render_link.sh: the fast path).  The host link's speed with 8 MiB each way is a benchmark
# (tests/bench/bench_channels.sh): the test moves less so that it holds on a
# busy machine too.
. "$(dirname "$0")/../lib.sh"
board_ready channels_status channels_ping channels_imsu channels_stress \
    channels_link-sink channels_link-source || exit 0
board_selftest channels --ncs 8 --link serial --bytes $((1 << 18)) status ping imsu stress \
    link-sink link-source
