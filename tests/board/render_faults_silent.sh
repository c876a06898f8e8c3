#!/usr/bin/env bash
# NCs that stop answering while a frame renders (a hang with interrupts
# off, a silent stop with interrupts on: no fault word for the RC to see)
# are caught by the RC's watchdog: with 1 and with all but one of 4 NCs
# failing, the frame equals the host build's and the summary names them.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/render_lib.sh"
board_ready render_faults_silent || exit 0
for kind in hang silent; do
    render_faults_one render_faults_${kind}_1of4 scenes/demo.scn 64x48 4 1 21 $kind
    render_faults_one render_faults_${kind}_3of4 scenes/demo.scn 64x48 4 3 22 $kind
done
