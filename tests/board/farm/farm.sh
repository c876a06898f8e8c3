#!/usr/bin/env bash
# links1 farm on this machine alone (a hosts file of ':'): three frames of
# scenes/anim.scn farmed through GNU parallel equal one board's
# `links1 render --frames 0:2` byte for byte, one job at a time (a host
# written 2/: runs two at once); with one frame deleted, a
# second farm renders only that frame (parallel's joblog holds one job, the
# other frames are not rewritten); a scene and a DIR with spaces, quotes and
# $ in their names farm as well; a missing parallel, one not GNU's, an empty or unreadable
# hosts file, a DIR that is a file or another user's, --slurm with no
# sbatch and --slurm beside --hosts are refused, naming the problem, before
# anything runs.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
CHECKS="farm_frame0 farm_frame1 farm_frame2 farm_summary farm_one_slot farm_two_slots farm_resume_one_job farm_resume_kept
        farm_resume_frame1 farm_film farm_bands farm_rows_band farm_band_refused farm_hostile_names farm_no_parallel farm_not_gnu_parallel farm_empty_hosts
        farm_unreadable_hosts farm_dir_is_file farm_dir_not_yours farm_slurm_no_sbatch farm_slurm_and_hosts"
board_ready $CHECKS || exit 0
if ! command -v parallel >/dev/null; then
    checks_fail "GNU parallel is not installed (the Debian package parallel)" $CHECKS
    exit 0
fi
SIZE=32x24
T=$RENDER_TMP
echo : >"$T/hosts"
render_board farm_ref "$T/ref.ppm" scenes/anim.scn -o "$T/ref.ppm" --size $SIZE --frames 0:2 || exit 0

want() { # NAME GOT WANT
    if [ "$2" = "$3" ]; then echo "PASS $1"; else echo "FAIL $1: got '$2', want '$3'"; fi
}

farm farm_run scenes/anim.scn --frames 0:2 -o "$T/out" --hosts "$T/hosts" --ext ppm \
    --retries 2 -- --size $SIZE
for f in 0 1 2; do render_same farm_frame$f "$T/ref-000$f.ppm" "$T/out/frame-000$f.ppm"; done
want farm_summary "$(grep -c '^links1 farm: host :: 3 frame(s) in .* frames/min' "$T/farm_run.log")/$(
    grep -c '3 frame(s) rendered now, 0 kept from before, 0 missing' "$T/farm_run.log")" 1/1
# job slots: overlaps JOBLOG counts the jobs that start before the one
# started before them ends (parallel's joblog: column 3 start, 4 runtime)
overlaps() {
    tail -n +2 "$1" | sort -t$'\t' -k3,3g |
        awk -F'\t' 'NR > 1 && $3 < end { n++ } { end = $3 + $4 } END { print n + 0 }'
}
want farm_one_slot "$(overlaps "$T/out/farm-joblog.tsv")" 0
echo 2/: >"$T/hosts2"
farm farm_run2 scenes/anim.scn --frames 0:1 -o "$T/out2" --hosts "$T/hosts2" --ext ppm \
    -- --size $SIZE
want farm_two_slots "$(overlaps "$T/out2/farm-joblog.tsv")/$(cmp -s "$T/ref-0001.ppm" \
    "$T/out2/frame-0001.ppm" && echo same)" 1/same

# resume: frame 1 deleted; only it is rendered again
before=$(stat -c '%n %i %Y' "$T/out/frame-0000.ppm" "$T/out/frame-0002.ppm" | tr '\n' ' ')
rm -f "$T/out/frame-0001.ppm"
sleep 1 # a rewritten frame would get a later mtime
farm farm_resume scenes/anim.scn --frames 0:2 -o "$T/out" --hosts "$T/hosts" --ext ppm \
    --film "$T/farmed.apng" --fps 4 -- --size $SIZE
want farm_resume_one_job "$(tail -n +2 "$T/out/farm-joblog.tsv" | awk -F'\t' '{ print $7, $9 }' |
    grep -c -- '^0 .*--frames 0001:0001 ')/$(tail -n +2 "$T/out/farm-joblog.tsv" | wc -l)/$(
    grep -c '1 frame(s) rendered now, 2 kept from before, 0 missing' "$T/farm_resume.log")" 1/1/1
after=$(stat -c '%n %i %Y' "$T/out/frame-0000.ppm" "$T/out/frame-0002.ppm" | tr '\n' ' ')
want farm_resume_kept "$after" "$before"
render_same farm_resume_frame1 "$T/ref-0001.ppm" "$T/out/frame-0001.ppm"
# the film made from DIR once every frame is there: an animated PNG (lossless)
# whose frames, decoded by ffmpeg, are the board's frames in order
mkdir -p "$T/film"
if ffmpeg -v error -i "$T/farmed.apng" -f image2 -c:v ppm -pix_fmt rgb24 "$T/film/f%d.ppm" &&
    [ "$(ls "$T/film" | wc -l)" = 3 ] && cmp -s "$T/film/f1.ppm" "$T/ref-0000.ppm" &&
    cmp -s "$T/film/f2.ppm" "$T/ref-0001.ppm" && cmp -s "$T/film/f3.ppm" "$T/ref-0002.ppm"; then
    echo "PASS farm_film"
else
    echo "FAIL farm_film: $T/farmed.apng: $(ls "$T/film" | wc -l) frames decoded, want the board's 3 in order"
fi

# one still frame in bands: 5 bands of frame 1 (24 scanlines: 4 or 5 each),
# a job a band, stitched into DIR/frame-0001.ppm equal to the board's frame
farm farm_bands_run scenes/anim.scn --frames 1:1 --bands 5 -o "$T/bands" --hosts "$T/hosts" \
    --ext ppm -- --size $SIZE
if cmp -s "$T/ref-0001.ppm" "$T/bands/frame-0001.ppm" && [ -z "$(ls "$T/bands" | grep '^band-')" ] &&
    grep -q '5 bands stitched into' "$T/farm_bands_run.log"; then
    echo "PASS farm_bands"
else
    echo "FAIL farm_bands: $T/bands/frame-0001.ppm is not the board's frame 1 (or bands left: $(ls "$T/bands" | tr '\n' ' '))"
fi
# a band by scanlines: the frame's rows 7..19, nothing else
"$LINKS1" render scenes/anim.scn --frame 2 --size $SIZE --rows 7:19 -o "$T/rows.ppm" --quiet \
    >"$T/rows.log" 2>&1
w=${SIZE%x*}
if [ "$(head -c 2 "$T/rows.ppm" 2>/dev/null)" = P6 ] && [ "$(sed -n 2p "$T/rows.ppm")" = "$w 13" ] &&
    cmp -s <(tail -c $((w * 13 * 3)) "$T/rows.ppm") \
        <(tail -c $((w * 24 * 3)) "$T/ref-0002.ppm" | tail -c +$((w * 7 * 3 + 1)) | head -c $((w * 13 * 3))); then
    echo "PASS farm_rows_band"
else
    echo "FAIL farm_rows_band: render --rows 7:19 is not scanlines 7..19 of the board's frame 2: $(tail -n 1 "$T/rows.log")"
fi
# more bands than scanlines: refused, naming the frame's height, before a
# board boots (the compiled scene says how high its frame is)
if ! "$LINKS1" render scenes/anim.scn --size $SIZE --band 3/25 -o "$T/b.ppm" >"$T/band_bad.log" 2>&1 &&
    grep -q -- '--band 3/25: 25 bands of a frame of 24 scanlines' "$T/band_bad.log" && [ ! -e "$T/b.ppm" ] &&
    ! grep -q 'booting' "$T/band_bad.log"; then
    echo "PASS farm_band_refused"
else
    echo "FAIL farm_band_refused: $(tail -n 1 "$T/band_bad.log")"
fi

# hostile names: spaces, quotes and $ in the scene's path and in DIR
hostile="$T/a b'c\"d \$HOME e"
mkdir -p "$hostile"
cp scenes/anim.scn "$hostile/s \$x 'q'.scn"
cp -r scenes/maps "$hostile/" # the textures it names, beside it
farm farm_hostile "$hostile/s \$x 'q'.scn" --frames 2:2 -o "$hostile/out \"d\"" \
    --hosts "$T/hosts" --ext ppm -- --size $SIZE
if cmp -s "$T/ref-0002.ppm" "$hostile/out \"d\"/frame-0002.ppm"; then
    echo "PASS farm_hostile_names"
else
    echo "FAIL farm_hostile_names: no frame equal to the board's in '$hostile/out \"d\"': $(ls "$hostile" 2>&1 | tr '\n' ' ')"
fi

# refusals: each before anything runs, naming the problem
refused() { # NAME PATTERN ARGS...: exit non-zero, PATTERN in the log, no joblog made
    local name=$1 pat=$2; shift 2
    rm -rf "$T/r"
    farm "$name" "$@"
    local rc=$?
    if [ $rc -ne 0 ] && grep -q -- "$pat" "$T/$name.log" && [ ! -e "$T/r/farm-joblog.tsv" ]; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc, want a refusal naming '$pat': $(tail -n 1 "$T/$name.log")"
    fi
}
mkdir -p "$T/nopar"
for tool in timeout sed grep tail rm; do ln -sf "$(command -v $tool)" "$T/nopar/$tool"; done
PATH="$T/nopar" refused farm_no_parallel "GNU parallel is not installed" \
    scenes/anim.scn --frames 0:0 -o "$T/r" --hosts "$T/hosts"
PATH="$T/nopar" refused farm_slurm_no_sbatch "Slurm's sbatch is not installed" \
    scenes/anim.scn --frames 0:0 -o "$T/r" --slurm
refused farm_slurm_and_hosts "not both" scenes/anim.scn --frames 0:0 -o "$T/r" --slurm \
    --hosts "$T/hosts"
mkdir -p "$T/otherpar" # a 'parallel' that is not GNU's (moreutils has one)
printf '#!/bin/sh\necho "parallel [OPTIONS] command -- arguments"\n' >"$T/otherpar/parallel"
chmod +x "$T/otherpar/parallel"
PATH="$T/otherpar:$PATH" refused farm_not_gnu_parallel "is not GNU parallel" \
    scenes/anim.scn --frames 0:0 -o "$T/r" --hosts "$T/hosts"
: >"$T/empty"
printf '# only a comment\n\n' >>"$T/empty"
refused farm_empty_hosts "no host in it" scenes/anim.scn --frames 0:0 -o "$T/r" --hosts "$T/empty"
refused farm_unreadable_hosts "cannot read it" scenes/anim.scn --frames 0:0 -o "$T/r" \
    --hosts "$T/no-such-hosts"
touch "$T/afile"
refused farm_dir_is_file "not a directory" scenes/anim.scn --frames 0:0 -o "$T/afile" \
    --hosts "$T/hosts"
if [ "$(id -u)" -eq 0 ]; then
    mkdir -p "$T/theirs" && chown nobody "$T/theirs"
    refused farm_dir_not_yours "belongs to uid" scenes/anim.scn --frames 0:0 -o "$T/theirs" \
        --hosts "$T/hosts"
else # not root: a directory of root's stands for another user's
    refused farm_dir_not_yours "belongs to uid" scenes/anim.scn --frames 0:0 -o / \
        --hosts "$T/hosts"
fi
