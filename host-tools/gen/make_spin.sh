#!/usr/bin/env bash
# host-tools/gen/make_spin.sh N FRAMES OUT.scn [camera|ball]: SPD tetra N (written
# by links1-spd, 4^N triangles) turned into an animation of FRAMES frames.
# By default the whole tetrahedron spins a quarter turn about the vertical
# axis (one cluster with two keys): every triangle moves every frame, so
# the DM prepares all of them anew each frame (bench_pipeline.sh measures
# how much of that the NCs' rendering hides).  With "camera" nothing of the
# scene moves and the camera does (two camera keys: from SPD's view to one
# nearer the tetrahedron's side): with --world-space the DM keeps every
# triangle's world form from frame to frame (bench_world.sh).  With "ball"
# the tetrahedron and the camera stay and a small sphere (a cluster of its
# own, two keys) passes in front of it: with --world-space the DM prepares
# the sphere's cluster again and keeps every triangle.
set -eu
cd "$(dirname "$0")/../.."
SPD=${SPD:-build/links1-spd}
[ $# -eq 3 ] || [ $# -eq 4 ] || { echo "usage: make_spin.sh N FRAMES OUT.scn [camera|ball]" >&2; exit 2; }
n=$1 frames=$2 out=$3 move=${4:-spin}
case $n$frames in *[!0-9]*) echo "make_spin.sh: N and FRAMES are numbers" >&2; exit 2 ;; esac
[ "$frames" -ge 2 ] || { echo "make_spin.sh: at least 2 frames" >&2; exit 2; }
case $move in spin | camera | ball) ;; *) echo "make_spin.sh: the fourth argument is camera, ball or nothing" >&2; exit 2 ;; esac
tmp=$(mktemp /tmp/links1-spin.XXXXXX.scn)
trap 'rm -f "$tmp"' EXIT
"$SPD" ${SPIN_DB:-tetra} "$n" -o "$tmp" >/dev/null
if [ "$move" = camera ]; then
    # the camera line gets the keys, the animation its frames
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
    exit 0
fi
if [ "$move" = ball ]; then
    # the animation's frames before the first triangle, the ball after the last
    awk -v last=$((frames - 1)) '
        !done && /^triangle / { print "animation { frames " last + 1 " }"; done = 1 }
        { print }
        END {
            if (!done) exit 1
            print "material ball { colour 0.9 0.8 0.2  dic 0.1 drc 0.6  src 0.3  phong 30 }"
            print "cluster ball {"
            print "  key 0 { translate -0.8 1.2 -0.8 }"
            print "  key " last " { translate 0.8 1.2 -0.8 }"
            print "  sphere { material ball  centre 0 0 0  radius 0.2 }"
            print "}"
        }' "$tmp" >"$out"
    exit 0
fi
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
