#!/usr/bin/env bash
# tests/images/ref_film.sh: `links1 ref --frames A:B -o OUT.webm|.apng`
# makes one film through ffmpeg, as `links1 render` does (its board test:
# tests/board/render/render_film.sh).  ffprobe counts the frames of a VP9 film and
# reads its size (odd, padded to even); the animated PNG's frames are the
# numbered PNGs' pixel for pixel; without ffmpeg in PATH the film is
# refused and nothing is written.
# Prints "PASS ref_film_NAME" / "FAIL ref_film_NAME: why".
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
T=$(mktemp -d /tmp/links1-ref-film.XXXXXX)
trap 'rm -rf "$T"' EXIT
if ! command -v ffprobe >/dev/null; then
    for c in webm apng_frames no_ffmpeg; do
        echo "FAIL ref_film_$c: ffprobe is not installed (the Debian package ffmpeg)"
    done
    exit 0
fi

"$LINKS1" ref scenes/fly.scn --arith float --size 33x25 --frames 3:5 -o "$T/f.webm" >"$T/webm.log" 2>&1
got=$(ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=nb_read_frames,width,height -of csv=p=0 "$T/f.webm" 2>&1)
if [ "$got" = "34,26,3" ]; then
    echo "PASS ref_film_webm"
else
    echo "FAIL ref_film_webm: ffprobe says '$got', want 34,26,3 (33x25 padded, 3 frames): $(tail -n 1 "$T/webm.log")"
fi

"$LINKS1" ref scenes/fly.scn --arith float --size 33x25 --frames 3:5 -o "$T/f.apng" >"$T/apng.log" 2>&1
"$LINKS1" ref scenes/fly.scn --arith float --size 33x25 --frames 3:5 -o "$T/f.ppm" >"$T/ppm.log" 2>&1
ffmpeg -v error -i "$T/f.apng" -f image2 -c:v ppm -pix_fmt rgb24 "$T/a-%d.ppm" >"$T/dec.log" 2>&1
bad=""
for k in 1 2 3; do
    cmp -s "$T/a-$k.ppm" "$T/f-000$((k + 2)).ppm" || bad="$bad $((k + 2))"
done
if [ -z "$bad" ] && [ ! -e "$T/a-4.ppm" ]; then
    echo "PASS ref_film_apng_frames"
else
    echo "FAIL ref_film_apng_frames: frames$bad differ from the numbered images (or are missing, or more came): $(cat "$T/apng.log" "$T/dec.log" | tail -n 2)"
fi

mkdir -p "$T/none"
out=$(PATH=/nonexistent "$LINKS1" ref scenes/fly.scn --size 16x12 --frames 0:1 -o "$T/none/f.mp4" 2>&1)
rc=$?
if [ $rc -ne 0 ] && echo "$out" | grep -q "needs the ffmpeg command" && [ -z "$(ls -A "$T/none")" ]; then
    echo "PASS ref_film_no_ffmpeg"
else
    echo "FAIL ref_film_no_ffmpeg: exit $rc, files $(ls -A "$T/none" | tr '\n' ' '), said: $out"
fi
