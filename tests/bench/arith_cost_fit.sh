#!/usr/bin/env bash
# arith_cost_fit.sh: the board cost model behind `--arith auto`
# (host-tools/scene/arith_cost.c, docs/results/arith-auto.md).
#
# For each calibration scene (the four scenes of bench_arith and sweep
# scenes of every family) and each board firmware (float, soft, fixed): one
# board render at SIZE (default 64x48) with --count-insns, 2 NCs.  The
# board prints the frame's work (pixels, rays, box and primitive tests) and
# the NCs' guest instructions.  A least-squares fit per arithmetic gives
# NC instructions as
#     a * pixels + b * (shadow + secondary rays) + c * box tests + d * primitive tests
# and the script prints the coefficients (the table of arith_cost.c), then
# each scene's measured and estimated instructions per pixel and the error.
#   bash tests/bench/arith_cost_fit.sh [--out DIR]
set -u
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
SIZE=${FIT_SIZE:-64x48}
out=build/arith-cost
[ "${1:-}" = --out ] && out=$2
mkdir -p "$out"
fail() { echo "arith_cost_fit: $*" >&2; exit 1; }

scenes=()
for s in demo glass molecule city; do
    scenes+=("$(scene_of $s)")
done
for fk in scale:1 scale:10 cluster_scale:0.3 grazing:10 coincident:0.001 thin_triangles:100 \
    thin_triangles:3000 tir_chain:2 tir_chain:8 ellipsoid_ratio:10 ellipsoid_ratio:1000 \
    map_repeat:1 map_repeat:100; do
    scn=$out/${fk/:/-}.scn
    python3 host-tools/gen/make_scene.py "${fk%%:*}" "${fk#*:}" --size "$SIZE" >"$scn" || exit 1
    scenes+=("$scn")
done

data=$out/fit.tsv
printf 'scene\tarith\tpixels\trays\tbox\tprim\tinsns\n' >"$data"
for scn in "${scenes[@]}"; do
    for arith in float soft fixed; do
        log=$out/$(basename "$scn" .scn)-$arith.log
        timeout 300 "$LINKS1" render --count-insns "$scn" --arith "$arith" --ncs 2 \
            --size "$SIZE" -o "$out/img.png" >"$log" 2>&1 ||
            fail "$scn --arith $arith: $(tail -n 1 "$log")"
        python3 - "$log" "$scn" "$arith" >>"$data" <<'PY' || fail "cannot read $log"
import re, sys
t = open(sys.argv[1]).read()
r = re.search(r"rays (\d+) primary, (\d+) shadow, (\d+) reflection, (\d+) refraction, "
              r"(\d+) transmission; tests (\d+) box, (\d+) primitive", t)
n = re.search(r"NCs total (\d+)", t)
p, sh, rf, rr, tr, box, prim = (int(x) for x in r.groups())
print("\t".join(str(x) for x in (sys.argv[2], sys.argv[3], p, sh + rf + rr + tr, box, prim,
                                 int(n.group(1)))))
PY
    done
done

python3 - "$data" <<'PY'
import sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])][1:]

def solve(a, b):  # Gaussian elimination with partial pivoting
    n = len(b)
    m = [a[i][:] + [b[i]] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(n):
            if r != c:
                f = m[r][c] / m[c][c]
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return [m[i][n] / m[i][i] for i in range(n)]

print("| arithmetic | per pixel | per ray (shadow, secondary) | per box test | per primitive test | largest error of the fit |")
print("|---|---|---|---|---|---|")
details = []
for arith in ("float", "soft", "fixed"):
    sel = [r for r in rows if r[1] == arith]
    # relative least squares: each scene weighted by 1 / its instructions
    xs = [[float(v) / float(r[6]) for v in r[2:6]] for r in sel]
    ata = [[sum(x[i] * x[j] for x in xs) for j in range(4)] for i in range(4)]
    atb = [sum(x[i] for x in xs) for i in range(4)]
    c = solve(ata, atb)
    worst = 0
    for r in sel:
        est = sum(ci * float(v) for ci, v in zip(c, r[2:6]))
        err = est / float(r[6]) - 1
        worst = max(worst, abs(err))
        details.append((r[0], arith, float(r[6]) / float(r[2]), est / float(r[2]), err))
    print("| %s | %.0f | %.0f | %.0f | %.0f | %.1f%% |" % (arith, c[0], c[1], c[2], c[3], 100 * worst))
print()
print("| scene | arithmetic | measured NC insns/pixel | estimated | error |")
print("|---|---|---|---|---|")
for s, a, m, e, err in details:
    print("| %s | %s | %.0f | %.0f | %+.1f%% |" % (s.split("/")[-1], a, m, e, 100 * err))
PY
