#!/usr/bin/env bash
# NCs that fault while a frame renders (an undefined instruction, a data
# abort) do not stop it: with 1 and with all but one of 4 NCs failing, the
# frame equals the host build's bit for bit and the summary names the
# failed NCs and the areas handed to others (roles/rc_nc.c).  With static
# balancing (one area per NC) the failed NC's area goes to one that has
# drawn its own.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_faults || exit 0
for kind in undef abort; do
    render_faults_one render_faults_${kind}_1of4 scenes/demo.scn 96x72 4 1 11 $kind
    render_faults_one render_faults_${kind}_3of4 scenes/demo.scn 96x72 4 3 12 $kind
done
render_faults_one render_faults_abort_1of4_static scenes/demo.scn 96x72 4 1 13 abort static
