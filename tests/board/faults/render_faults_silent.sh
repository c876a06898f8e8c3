#!/usr/bin/env bash
# NCs that stop answering while a frame renders (a hang with interrupts
# off, a silent stop with interrupts on: no fault word for the RC to see)
# are caught by the RC's watchdog: the frame equals the host build's and
# the summary names them.  `make test` runs a hang of 1 of 4 NCs and a
# silent stop of 3 of 4; RENDER_FAULTS_SILENT_ALL=1 (`make test-full`,
# render_faults_silent_full.sh) the other two pairings as well.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_faults_silent || exit 0
render_faults_one render_faults_hang_1of4 scenes/demo.scn 64x48 4 1 21 hang
render_faults_one render_faults_silent_3of4 scenes/demo.scn 64x48 4 3 22 silent
if [ "${RENDER_FAULTS_SILENT_ALL:-0}" = 1 ]; then
    render_faults_one render_faults_silent_1of4 scenes/demo.scn 64x48 4 1 21 silent
    render_faults_one render_faults_hang_3of4 scenes/demo.scn 64x48 4 3 22 hang
fi
