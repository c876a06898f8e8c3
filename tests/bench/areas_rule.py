#!/usr/bin/env python3
"""areas_rule.py: the decreasing schedule's default K and guided factor for
each band of NC counts (proto/areas.c, areas_decreasing_rule), worked out
again from board traces (docs/areas.md).

    python3 tests/bench/areas_rule.py [--traces DIR] [--runs N]

Traces each of demo, glass and molecule at 512x480 on one NC (links1
render --trace; made in DIR unless there already, N of each, default 5),
then `links1 replay T --ncs 64,128,254 --balance decreasing --areas K
--guided F` for every K of the grid and F of 1 to 4.  For each band's NC
count, each scene's speed-up is the median over its traces; the pick is
the pair whose scenes all come within the smallest fraction of that
scene's best (of equals, the largest sum).  Prints the picks, the
runners-up and, per scene, the pick's speed-up.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

SCENES = ("demo", "glass", "molecule")
SIZE = "512x480"
# NC count each band of areas_decreasing_rule is judged at (its largest,
# and 254 for the last)
BANDS = ((64, 64), (128, 128), (None, 254))
# K: powers of two from 4096 to 65536 and the quarter steps between them
K_GRID = tuple(b * q // 4 for b in (4096, 8192, 16384, 32768) for q in (4, 5, 6, 7)) + (65536,)
FACTORS = (1, 2, 3, 4)
LINKS1 = os.environ.get("LINKS1", "build/links1")


def make_trace(scene, path):
    """Renders scene on one NC with --trace path (its log beside it)."""
    log = path + ".log"
    with open(log, "w") as f:
        r = subprocess.run([LINKS1, "render", f"scenes/{scene}.scn", "--size", SIZE, "--ncs", "1",
                            "--count-insns", "--trace", path, "-o", path + ".ppm"],
                           stdout=f, stderr=subprocess.STDOUT, check=False)
    if r.returncode != 0:
        sys.exit(f"areas_rule: links1 render {scene} failed (see {log})")


def speedups(trace, k, factor):
    """{ncs: speed-up} of one replay; k and factor None: the board's own
    (areas_decreasing_defaults)."""
    ncs = ",".join(str(n) for _, n in BANDS)
    pair = [] if k is None else ["--areas", str(k), "--guided", str(factor)]
    r = subprocess.run([LINKS1, "replay", trace, "--ncs", ncs, "--balance", "decreasing"] + pair,
                       capture_output=True, text=True, check=False)
    if r.returncode != 0:
        sys.exit(f"areas_rule: links1 replay {trace}: {r.stderr.strip()}")
    out = {}
    for line in r.stdout.splitlines():
        f = line.split()
        if f and f[0] == "ncs":
            out[int(f[1])] = float(f[f.index("speed-up") + 1])
    return out


def medians_of(traces, k, factor):
    """{scene: {ncs: the median speed-up over its traces}} of one pair."""
    runs = {s: [speedups(t, k, factor) for t in traces[s]] for s in SCENES}
    return {s: {n: statistics.median(r[n] for r in runs[s]) for _, n in BANDS} for s in SCENES}


def best_pairs(medians, ncs):
    """{scene: the pair of its best median speed-up on ncs NCs}."""
    return {s: max(medians, key=lambda p, s=s: medians[p][s][ncs]) for s in SCENES}


def pick(medians, ncs):
    """Every pair ranked by the rule, its pick first: (worst fraction short
    of a scene's best, -sum of speed-ups, (k, factor))."""
    best = {s: medians[p][s][ncs] for s, p in best_pairs(medians, ncs).items()}
    return sorted((max(1 - medians[p][s][ncs] / best[s] for s in SCENES),
                   -sum(medians[p][s][ncs] for s in SCENES), p) for p in medians)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--traces", help="directory of the traces (made there when missing)")
    ap.add_argument("--runs", type=int, default=10, help="traces of each scene (default 10)")
    a = ap.parse_args()
    if a.runs < 1 or a.runs > 50:
        sys.exit("areas_rule: --runs wants 1 to 50")
    tmp = None
    if not a.traces:
        tmp = tempfile.TemporaryDirectory(prefix="links1-areas-rule.")
        a.traces = tmp.name
    os.makedirs(a.traces, exist_ok=True)
    traces = {}
    for s in SCENES:
        traces[s] = []
        for i in range(1, a.runs + 1):
            path = os.path.join(a.traces, f"{s}-{i}.trace")
            if not os.path.exists(path):
                make_trace(s, path)
            traces[s].append(path)
    medians = {}
    for k in K_GRID:
        for factor in FACTORS:
            medians[(k, factor)] = medians_of(traces, k, factor)
    print(f"areas_rule: {a.runs} traces each of {', '.join(SCENES)} at {SIZE}; "
          f"K {K_GRID[0]}..{K_GRID[-1]} ({len(K_GRID)}), F {FACTORS[0]}..{FACTORS[-1]}")
    now = medians_of(traces, None, None)
    for top, ncs in BANDS:
        ranked = pick(medians, ncs)
        print(f"ncs {ncs} today's rule: " + " ".join(f"{s} {now[s][ncs]:.2f}" for s in SCENES))
        for s, (k, factor) in best_pairs(medians, ncs).items():
            print(f"ncs {ncs} best for {s}: {medians[(k, factor)][s][ncs]:.2f} at K {k} F {factor}")
        band = f"..{top}" if top else "rest"
        for i, (short, _, (k, factor)) in enumerate(ranked[:4]):
            m = medians[(k, factor)]
            print(f"band {band} ncs {ncs} {'pick' if i == 0 else 'then'} K {k} F {factor} "
                  f"short {100 * short:.2f}% " +
                  " ".join(f"{s} {m[s][ncs]:.2f}" for s in SCENES))
    return 0


if __name__ == "__main__":
    sys.exit(main())
