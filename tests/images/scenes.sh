#!/usr/bin/env bash
# tests/images/scenes.sh: every scene in scenes/ and every scene `make`
# writes into build/scenes/ (host-tools/gen/) compiles, its compiled form
# loads and renders on the host (the same loader the board runs), and the
# animation's frames differ from one another.
# Prints "PASS scene_NAME" / "FAIL scene_NAME: why" and "PASS anim_frames_move".
set -u
cd "$(dirname "$0")/../.."
out=build/test-images/scenes
mkdir -p "$out"
for scn in scenes/*.scn scenes/pov/*.scn build/scenes/*.scn; do
    name=$(basename "$scn" .scn)
    if ! err=$(build/links1 compile "$scn" -o "$out/$name.l1s" 2>&1); then
        echo "FAIL scene_$name: compile: $err"
    elif ! err=$(build/links1 ref "$out/$name.l1s" -o "$out/$name.png" 2>&1); then
        echo "FAIL scene_$name: ref of the compiled form: $err"
    else
        echo "PASS scene_$name"
    fi
done
rm -f "$out"/anim-*.ppm
build/links1 ref scenes/anim.scn --frames 0:3 -o "$out/anim.ppm" 2>/dev/null
frames=()
for f in 0 1 2 3; do
    frames+=("$out/anim-000$f.ppm")
done
same=""
for i in 0 1 2; do
    if cmp -s "${frames[$i]}" "${frames[$((i + 1))]}"; then
        same="$same $i=$((i + 1))"
    fi
done
if [ -z "$same" ] && [ -s "${frames[3]}" ]; then
    echo "PASS anim_frames_move"
else
    echo "FAIL anim_frames_move: identical or missing frames:$same"
fi
if build/links1 ref scenes/anim.scn --frame 4 -o "$out/anim-4.ppm" 2>/dev/null ||
   [ -e "$out/anim-4.ppm" ]; then
    echo "FAIL anim_frame_out_of_range: frame 4 of a 4-frame scene was rendered"
else
    echo "PASS anim_frame_out_of_range"
fi

# A broken scene: the error names file:line:col and nothing is written.
bad="$out/broken.scn"
printf 'light point { position 0 5 0 }\nmaterial m { }\nsphere { material m radius -2 }\n' >"$bad"
rm -f "$out"/broken.l1s*
msg=$(build/links1 compile "$bad" -o "$out/broken.l1s" 2>&1)
rc=$?
if [ $rc -ne 0 ] && ! compgen -G "$out/broken.l1s*" >/dev/null &&
   [[ "$msg" == "$bad:3:28: radius must be"* ]]; then
    echo "PASS compile_error_writes_nothing"
else
    echo "FAIL compile_error_writes_nothing: status $rc, message '$msg'"
fi

# POV-Ray cannot render the demo the same way: --strict refuses it by name.
if msg=$(build/links1 export-pov scenes/demo.scn -o "$out/demo.pov" --strict 2>&1); then
    echo "FAIL export_pov_strict_refuses: the demo was exported with --strict"
elif [[ "$msg" == *"POV-Ray cannot render this scene the same way"* ]]; then
    echo "PASS export_pov_strict_refuses"
else
    echo "FAIL export_pov_strict_refuses: message '$msg'"
fi

# An empty compiled scene: links1 ref and links1 render (before any board
# boots) refuse it with the same message, and write nothing.
empty="$out/empty.l1s"
: >"$empty"
rm -f "$out"/empty-*.png
ref_msg=$(build/links1 ref "$empty" -o "$out/empty-ref.png" 2>&1)
ref_rc=$?
render_msg=$(build/links1 render "$empty" -o "$out/empty-render.png" 2>&1)
render_rc=$?
want="$empty: empty file, not a compiled scene"
if [ $ref_rc -ne 0 ] && [ $render_rc -ne 0 ] && [ "$ref_msg" = "links1 ref: $want" ] &&
   [ "$render_msg" = "links1 render: $want" ] && ! compgen -G "$out/empty-*.png" >/dev/null; then
    echo "PASS empty_l1s_refused_by_ref_and_render"
else
    echo "FAIL empty_l1s_refused_by_ref_and_render: ref (status $ref_rc) '$ref_msg'," \
         "render (status $render_rc) '$render_msg'"
fi
