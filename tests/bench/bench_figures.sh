#!/usr/bin/env bash
# bench_figures.sh: make figures at its full size (tests/bench/figures.sh),
# into a temporary directory; prints the tables.  make figures writes the
# same into docs/figures.
set -u
out=$(mktemp -d /tmp/links1-bench-figures.XXXXXX)
trap 'rm -rf "$out"' EXIT
FIG_OUT="$out" bash "$(dirname "$0")/figures.sh"
