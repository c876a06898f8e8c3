#!/usr/bin/env bash
# make-run.sh: what `make run` does after building.
#
# Step 1 (now): boot the default board (DM, RC and 8 NCs) and show every unit
# computer reporting in, then shut it down.
# Step 2 (when `links1 render` exists): render scenes/demo.scn to
# out/demo.png with the default settings.
set -eu
cd "$(dirname "$0")/.."
LINKS1=build/links1
SMP=${SMP:-10}

"$LINKS1" boot --smp "$SMP"

# Rendering the demo scene goes here once `links1 render` exists:
#   mkdir -p out && "$LINKS1" render scenes/demo.scn -o out/demo.png
