# tests/sweeps/families.sh: the sweep families of make_scene.py and their
# knobs (sourced by sweep.sh, auto.sh and auto_model.sh).
# family|knobs, easiest first|x axis label|logscale (0/1)|same (1: the
# image should not change, so the error is against the double build at the
# first knob; 0: at the same knob)
families=(
    "scale|1 3 10 20 30 100 300 1000 10000 1000000|scene scale|1|1"
    "scale_down|1 0.3 0.1 0.05 0.03 0.01 0.001 0.0001 1e-06|scene scale|1|1"
    "cluster_scale|1 3 30 1000 10000 1000000|cluster scale|1|1"
    "cluster_scale_down|1 0.3 0.1 0.03 0.01 0.001 0.0001 1e-06|cluster scale|1|1"
    "model_scale|1 0.01 0.0001 1e-06|model node scale|1|1"
    "grazing|45 20 10 5 2 1 0.5 0.2 0.1|degrees above the floor|1|0"
    "coincident|0.1 0.01 0.003 0.001 0.0003 0.0001 0.00001|gap|1|0"
    "thin_triangles|10 100 1000 3000 10000 30000|length / width|1|0"
    "tir_chain|1 2 3 4 6 8 12 16|max_depth|0|0"
    "ellipsoid_ratio|1 10 100 300 1000 3000|axis ratio|1|0"
    "map_repeat|1 10 100 1000 3000 10000|repeats|1|0"
    "density_steps|256 64 32 24 16 8 4 2|density root-finder steps|1|1"
)

# add_host_fixed_cands [SUFFIX]: onto cands[], "fixed Qi.f|fixedF|fixed"
# and SUFFIX for each host fixed-point build next to links1
# ($BIN/links1-ref-fixedF, the Makefile's REF_FIXED_BITS), most fraction
# bits first: the host's formats, each at the fixed firmware's cost.
add_host_fixed_cands() {
    local f p
    for f in $(for p in "$BIN"/links1-ref-fixed[0-9]*; do
                   [ -x "$p" ] && echo "${p##*fixed}"
               done | sort -rn); do
        cands+=("fixed Q$((31 - f)).$f|fixed$f|fixed${1:-}")
    done
}

# family_work DIR: DIR made to hold the family scenes, with a copy of
# scenes/maps/ in it that make_scene.py's map scenes name ($MAPS): a map's
# image is read only from below its scene's directory.
family_work() {
    mkdir -p "$1/maps" && cp scenes/maps/*.png "$1/maps/" && export MAPS="$1/maps"
}

# family_scene FAMILY KNOB SIZE: the family's scene at that knob value on
# stdout (scale_down and cluster_scale_down are the scale and cluster_scale
# families below 1).
family_scene() {
    local gen=$1
    [ "$gen" = scale_down ] && gen=scale
    [ "$gen" = cluster_scale_down ] && gen=cluster_scale
    python3 host-tools/gen/make_scene.py "$gen" "$2" --size "$3"
}
