#!/usr/bin/env bash
# A film made as the frames come: `links1 render --frames A:B -o OUT.mp4`
# (and .apng) pipes each frame as a PNG into ffmpeg.  ffprobe counts the
# frames and reads the size of each film (an odd size padded to even for
# .mp4, kept for .apng) and the frame rate --fps asked for; the animated PNG's first frame is the host build's
# frame pixel for pixel; a missing ffmpeg is refused before the board
# boots, and an ffmpeg that fails is named with its message; neither leaves
# a file named OUT (or anything else) beside it.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
CHECKS="render_film_mp4_frames render_film_mp4_size render_film_mp4_fps render_film_apng_frames render_film_apng_size
        render_film_apng_first_frame render_film_no_ffmpeg render_film_ffmpeg_fails"
board_ready $CHECKS || exit 0
if ! command -v ffprobe >/dev/null; then
    checks_fail "ffprobe is not installed (the Debian package ffmpeg)" $CHECKS
    exit 0
fi
SIZE=63x47 # odd both ways
films="$RENDER_TMP/films"
mkdir -p "$films"

# probe FILM: "FRAMES WIDTHxHEIGHT" as ffprobe counts and reads them
probe() {
    ffprobe -v error -count_frames -select_streams v:0 \
        -show_entries stream=nb_read_frames,width,height -of csv=p=0 "$1" 2>&1 |
        awk -F, 'NF == 3 { print $3, $1 "x" $2 }'
}
# want NAME GOT WANT
want() {
    if [ "$2" = "$3" ]; then echo "PASS $1"; else echo "FAIL $1: got '$2', want '$3'"; fi
}

if render_board render_film "$films/fly.mp4" scenes/fly.scn -o "$films/fly.mp4" \
    scenes/fly.scn -o "$films/fly.apng" --ncs 3 --size $SIZE --frames 2:5 --fps 6; then
    read -r n s < <(probe "$films/fly.mp4")
    want render_film_mp4_frames "${n:-none}" 4
    want render_film_mp4_size "${s:-none}" 64x48 # padded to even for yuv420p
    want render_film_mp4_fps "$(ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate \
        -of csv=p=0 "$films/fly.mp4" 2>&1)" 6/1
    read -r n s < <(probe "$films/fly.apng")
    want render_film_apng_frames "${n:-none}" 4
    want render_film_apng_size "${s:-none}" $SIZE
    ref=$(render_ref scenes/fly.scn float $SIZE 2:2)
    ffmpeg -v error -i "$films/fly.apng" -frames:v 1 -f image2 -c:v ppm -pix_fmt rgb24 \
        "$RENDER_TMP/apng0.ppm" 2>&1
    render_same render_film_apng_first_frame "${ref%.ppm}-0002.ppm" "$RENDER_TMP/apng0.ppm"
fi

# No ffmpeg in PATH: refused before a board boots, nothing written.
nopath="$RENDER_TMP/nopath"
mkdir -p "$nopath" "$RENDER_TMP/bin"
ln -s "$(command -v qemu-system-arm)" "$RENDER_TMP/bin/qemu-system-arm"
to=$(command -v timeout)
out=$(PATH="$RENDER_TMP/bin" "$to" 60 "$LINKS1" render scenes/fly.scn -o "$nopath/f.mp4" \
    --ncs 1 --size 32x24 --frames 0:1 2>&1)
rc=$?
if [ $rc -ne 0 ] && echo "$out" | grep -q "needs the ffmpeg command, which is not in PATH" &&
    [ -z "$(ls -A "$nopath")" ] && ! echo "$out" | grep -q "loaded:"; then
    echo "PASS render_film_no_ffmpeg"
else
    echo "FAIL render_film_no_ffmpeg: exit $rc, files: $(ls -A "$nopath" | tr '\n' ' '), said: $out"
fi

# An ffmpeg that fails: its exit and message named, nothing left beside OUT.
fake="$RENDER_TMP/fake"
failed="$RENDER_TMP/failed"
mkdir -p "$fake" "$failed"
cat >"$fake/ffmpeg" <<'EOF'
#!/bin/sh
head -c 100 >/dev/null
echo "fake ffmpeg: no encoder here" >&2
exit 3
EOF
chmod +x "$fake/ffmpeg"
out=$(PATH="$fake:$PATH" timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet scenes/fly.scn \
    -o "$failed/f.mp4" --ncs 1 --size 32x24 --frames 0:1 2>&1)
rc=$?
echo "--- links1 render with a failing ffmpeg (exit $rc)"; echo "$out" | sed 's/^/    /'
if [ $rc -ne 0 ] && echo "$out" | grep -q "f.mp4: ffmpeg exited 3 .*: fake ffmpeg: no encoder here" &&
    [ -z "$(ls -A "$failed")" ]; then
    echo "PASS render_film_ffmpeg_fails"
else
    echo "FAIL render_film_ffmpeg_fails: exit $rc, files left: $(ls -A "$failed" | tr '\n' ' ')"
fi
