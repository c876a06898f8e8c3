#!/usr/bin/env bash
# Normal and attribute maps on the board (scenes/surface_maps.scn: a
# riveted plate and ball from a normal map, a floor whose src and drc come
# from attribute maps, a glass ball whose trc does): the board's image
# equals the host build's, bit for bit, in float, soft float and fixed
# point; and with --mark-lost (the pixels that lost precision painted) in
# float and fixed, so the maps' precision flags are the host's too.  An
# imported model with a normal texture (a bent, smooth grid: the normal map
# in the frame of the triangles' texture coordinates, tests/models/
# make_normal_tex.py) equals the host build's in float, fixed, soft float
# and double.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_surface_maps_float_2nc_dynamic render_surface_maps_soft_1nc_static \
    render_surface_maps_fixed_2nc_decreasing render_maps_marked_float render_maps_marked_fixed \
    render_normal_tex_float_2nc_dynamic render_normal_tex_fixed_2nc_decreasing \
    render_normal_tex_soft_1nc_static render_normal_tex_double_2nc_static || exit 0
SIZE=96x72
scn=scenes/surface_maps.scn
render_grid_one $scn float 2 dynamic $SIZE
render_grid_one $scn soft 1 static $SIZE
render_grid_one $scn fixed 2 decreasing $SIZE
for a in float fixed; do
    name=render_maps_marked_$a
    ref=$RENDER_TMP/maps-marked-host-$a.ppm
    "$LINKS1" ref $scn --arith $a --size $SIZE --mark-lost -o "$ref" >"$ref.log" 2>&1
    out=$RENDER_TMP/$name.ppm
    render_board $name "$out" $scn -o "$out" --arith $a --ncs 2 --size $SIZE --mark-lost || continue
    render_same $name "$ref" "$out"
done

models=$RENDER_TMP/normal_tex
mkdir -p "$models"
if ! python3 host-tools/gen/make_normal_tex.py "$models" >"$models/make.log" 2>&1 ||
    ! "$LINKS1" import "$models/grid.obj" -o "$models/normal_tex.scn" --camera auto --smooth \
        >"$models/import.log" 2>&1; then
    for a in float_2nc_dynamic fixed_2nc_decreasing soft_1nc_static double_2nc_static; do
        echo "FAIL render_normal_tex_$a: no model: $(tail -n 1 "$models/make.log" "$models/import.log")"
    done
else
    render_grid_one "$models/normal_tex.scn" float 2 dynamic $SIZE
    render_grid_one "$models/normal_tex.scn" fixed 2 decreasing $SIZE
    render_grid_one "$models/normal_tex.scn" soft 1 static $SIZE
    render_grid_one "$models/normal_tex.scn" double 2 static $SIZE
fi
