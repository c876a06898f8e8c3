# tests/bench/bench_args.sh: the arguments of a script that measures into
# DIR and charts what it measured (bench_aa.sh, tests/sweeps/pareto.sh);
# sourced from the top of the tree.
#   bench_args NAME DEFAULT_DIR "$@"
# sets out (--out DIR, else DEFAULT_DIR) and CHARTS_ONLY (1 with
# --charts-only); any other word prints "usage: NAME [--out DIR]
# [--charts-only]" and exits 2.
bench_args() {
    local name=$1
    out=$2
    shift 2
    CHARTS_ONLY=0
    while [ $# -gt 0 ]; do
        case $1 in
        --out) out=$2; shift 2 ;;
        --charts-only) CHARTS_ONLY=1; shift ;;
        *) echo "usage: $name [--out DIR] [--charts-only]" >&2; exit 2 ;;
        esac
    done
}

# bench_measuring: true unless --charts-only, which runs nothing and draws
# the charts again from what DIR holds.
bench_measuring() { [ "$CHARTS_ONLY" = 0 ]; }
