#!/usr/bin/env bash
# tests/images/spd_official.sh: links1-spd's scenes against the SPD's own
# output (tests/spd/official/, sizes 1 and 2 of every database, made by Eric
# Haines's programs): for each, the text scene links1-spd writes and the
# official NFF file rendered by `links1 ref` (double, at 128x128: the
# scenes' own 512x512 is four times more pixels to say the same) give the
# same image, bit for bit; and links1-spd's NFF is the official file.
# Prints "PASS spd_official_NAME" / "FAIL spd_official_NAME: why".
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/spd
mkdir -p "$out"
for nff in tests/spd/official/*.nff; do
    name=$(basename "$nff" .nff)
    db=${name%[0-9]*} size=${name##*[a-z]}
    t="spd_official_$name"
    if ! build/links1-spd "$db" "$size" -o "$out/$name.scn" 2>"$out/$name.log" ||
       ! build/links1-spd "$db" "$size" -o "$out/$name.nff" 2>>"$out/$name.log"; then
        echo "FAIL $t: links1-spd $db $size: $(tail -n 1 "$out/$name.log")"
        continue
    fi
    if ! cmp -s "$out/$name.nff" "$nff"; then
        echo "FAIL $t: links1-spd $db $size -o X.nff differs from $nff"
        continue
    fi
    if ! build/links1 ref "$out/$name.scn" --size 128x128 -o "$out/$name-scn.ppm" >"$out/$name-scn.log" 2>&1; then
        echo "FAIL $t: links1 ref of links1-spd's scene: $(tail -n 1 "$out/$name-scn.log")"
    elif ! build/links1 ref "$nff" --size 128x128 -o "$out/$name-nff.ppm" >"$out/$name-nff.log" 2>&1; then
        echo "FAIL $t: links1 ref $nff: $(tail -n 1 "$out/$name-nff.log")"
    elif ! cmp -s "$out/$name-scn.ppm" "$out/$name-nff.ppm"; then
        echo "FAIL $t: the images of $out/$name.scn and $nff differ"
    else
        echo "PASS $t"
    fi
done
