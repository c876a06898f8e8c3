#!/usr/bin/env python3
"""doc_refs.py: what the docs name exists.  Reads README.md and every
docs/**/*.md and prints one line per check:

  doc_paths_exist      every repository path a doc names in backticks
                       (boot/ kernel/ drivers/ roles/ render/ fixed/ proto/
                       host-tools/ tests/ linker/ scenes/ docs/ .ci/ ...)
                       exists (a name with * or {..} or N/X placeholders
                       must match at least one path)
  doc_links_exist      every relative Markdown link or image points at a
                       file that exists
  doc_options_accepted every `links1 CMD ... --option` a doc shows (inline
                       or in an indented or fenced block) is an option that
                       `links1 CMD` accepts: run with it, the command does
                       not answer "unknown option" (`links1 CMD --option
                       --help`: the option is read, then the usage shown or
                       --help taken as its value; nothing runs)
  doc_words_at_most    README.md and docs/ together hold at most
                       DOC_WORDS_MAX words (as `wc -w` counts them)

  python3 tests/docs/doc_refs.py [LINKS1]   (default build/links1)
"""
import glob
import os
import re
import subprocess
import sys

ROOTS = ("boot/", "kernel/", "drivers/", "roles/", "render/", "fixed/", "proto/",
         "host-tools/", "tests/", "linker/", "scenes/", "docs/", ".ci/")
DOC_WORDS_MAX = 35000
CMDS = ("render", "ref", "compile", "farm", "replay", "board", "boot", "selftest",
        "semihost", "import", "export-pov", "compare")


def docs():
    files = ["README.md"] + sorted(glob.glob("docs/**/*.md", recursive=True))
    return [(f, open(f, encoding="utf-8").read()) for f in files]


def code_spans(text):
    """Inline code and the lines of indented or fenced blocks."""
    spans = re.findall(r"`([^`\n]+)`", text)
    fenced = False
    for line in text.split("\n"):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced or line.startswith("    "):
            spans.append(line.strip())
    return spans


def expand(p):
    """proto/x.{h,c} -> proto/x.h, proto/x.c"""
    m = re.search(r"\{([^{}]*)\}", p)
    if not m:
        return [p]
    return [q for alt in m.group(1).split(",")
            for q in expand(p[:m.start()] + alt + p[m.end():])]


PLACEHOLDER = r"<[^>]*>|\b(VARIANT|NAME|MACHINE|FAMILY|N|S|K|F|X)\b|XXXX\w*"


def path_exists(p):
    p = p.rstrip(".,;:)")
    p = re.sub(r"(:\d+)+:?$", "", p)  # file:line:column
    for q in expand(p):
        pat = re.sub(PLACEHOLDER, "*", q)
        if "*" in pat:
            if not glob.glob(pat, recursive=True):
                return False
        elif not os.path.exists(q):
            return False
    return True


def check_paths(all_docs):
    bad = []
    for f, text in all_docs:
        for span in code_spans(text):
            for word in re.split(r"[\s\"'()=]+", span):
                if word.startswith(ROOTS) and not word.startswith("build/") and \
                        not path_exists(word):
                    bad.append(f"{f}: {word}")
    return bad


def check_links(all_docs):
    bad = []
    for f, text in all_docs:
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            path = os.path.normpath(os.path.join(os.path.dirname(f), target.split("#")[0]))
            if not os.path.exists(path):
                bad.append(f"{f}: ({target})")
    return bad


def doc_options(all_docs):
    seen = {}
    for f, text in all_docs:
        for span in code_spans(text):
            for m in re.finditer(r"\blinks1 (%s)\b([^|;&]*)" % "|".join(map(re.escape, CMDS)),
                                 span):
                own = m.group(2).split(" -- ")[0]  # after " -- ": another command's
                for opt in re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", own):
                    seen.setdefault((m.group(1), opt), f)
    return seen


def check_options(all_docs, links1):
    bad = []
    for (cmd, opt), f in sorted(doc_options(all_docs).items()):
        if opt == "--help":
            continue
        try:
            r = subprocess.run([links1, cmd, opt, "--help"], capture_output=True, text=True,
                               timeout=20, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            bad.append(f"{f}: links1 {cmd} {opt} --help did not end within 20 s")
            continue
        if re.search(r"unknown option|unrecognized option", r.stderr):
            bad.append(f"{f}: links1 {cmd} {opt}")
    return bad


def check_words(all_docs):
    words = sum(len(text.split()) for _, text in all_docs)
    if words <= DOC_WORDS_MAX:
        return []
    big = sorted(all_docs, key=lambda d: -len(d[1].split()))[:3]
    return [f"{words} words, over {DOC_WORDS_MAX} (largest: "
            + ", ".join(f"{f} {len(t.split())}" for f, t in big) + ")"]


def report(name, bad):
    if bad:
        print(f"FAIL {name}: {len(bad)} of them, e.g. " + "; ".join(bad[:12]))
    else:
        print(f"PASS {name}")


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    links1 = sys.argv[1] if len(sys.argv) > 1 else "build/links1"
    all_docs = docs()
    report("doc_paths_exist", check_paths(all_docs))
    report("doc_links_exist", check_links(all_docs))
    report("doc_options_accepted", check_options(all_docs, links1))
    report("doc_words_at_most", check_words(all_docs))


if __name__ == "__main__":
    main()
