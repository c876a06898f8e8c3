#!/usr/bin/env bash
# tests/bench/make_spin.sh N FRAMES OUT.scn: SPD tetra N (written by
# links1-spd, 4^N triangles) turned into an animation of FRAMES frames in
# which the whole tetrahedron spins a quarter turn about the vertical axis
# (one cluster with two keys): every triangle moves every frame, so the DM
# prepares all of them anew each frame (bench_pipeline.sh measures how much
# of that the NCs' rendering hides).
set -eu
cd "$(dirname "$0")/../.."
SPD=${SPD:-build/links1-spd}
[ $# -eq 3 ] || { echo "usage: make_spin.sh N FRAMES OUT.scn" >&2; exit 2; }
n=$1 frames=$2 out=$3
case $n$frames in *[!0-9]*) echo "make_spin.sh: N and FRAMES are numbers" >&2; exit 2 ;; esac
[ "$frames" -ge 2 ] || { echo "make_spin.sh: at least 2 frames" >&2; exit 2; }
tmp=$(mktemp /tmp/links1-spin.XXXXXX.scn)
trap 'rm -f "$tmp"' EXIT
"$SPD" ${SPIN_DB:-tetra} "$n" -o "$tmp" >/dev/null
# the primitives (every line from the first triangle on) go into the cluster
awk -v last=$((frames - 1)) '
    !inside && /^triangle / {
        print "animation { frames " last + 1 " }"
        print "cluster spin {"
        print "  key 0 { rotate 0 0 0 }"
        print "  key " last " { rotate 0 90 0 }"
        inside = 1
    }
    { print }
    END { if (inside) print "}"; else exit 1 }' "$tmp" >"$out"
