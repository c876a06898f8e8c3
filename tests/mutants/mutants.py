#!/usr/bin/env python3
"""mutants.py: `make test-mutants`.  Each fault of tests/mutants/mutants.txt
is applied alone to a clean copy of the tree (the sources and the build, so
only what the fault touches is rebuilt); the tests it names run first
(tests/run.sh), and when none of them fails, the whole `make test`.  A
mutant is caught when at least one test fails.  Prints one line per mutant
and a table (also written to build/mutants/report.md); exits 1 when a
mutant does not apply or is not caught.

Environment (set by the Makefile): HOST_TESTS, BOARD_TESTS (the suite's
tests, as `make test` runs them), FW_DIR; MUTANTS=NAME,... runs only those.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
LIST = os.path.join(ROOT, "tests", "mutants", "mutants.txt")
REPORT_DIR = os.path.join(ROOT, "build", "mutants")
JOBS = "-j%d" % (os.cpu_count() or 2)


def parse(path):
    mutants, cur = [], None
    with open(path) as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if line.startswith("== "):
                name, _, what = line[3:].partition(": ")
                cur = {"name": name.strip(), "what": what, "file": None, "try": [],
                       "old": None, "new": None, "line": n}
                mutants.append(cur)
            elif cur is None or not line or line.startswith("#"):
                continue
            elif line.startswith("file: "):
                cur["file"] = line[6:].strip()
            elif line.startswith("try: "):
                cur["try"] = line[5:].split()
            elif line.startswith("- "):
                cur["old"] = line[2:]
            elif line.startswith("+ "):
                cur["new"] = line[2:]
            else:
                sys.exit("%s:%d: a mutant's line must start '- ', '+ ', 'file: ' or 'try: '"
                         % (path, n))
    for m in mutants:
        if not (m["file"] and m["old"] is not None and m["new"] is not None):
            sys.exit("%s:%d: mutant %s lacks its file, '- ' or '+ ' line"
                     % (path, m["line"], m["name"]))
    return mutants


def sources():
    """The tree's files as git sees them (tracked, and new ones not ignored)."""
    out = subprocess.run(["git", "ls-files", "-co", "--exclude-standard", "-z"], cwd=ROOT,
                         capture_output=True, check=True).stdout
    return [p for p in out.decode().split("\0") if p and not p.startswith("build/")]


def copy_tree(dst):
    for rel in sources():
        src = os.path.join(ROOT, rel)
        if not os.path.isfile(src):
            continue  # deleted in the working tree
        os.makedirs(os.path.dirname(os.path.join(dst, rel)), exist_ok=True)
        shutil.copy2(src, os.path.join(dst, rel))
    # the build as it is (real copies: the compiler rewrites objects in place)
    subprocess.run(["cp", "-a", os.path.join(ROOT, "build"), os.path.join(dst, "build")],
                   check=True)
    shutil.rmtree(os.path.join(dst, "build", "mutants"), ignore_errors=True)


def apply(m, tree):
    path = os.path.join(tree, m["file"])
    with open(path) as f:
        lines = f.read().split("\n")
    hits = [i for i, l in enumerate(lines) if l == m["old"]]
    if len(hits) != 1:
        return "its '- ' line occurs %d times in %s (want once)" % (len(hits), m["file"])
    lines[hits[0]] = m["new"]
    with open(path, "w") as f:
        f.write("\n".join(lines))
    st = os.stat(path)  # newer than every object built from it
    os.utime(path, (st.st_atime, time.time() + 2))
    return None


def failing(output):
    """The tests with failures in a tests/run.sh output, and its totals."""
    names = [m.group(1) for m in re.finditer(r"^  \[(\S+): \d+ passed, [1-9]\d* failed", output,
                                             re.M)]
    tot = re.search(r"^(\d+) passed, (\d+) failed$", output, re.M)
    return names, (int(tot.group(1)), int(tot.group(2))) if tot else None


def run(cmd, tree, env, log):
    with open(log, "a") as f:
        f.write("$ %s\n" % " ".join(cmd))
        f.flush()
        p = subprocess.run(cmd, cwd=tree, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT)
        out = p.stdout.decode(errors="replace")
        f.write(out)
    return p.returncode, out


def one(m, host_all, board_all, log):
    tree = tempfile.mkdtemp(prefix="links1-mutant-%s." % m["name"])
    try:
        copy_tree(tree)
        why = apply(m, tree)
        if why:
            return "not applied", why
        env = dict(os.environ, FW_DIR=os.environ.get("FW_DIR", "build"))
        hosts = [t for t in host_all if os.path.basename(t) in m["try"]]
        boards = [t for t in board_all if os.path.basename(t) in m["try"]]
        unknown = set(m["try"]) - {os.path.basename(t) for t in hosts + boards}
        if unknown:
            return "not applied", "try names tests the suite lacks: " + " ".join(sorted(unknown))
        rc, out = run(["make", JOBS, "--no-print-directory", "all"] + hosts, tree, env, log)
        if rc != 0:  # a fault must build to test the tests
            return "not applied", "it does not build (%s)" % out.strip().splitlines()[-1][:80]
        env_try = dict(env, HOST_TESTS=" ".join(hosts), BOARD_TESTS=" ".join(boards),
                       TEST_LOG_DIR=os.path.join(tree, "build", "test-logs-mutant"))
        rc, out = run(["bash", "tests/run.sh"], tree, env_try, log)
        names, tot = failing(out)
        if rc != 0 and names:
            return "caught", " ".join(os.path.basename(n) for n in names)
        rc, out = run(["make", "--no-print-directory", "test"], tree, env, log)
        names, tot = failing(out)
        # the fault's own line is gone from the copy: mutants_apply.sh fails
        # whatever the fault, so it catches nothing
        names = [n for n in names if os.path.basename(n) != "mutants_apply.sh"]
        if rc != 0 and names:
            return "caught", "make test: " + " ".join(os.path.basename(n) for n in names)
        return "missed", "make test: %s" % ("%d passed, %d failed" % tot if tot else "no summary")
    finally:
        shutil.rmtree(tree, ignore_errors=True)


def check_lines():
    """--check: every mutant still names a line that occurs once in its file
    and a test of tests/plan.tsv to try (a stale mutant would be reported as
    not applied only when `make test-mutants` runs).  One PASS/FAIL line."""
    mutants = parse(LIST)
    with open(os.path.join(ROOT, "tests", "plan.tsv")) as f:
        planned = {os.path.basename(l.split("\t")[0]) for l in f
                   if l.strip() and not l.startswith("#")}
    bad = []
    for m in mutants:
        try:
            with open(os.path.join(ROOT, m["file"])) as f:
                lines = f.read().split("\n")
        except OSError as e:
            bad.append("%s: %s" % (m["name"], e))
            continue
        hits = sum(1 for l in lines if l == m["old"])
        if hits != 1:
            bad.append("%s: its '- ' line occurs %d times in %s" % (m["name"], hits, m["file"]))
        unknown = [t for t in m["try"] if t not in planned and t + ".sh" not in planned]
        if unknown:
            bad.append("%s: try names %s, not in tests/plan.tsv" % (m["name"], " ".join(unknown)))
    if bad:
        print("FAIL mutants_apply: " + "; ".join(bad))
    else:
        print("PASS mutants_apply (%d mutants)" % len(mutants))
    return 0


def main():
    if sys.argv[1:] == ["--check"]:
        return check_lines()
    host_all = os.environ.get("HOST_TESTS", "").split()
    board_all = os.environ.get("BOARD_TESTS", "").split()
    if not host_all or not board_all:
        sys.exit("mutants.py: run it through `make test-mutants` (HOST_TESTS, BOARD_TESTS)")
    mutants = parse(LIST)
    only = [n for n in os.environ.get("MUTANTS", "").split(",") if n]
    if only:
        mutants = [m for m in mutants if m["name"] in only]
    os.makedirs(REPORT_DIR, exist_ok=True)
    log = os.path.join(REPORT_DIR, "log")
    open(log, "w").close()
    rows, bad = [], 0
    for m in mutants:
        t0 = time.time()
        verdict, detail = one(m, host_all, board_all, log)
        secs = time.time() - t0
        bad += verdict != "caught"
        print("%s %s: %s (%s, %.0f s)" % ("PASS" if verdict == "caught" else "FAIL",
                                          "mutant_" + m["name"], verdict, detail, secs),
              flush=True)
        rows.append("| %s | %s | `%s` | %s | %s |" % (m["name"], m["what"], m["file"], verdict,
                                                     detail))
    with open(os.path.join(REPORT_DIR, "report.md"), "w") as f:
        f.write("| mutant | the fault | file | verdict | caught by |\n|---|---|---|---|---|\n")
        f.write("\n".join(rows) + "\n")
    print("%d mutants, %d caught, %d not" % (len(mutants), len(mutants) - bad, bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
