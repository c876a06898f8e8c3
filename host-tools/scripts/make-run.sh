#!/usr/bin/env bash
# make-run.sh: what `make run` does after building: render the default scene
# (scenes/demo.scn) on the default board (DM, RC and 8 NCs) with the default
# settings, showing progress, into out/demo.png.
set -eu
cd "$(dirname "$0")/../.."
LINKS1=build/links1
mkdir -p out
"$LINKS1" render scenes/demo.scn -o out/demo.png --quiet
echo "make run: wrote out/demo.png"
