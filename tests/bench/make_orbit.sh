#!/usr/bin/env bash
# tests/bench/make_orbit.sh N FRAMES OUT.scn: SPD tetra N (written by
# links1-spd, 4^N triangles) turned into an animation of FRAMES frames in
# which only the camera moves (two camera keys: from SPD's view to one
# nearer the tetrahedron's side) and nothing of the scene does: with
# --world-space the DM keeps every triangle's world form from frame to
# frame (bench_world.sh measures both preparations).
set -eu
cd "$(dirname "$0")/../.."
SPD=${SPD:-build/links1-spd}
[ $# -eq 3 ] || { echo "usage: make_orbit.sh N FRAMES OUT.scn" >&2; exit 2; }
n=$1 frames=$2 out=$3
case $n$frames in *[!0-9]*) echo "make_orbit.sh: N and FRAMES are numbers" >&2; exit 2 ;; esac
[ "$frames" -ge 2 ] || { echo "make_orbit.sh: at least 2 frames" >&2; exit 2; }
tmp=$(mktemp /tmp/links1-orbit.XXXXXX.scn)
trap 'rm -f "$tmp"' EXIT
"$SPD" tetra "$n" -o "$tmp" >/dev/null
awk -v last=$((frames - 1)) '
    !done && /^camera \{.*\}$/ {
        sub(/\}$/, " key 0 { }  key " last " { eye 2.4 2.8 -2.4 } }")
        print
        print "animation { frames " last + 1 " }"
        done = 1
        next
    }
    { print }
    END { if (!done) exit 1 }' "$tmp" >"$out"
