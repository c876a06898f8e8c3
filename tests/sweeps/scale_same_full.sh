#!/usr/bin/env bash
# tests/sweeps/scale_same_full.sh (make test-full): scale_same.sh at every
# factor of its ranges.
SCALE_SAME_FULL=1 exec bash "$(dirname "$0")/scale_same.sh"
