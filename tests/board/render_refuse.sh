#!/usr/bin/env bash
# Scenes the DM must refuse, on a board that keeps running:
#  - a damaged compiled scene: refused with the loader's reason, and the
#    next scene uploaded to the same board renders, equal to the host build;
#  - a scene whose prepared frame exceeds the IMSU block: refused by the
#    host compiler before the upload, naming the limit
#    (LINKS1_IMSU_PAIR_BLOCK) and the counts.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/render_lib.sh"
board_ready render_refuse_bad render_refuse_next render_refuse_too_big || exit 0

good=scenes/pov/spheres.scn
"$LINKS1" compile $good -o "$RENDER_TMP/bad.l1s" >/dev/null 2>&1
# Damage the first section table entry (after the 16-byte header): its
# offset points far past the end of the file.
printf '\xff\xff\xff\x7f' | dd of="$RENDER_TMP/bad.l1s" bs=1 seek=20 conv=notrunc status=none
ref=$(render_ref $good float 160x120) # the scene's own size
log="$RENDER_TMP/refuse.log"
timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 2 "$RENDER_TMP/bad.l1s" \
    -o "$RENDER_TMP/bad.ppm" $good -o "$RENDER_TMP/next.ppm" >"$log" 2>&1
rc=$?
echo "--- links1 render bad.l1s then $good (exit $rc)"; sed 's/^/    /' "$log"
if [ $rc -eq 1 ] && grep -q 'scene upload: the board says: scene refused: ' "$log" &&
    [ ! -e "$RENDER_TMP/bad.ppm" ]; then
    echo "PASS render_refuse_bad"
else
    echo "FAIL render_refuse_bad: exit $rc (want 1) or no 'scene refused' message from the board"
fi
render_same render_refuse_next "$ref" "$RENDER_TMP/next.ppm"

# 700,000 small spheres without the automatic hierarchy: 53 MB compiled
# (within SCN_MAX_SIZE), 190 MB prepared on the board, more than an IMSU
# block: refused by the compiler before anything is uploaded, naming the
# limit (the DM's own check of the same bound: test_blob).
python3 - "$RENDER_TMP/big.scn" <<'PY'
import sys
out = ["camera { eye 0 3 -6  look_at 0 0 0  up 0 1 0  fov 50 }", "resolution 32 24",
       "options { auto_hierarchy off }",
       "light parallel { colour 0.6 0.6 0.6  direction -1 -1.5 1 }",
       "material grass { colour 0.3 0.6 0.3 dic 0.25 drc 0.7 }"]
for i in range(700000):
    out.append("sphere { material grass centre %d 0 %d radius 0.4 }" % (i % 1000 - 500, i // 1000))
open(sys.argv[1], "w").write("\n".join(out) + "\n")
PY
log="$RENDER_TMP/big.log"
timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 1 "$RENDER_TMP/big.scn" \
    -o "$RENDER_TMP/big.ppm" >"$log" 2>&1
rc=$?
echo "--- links1 render big.scn (exit $rc)"; sed 's/^/    /' "$log"
if [ $rc -ne 0 ] && grep -q 'board memory .*(700000 primitives, 1 clusters).*LINKS1_IMSU_PAIR_BLOCK' "$log" &&
    ! grep -q 'scene upload' "$log"; then
    echo "PASS render_refuse_too_big"
else
    echo "FAIL render_refuse_too_big: exit $rc (want non-zero) or the compiler's refusal does not name LINKS1_IMSU_PAIR_BLOCK and the count"
fi
