#!/usr/bin/env bash
# render_faults_silent.sh with every pairing of hang and silent stop with 1
# and 3 of 4 NCs failing (`make test-full`).
RENDER_FAULTS_SILENT_ALL=1 exec bash "$(dirname "$0")/render_faults_silent.sh"
