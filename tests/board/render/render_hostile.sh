#!/usr/bin/env bash
# Hostile compiled scenes on the board (tests/hostile/): each class is
# uploaded to a running board, which must refuse it with the words the
# class names (the same the host's refusal has, test_hostile), and then
# render the next scene, a good one, equal to the host build.  Eight
# classes per board run, each followed by the good scene.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
MAKE_HOSTILE=build/tests/make_hostile
names=()
if [ -x "$MAKE_HOSTILE" ]; then
    "$MAKE_HOSTILE" "$RENDER_TMP" >"$RENDER_TMP/classes.txt" || rm -f "$RENDER_TMP/classes.txt"
fi
if [ ! -s "$RENDER_TMP/classes.txt" ]; then
    echo "FAIL render_hostile: $MAKE_HOSTILE did not write the hostile scenes (run make)"
    exit 0
fi
# working_set (a prepared frame over the DM's block) is the host's alone
# now: the board's blocks hold 184 MiB, and a scene that needs more is
# refused by the compiler before any upload (render_refuse.sh); the DM's
# own check of the bound is test_hostile's and test_blob's.
while IFS=$'\t' read -r name expect; do
    [ "$name" = working_set ] || names+=("$name")
done <"$RENDER_TMP/classes.txt"
checks=()
for n in "${names[@]}"; do checks+=("render_hostile_$n" "render_hostile_${n}_next"); done
board_ready "${checks[@]}" || exit 0

good="$RENDER_TMP/base.l1s"
ref="$RENDER_TMP/ref-base.ppm"
"$LINKS1" ref "$good" --arith float -o "$ref" >"$RENDER_TMP/ref.log" 2>&1

expect_of() { awk -F'\t' -v n="$1" '$1 == n { print $2 }' "$RENDER_TMP/classes.txt"; }

run_batch() { # $@ = class names
    local args=() n log="$RENDER_TMP/batch-$1.log" rc
    for n in "$@"; do
        args+=("$RENDER_TMP/$n.l1s" -o "$RENDER_TMP/$n.ppm" "$good" -o "$RENDER_TMP/$n-next.ppm")
    done
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 2 "${args[@]}" >"$log" 2>&1
    rc=$?
    echo "--- links1 render ${#@} hostile scenes, each followed by base.l1s (exit $rc)"
    sed 's/^/    /' "$log"
    # each refusal: the board's answer, then "links1 render: FILE was not loaded"
    awk '/the board says: / { said = $0 }
         / was not loaded$/ { f = $0; sub(/^links1 render: /, "", f); sub(/ was not loaded$/, "", f);
                              print f "\t" said; said = "" }' "$log" >"$log.refusals"
    for n in "$@"; do
        local said expect
        said=$(awk -F'\t' -v f="$RENDER_TMP/$n.l1s" '$1 == f { print $2 }' "$log.refusals")
        expect=$(expect_of "$n")
        if [ $rc -ne 1 ]; then
            echo "FAIL render_hostile_$n: links1 render exited $rc, want 1 (scenes refused)"
        elif [ -e "$RENDER_TMP/$n.ppm" ]; then
            echo "FAIL render_hostile_$n: the board rendered it"
        elif [[ "$said" == *"scene refused: "*"$expect"* ]]; then
            echo "PASS render_hostile_$n"
        else
            echo "FAIL render_hostile_$n: the board's answer '${said:-none}' lacks '$expect'"
        fi
        render_same "render_hostile_${n}_next" "$ref" "$RENDER_TMP/$n-next.ppm"
    done
}

for ((i = 0; i < ${#names[@]}; i += 8)); do
    run_batch "${names[@]:i:8}"
done
