#!/usr/bin/env bash
# make-run.sh: what `make run` does after building: render the default scene
# (scenes/demo.scn) with the default settings, showing progress, into
# out/demo.png: on the virt board (DM, RC and 8 NCs), or with MACHINE=an521
# on five an521 boards (DM and RC on board 0, 8 NCs on boards 1..4).
set -eu
cd "$(dirname "$0")/../.."
LINKS1=build/links1
MACHINE=${MACHINE:-virt}
case $MACHINE in
virt | an521) ;;
*)
    echo "make run: MACHINE=$MACHINE: the machines are virt and an521" >&2
    exit 2
    ;;
esac
mkdir -p out
"$LINKS1" render scenes/demo.scn -o out/demo.png --quiet --machine "$MACHINE"
echo "make run: wrote out/demo.png ($MACHINE)"
