#!/usr/bin/env bash
# tests/images/cones.sh: cones and cylinders through the host tools.
# Paper mode keeps the paper's four primitives: --paper, and `options {
# paper on }` in the scene, facet every cone and cylinder (16 sides round,
# a fan over each capped end) and say so once on stderr; export-pov writes
# them as POV-Ray's cone and cylinder, open where open.  The scene is the
# POV-Ray check's (scenes/pov/cylinders.scn: two capped cylinders, a capped
# pointed cone and an open frustum).
# Prints "PASS name" / "FAIL name: why" per check.
set -u
cd "$(dirname "$0")/../.."
out=$(mktemp -d /tmp/links1-cones.XXXXXX)
trap 'rm -rf "$out"' EXIT
scn=scenes/pov/cylinders.scn

# paper_once NAME STDERR WORDS: WORDS once in STDERR.
paper_once() {
    local n
    n=$(grep -c -- "$3" "$2")
    if [ "$n" = 1 ]; then
        echo "PASS $1"
    else
        echo "FAIL $1: '$3' printed $n times: $(head -n 3 "$2" | tr '\n' ' ')"
    fi
}

build/links1 ref "$scn" --paper --size 32x24 -o "$out/paper.ppm" 2>"$out/paper.err" >/dev/null
paper_once cones_paper_option_says "$out/paper.err" \
    '^--paper: 4 cones/cylinders faceted (16 sides round'
sed 's/options { ambient_shadowed off }/options { ambient_shadowed off paper on }/' "$scn" \
    >"$out/paper_on.scn"
build/links1 ref "$out/paper_on.scn" --size 32x24 -o "$out/paper_on.ppm" \
    2>"$out/paper_on.err" >/dev/null
paper_once cones_paper_scene_says "$out/paper_on.err" '^paper mode: 4 cones/cylinders faceted'

# the facets: 1 box, 2 capped cylinders of 32 + 2 x 14, a capped pointed
# cone of 16 + 14, an open frustum of 32
line=$(build/links1 compile "$scn" -o "$out/paper.l1s" --paper 2>/dev/null)
plain=$(build/links1 compile "$scn" -o "$out/plain.l1s" 2>/dev/null)
if [[ $line == *"(183 primitives"* && $plain == *"(5 primitives"* ]]; then
    echo "PASS cones_paper_facets"
else
    echo "FAIL cones_paper_facets: want 183 primitives with --paper, 5 without: '$line' '$plain'"
fi

if ! build/links1 export-pov "$scn" -o "$out/c.pov" --strict 2>"$out/pov.err"; then
    echo "FAIL cones_export_pov: export-pov --strict refused: $(tail -n 1 "$out/pov.err")"
else
    cyl=$(grep -c '^cylinder { <-2, 0, 0.5>, <-2, 1.6, 0.5>, 0.6$\|^cylinder { <-1.2, 0.3, -1.6>, <1.2, 0.3, -1.9>, 0.3$' "$out/c.pov")
    cone=$(grep -c '^cone { <0, 0, 0>, 0.8, <0, 2, 0>, 0$\|^cone { <0, -0.7, 0>, 0.35, <0, 0.7, 0>, 0.7 open$' "$out/c.pov")
    if [ "$cyl" = 2 ] && [ "$cone" = 2 ] && ! grep -q '^triangle' "$out/c.pov"; then
        echo "PASS cones_export_pov"
    else
        echo "FAIL cones_export_pov: want 2 cylinders and 2 cones (one open), no triangles:" \
            "$(grep -E '^(cylinder|cone|triangle)' "$out/c.pov" | head -n 5 | tr '\n' ' ')"
    fi
fi
