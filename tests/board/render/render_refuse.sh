#!/usr/bin/env bash
# Scenes the DM must refuse, on a board that keeps running:
#  - a damaged compiled scene: refused with the loader's reason, and the
#    next scene uploaded to the same board renders, equal to the host build;
#  - a scene whose prepared frame exceeds the IMSU block: refused by the
#    host compiler before the upload, naming the limit
#    (LINKS1_IMSU_PAIR_BLOCK) and the counts; SPD teapot 64, which fits,
#    taken;
#  - a sphere of radius 1e-6 in a scene spanning 12, one step of fixed
#    Q12.19 (issue 11): the fixed DM refuses it with the host build's
#    message (links1 ref --arith fixed), and the next scene uploaded to the
#    same board renders, equal to the host build; in a cluster of its own,
#    links1 ref adds the cluster's name from the scene text;
#  - a sphere of radius 0.01 lit from 1e4 away (the tolerances stop
#    following the geometry): refused on the board after the next scene
#    with the host build's whole message (252 characters in fixed, once
#    cut at the DM's 200-character log line), naming the far light.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_refuse_bad render_refuse_next render_refuse_too_big render_fits_teapot_64 \
    render_refuse_detail render_refuse_detail_next render_refuse_detail_cluster \
    render_refuse_far_light || exit 0

good=scenes/pov/spheres.scn
damage=$(render_damaged_scene $good "$RENDER_TMP/bad.l1s") || echo "FAIL render_refuse_bad: $damage"
ref=$(render_ref $good float 160x120) # the scene's own size
log="$RENDER_TMP/refuse.log"
timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 2 "$RENDER_TMP/bad.l1s" \
    -o "$RENDER_TMP/bad.ppm" $good -o "$RENDER_TMP/next.ppm" >"$log" 2>&1
rc=$?
echo "--- links1 render bad.l1s then $good (exit $rc)"; sed 's/^/    /' "$log"
if [ -s "$RENDER_TMP/bad.l1s" ]; then
    if [ $rc -eq 1 ] && grep -qF "$RENDER_DAMAGED_REFUSAL" "$log" && [ ! -e "$RENDER_TMP/bad.ppm" ]; then
        echo "PASS render_refuse_bad"
    else
        echo "FAIL render_refuse_bad: exit $rc (want 1), an image written, or not the loader's '$RENDER_DAMAGED_REFUSAL'"
    fi
fi
render_same render_refuse_next "$ref" "$RENDER_TMP/next.ppm"

# 760,000 small spheres without the automatic hierarchy: 58 MB compiled
# (within SCN_MAX_SIZE), 206 MB prepared on the board, more than an IMSU
# block: refused by the compiler before anything is uploaded, naming the
# limit (the DM's own check of the same bound: test_blob).
python3 - "$RENDER_TMP/big.scn" <<'PY'
import sys
out = ["camera { eye 0 3 -6  look_at 0 0 0  up 0 1 0  fov 50 }", "resolution 32 24",
       "options { auto_hierarchy off }",
       "light parallel { colour 0.6 0.6 0.6  direction -1 -1.5 1 }",
       "material grass { colour 0.3 0.6 0.3 dic 0.25 drc 0.7 }"]
for i in range(760000):
    out.append("sphere { material grass centre %d 0 %d radius 0.4 }" % (i % 1000 - 500, i // 1000))
open(sys.argv[1], "w").write("\n".join(out) + "\n")
PY
log="$RENDER_TMP/big.log"
timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 1 "$RENDER_TMP/big.scn" \
    -o "$RENDER_TMP/big.ppm" >"$log" 2>&1
rc=$?
echo "--- links1 render big.scn (exit $rc)"; sed 's/^/    /' "$log"
if [ $rc -ne 0 ] && grep -q 'board memory .*(760000 primitives, 1 clusters).*LINKS1_IMSU_PAIR_BLOCK' "$log" &&
    ! grep -q 'scene upload' "$log"; then
    echo "PASS render_refuse_too_big"
else
    echo "FAIL render_refuse_too_big: exit $rc (want non-zero) or the compiler's refusal does not name LINKS1_IMSU_PAIR_BLOCK and the count"
fi

# SPD teapot 64 (269,824 triangles in 285,311 clusters, nearly all the
# automatic hierarchy's plain ones): within an IMSU block, so the compiler
# takes it (its index keeps maps for the clusters that may have them, not
# two for each cluster: 187 MB, not 214)
spd="$(dirname "$LINKS1")/links1-spd" log="$RENDER_TMP/teapot64.log"
"$spd" teapot 64 -o "$RENDER_TMP/teapot64.nff" >"$log" 2>&1 &&
    "$LINKS1" compile "$RENDER_TMP/teapot64.nff" -o "$RENDER_TMP/teapot64.l1s" >>"$log" 2>&1
rc=$?
blob=$(sed -n 's/.*on the board: blob \([0-9]*\) bytes of \([0-9]*\).*/\1 \2/p' "$log")
echo "--- links1-spd teapot 64, links1 compile (exit $rc)"; sed 's/^/    /' "$log"
if [ $rc -eq 0 ] && [ -n "$blob" ] && [ "${blob% *}" -le "${blob#* }" ]; then
    echo "PASS render_fits_teapot_64"
else
    echo "FAIL render_fits_teapot_64: exit $rc (want 0), or no blob within the block in the compiler's line"
fi
rm -f "$RENDER_TMP/teapot64.nff" "$RENDER_TMP/teapot64.l1s"

tiny=$RENDER_TMP/tiny_sphere.scn
render_tiny_sphere_scene "$tiny"
"$LINKS1" ref "$tiny" --arith fixed -o "$RENDER_TMP/tiny-host.ppm" >"$RENDER_TMP/tiny-host.log" 2>&1
want=$(sed -n 's/^links1 ref: [^:]*: //p' "$RENDER_TMP/tiny-host.log")
far=$RENDER_TMP/far_light.scn
cat >"$far" <<'EOF'
camera { eye 0 0.1 -0.3  look_at 0 0 0 }  resolution 32 24
light point { colour 1 1 1  position 1e4 1e4 -1e4 }  material m { colour 1 0 0 dic 0.2 drc 0.7 }
sphere { material m centre 0 0 0 radius 0.01 }
EOF
"$LINKS1" ref "$far" --arith fixed -o "$RENDER_TMP/far-host.ppm" >"$RENDER_TMP/far-host.log" 2>&1
want_far=$(sed -n 's/^links1 ref: [^:]*: //p' "$RENDER_TMP/far-host.log")
ref=$(render_ref $good fixed 80x60)
log="$RENDER_TMP/detail.log"
timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet --ncs 2 --arith fixed --size 80x60 "$tiny" \
    -o "$RENDER_TMP/tiny.ppm" $good -o "$RENDER_TMP/detail-next.ppm" "$far" -o "$RENDER_TMP/far.ppm" \
    >"$log" 2>&1
rc=$?
echo "--- links1 render --arith fixed tiny_sphere.scn then $good (exit $rc); the host build: $want"
sed 's/^/    /' "$log"
if [ $rc -eq 1 ] && [[ $want == "ellipsoid 1 has a radius of "* ]] &&
    grep -qF "the board says: scene refused: frame 0: $want" "$log" && [ ! -e "$RENDER_TMP/tiny.ppm" ]; then
    echo "PASS render_refuse_detail"
else
    echo "FAIL render_refuse_detail: exit $rc (want 1), or the board's refusal is not the host build's: $want"
fi
render_same render_refuse_detail_next "$ref" "$RENDER_TMP/detail-next.ppm"
if [[ $want_far == "scene spans "*"the eye or a light lies over 256 times farther out than the geometry; bring it closer" ]] &&
    grep -qF "the board says: scene refused: frame 0: $want_far" "$log" &&
    [ ! -e "$RENDER_TMP/far.ppm" ]; then
    echo "PASS render_refuse_far_light"
else
    echo "FAIL render_refuse_far_light: the board's refusal is not the host build's whole message: $want_far"
fi

sed 's/^box .*sphere.*/box { material m  min -6 -0.5 -4  max 6 0 8 }\ncluster speck { translate 0 1 0  sphere { material m centre 0 0 0 radius 0.000001 } }/' \
    "$tiny" >"$RENDER_TMP/speck.scn"
msg=$("$LINKS1" ref "$RENDER_TMP/speck.scn" --arith fixed -o "$RENDER_TMP/speck.ppm" 2>&1)
if [[ $msg == *": ellipsoid 1 has a radius of 1.91e-6; "*"; it is in cluster speck" ]] &&
    [ ! -e "$RENDER_TMP/speck.ppm" ]; then
    echo "PASS render_refuse_detail_cluster"
else
    echo "FAIL render_refuse_detail_cluster: links1 ref said '$msg'"
fi
