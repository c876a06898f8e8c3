#!/usr/bin/env bash
# tests/images/ply_binary.sh: binary PLY, both byte orders, imports and
# renders exactly as its ASCII twin (tests/models/make_ply_twins.py writes
# the three here); a PLY header line the model library cannot take, or a
# format it does not know, is still refused before the library reads it;
# and a model file that is not a regular file (a FIFO) is refused at once,
# by `links1 import` and by a scene's model statement, not read until the
# reader's 120 s deadline.
# Prints "PASS NAME" / "FAIL NAME: why".
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
T=$(mktemp -d /tmp/links1-ply-test.XXXXXX)
trap 'rm -rf "$T"' EXIT

if python3 tests/models/make_ply_twins.py "$T" && [ -s "$T/twin-le.ply" ] &&
    [ -s "$T/twin-be.ply" ] && [ -s "$T/twin-ascii.ply" ] &&
    ! cmp -s "$T/twin-le.ply" "$T/twin-be.ply"; then
    echo "PASS ply_twins_written"
else
    echo "FAIL ply_twins_written: make_ply_twins.py did not write three different files"
fi

# Each twin imported (--camera auto) and rendered on the host at 96x72.
for twin in ascii le be; do
    if ! err=$(timeout 60 "$LINKS1" import "$T/twin-$twin.ply" -o "$T/$twin.scn" \
            --camera auto 2>&1); then
        echo "FAIL ply_import_$twin: $err"
    elif ! grep -q '^ *triangle' "$T/$twin.scn"; then
        echo "FAIL ply_import_$twin: no triangle in $T/$twin.scn"
    elif ! err=$(timeout 60 "$LINKS1" ref "$T/$twin.scn" -o "$T/$twin.ppm" --size 96x72 2>&1); then
        echo "FAIL ply_import_$twin: ref: $err"
    else
        echo "PASS ply_import_$twin"
    fi
done
# The model shows (not all background), and the binary twins' scenes
# and pictures are the ASCII twin's, byte for byte.
if n=$(python3 tests/images/ppm_stat.py "$T/ascii.ppm" covered 2>/dev/null) &&
    [[ $n =~ ^[0-9]+$ ]] && [ "$n" -ge 200 ]; then
    echo "PASS ply_ascii_shows"
else
    echo "FAIL ply_ascii_shows: ${n:-no} pixels of the model in $T/ascii.ppm"
fi
for twin in le be; do
    if [ -s "$T/$twin.ppm" ] && cmp -s "$T/ascii.ppm" "$T/$twin.ppm" &&
        cmp -s "$T/ascii.scn" "$T/$twin.scn"; then
        echo "PASS ply_${twin}_same_as_ascii"
    else
        echo "FAIL ply_${twin}_same_as_ascii: the scene or the image differs from the ASCII twin's"
    fi
done

# refused PLY headers: exit 1, the line named, no scene
refused() { # NAME WANT HEADER-LINE
    local name=$1 want=$2 line=$3 err rc
    sed "s/^format ascii 1.0\$/$line/" "$T/twin-ascii.ply" >"$T/$name.ply"
    err=$(timeout 20 "$LINKS1" import "$T/$name.ply" -o "$T/$name.scn" --camera auto 2>&1)
    rc=$?
    if [ $rc -ne 1 ] || ! grep -qF -- "$want" <<<"$err" || [ -e "$T/$name.scn" ]; then
        echo "FAIL ply_refuses_$name: exit $rc: $err"
    else
        echo "PASS ply_refuses_$name"
    fi
}
refused unknown_format "a PLY header line the model library cannot take, refused before it reads the file: 'format binary_middle_endian 1.0'" \
    "format binary_middle_endian 1.0"
refused extra_word "'format binary_little_endian 1.0 x'" "format binary_little_endian 1.0 x"

# A FIFO as the model: refused within a second, naming it.
mkfifo "$T/fifo.obj"
start=$(date +%s%N)
err=$(timeout 10 "$LINKS1" import "$T/fifo.obj" -o "$T/fifo.scn" --camera auto 2>&1)
rc=$?
ms=$((($(date +%s%N) - start) / 1000000))
if [ $rc -eq 1 ] && [ $ms -lt 1000 ] &&
    grep -qF "links1 import: $T/fifo.obj: not a regular file (a FIFO): not read" <<<"$err"; then
    echo "PASS model_fifo_refused ($ms ms)"
else
    echo "FAIL model_fifo_refused: exit $rc after $ms ms: $err"
fi
printf 'light point { position 0 5 -5 }\nmaterial m { colour 1 0 0 }\nmodel { file "fifo.obj"  material m }\n' \
    >"$T/fifo_stmt.scn"
start=$(date +%s%N)
err=$(timeout 10 "$LINKS1" compile "$T/fifo_stmt.scn" -o "$T/fifo_stmt.l1s" 2>&1)
rc=$?
ms=$((($(date +%s%N) - start) / 1000000))
if [ $rc -eq 1 ] && [ $ms -lt 1000 ] && grep -qF "$T/fifo.obj: not a regular file (a FIFO)" <<<"$err"; then
    echo "PASS model_fifo_statement_refused ($ms ms)"
else
    echo "FAIL model_fifo_statement_refused: exit $rc after $ms ms: $err"
fi
