#!/usr/bin/env python3
"""func_lengths.py: no C function outside tests/ is longer than 100 lines.
A function is counted from the first line of its head to its closing
brace at the start of a line, both included.  Prints one line:

  PASS func_lengths_at_most_100   or   FAIL func_lengths_at_most_100: ...

  python3 tests/style/func_lengths.py [--list]   (--list: every function
  over 60 lines, longest first, and no verdict)
"""
import os
import re
import subprocess
import sys

LIMIT = 100
HEAD = re.compile(r"^[A-Za-z_][\w \t\*,()\[\]]*?\b(\w+)\s*\(")


def functions(path):
    lines = open(path, encoding="utf-8", errors="replace").read().split("\n")
    name, start, head = None, None, None
    for i, line in enumerate(lines):
        if line == "{" and i > 0:
            # the head: the nearest line above at column 0 with a name and '('
            for j in range(i - 1, max(i - 8, -1), -1):
                m = HEAD.match(lines[j])
                if m and not lines[j].startswith(("struct ", "enum ", "union ", "typedef ")):
                    name, start, head = m.group(1), i, j
                    break
        elif line.startswith("}") and start is not None:
            yield name, head + 1, i - head + 1
            name, start, head = None, None, None


def sources():
    out = subprocess.run(["git", "ls-files", "*.c"], capture_output=True, text=True).stdout
    return [p for p in out.split() if not p.startswith("tests/") and os.path.exists(p)]


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    found = [(n, p, line, name) for p in sources() for name, line, n in functions(p)]
    found.sort(reverse=True)
    if "--list" in sys.argv:
        for n, p, line, name in found:
            if n > 60:
                print(f"{n:5d} {p}:{line} {name}")
        return
    long_ones = [f"{name} ({p}:{line}, {n} lines)" for n, p, line, name in found if n > LIMIT]
    if long_ones:
        print(f"FAIL func_lengths_at_most_{LIMIT}: {len(long_ones)} function(s) over {LIMIT} "
              f"lines: " + "; ".join(long_ones))
    else:
        print(f"PASS func_lengths_at_most_{LIMIT}")


if __name__ == "__main__":
    main()
