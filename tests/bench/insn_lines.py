#!/usr/bin/env python3
"""insn_lines.py: the instructions of a profile by source line and by
inlined function, where tests/bench/insn_funcs.sh gives them by symbol.

    python3 tests/bench/insn_lines.py PROFILE ELF [--function NAME] [--top N]

PROFILE is what `links1 render --insn-profile PROFILE` wrote ("ADDR COUNT"
per translated block), ELF the firmware that ran.  Each block's count goes
to the source line of its first instruction (addr2line -i: the innermost
of its inline chain), and to every function on that chain once.  With
--function, only the blocks whose outermost function is NAME (the function
as the source names it: render_prepare_parts for the symbol
render_prepare_parts.part.0.constprop.0).

Prints "total N", then the top N lines ("COUNT SHARE FUNCTION FILE:LINE"),
then "inclusive", then the top N functions by their inline chains
("COUNT SHARE FUNCTION").  A block is counted whole at its first line: a
line that ends a block before a branch gets the block's other lines too.
ADDR2LINE names the tool (default arm-none-eabi-addr2line).
"""
import argparse
import collections
import os
import subprocess
import sys


def read_profile(path):
    """The profile's (address, count) rows; exits on a malformed one."""
    rows = []
    with open(path, encoding="ascii", errors="replace") as f:
        for n, line in enumerate(f, 1):
            if line.startswith("oom"):
                sys.exit(f"insn_lines: the plugin ran out of memory writing {path}")
            parts = line.split()
            if not parts:
                continue
            try:
                addr, count = int(parts[0], 16), int(parts[1]) if len(parts) == 2 else -1
            except ValueError:
                addr = count = -1
            if not 0 <= addr < 1 << 32 or count < 0:
                sys.exit(f"insn_lines: {path}:{n}: not 'ADDR COUNT': {line.strip()!r}")
            rows.append((addr, count))
    return rows


def inline_chains(elf, addrs):
    """Each address's inline chain, innermost first: [(function, file:line)]."""
    tool = os.environ.get("ADDR2LINE", "arm-none-eabi-addr2line")
    r = subprocess.run([tool, "-f", "-i", "-a", "-e", elf],
                       input="".join(f"0x{a:08x}\n" for a in addrs),
                       capture_output=True, text=True, check=False)
    if r.returncode != 0:
        sys.exit(f"insn_lines: {tool} failed: {r.stderr.strip()}")
    chains, cur, lines = {}, None, r.stdout.split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("0x"):
            cur = int(line, 16)
            chains[cur] = []
            i += 1
        elif cur is not None and line and i + 1 < len(lines):
            where = lines[i + 1].split(" (discriminator")[0]
            chains[cur].append((line, os.path.basename(where)))
            i += 2
        else:
            i += 1
    return chains


def print_top(table, total, top):
    """The top rows of table: "COUNT SHARE KEY"."""
    for key, n in table.most_common(top):
        print(f"{n} {100 * n / total:.1f}% {key}")


def main():
    ap = argparse.ArgumentParser(description="a profile's instructions by line and inlined function")
    ap.add_argument("profile")
    ap.add_argument("elf")
    ap.add_argument("--function", help="only the blocks whose outermost function is this one")
    ap.add_argument("--top", type=int, default=40, help="rows of each table (default 40)")
    a = ap.parse_args()
    if a.top < 1:
        sys.exit("insn_lines: --top must be at least 1")
    rows = read_profile(a.profile)
    chains = inline_chains(a.elf, [addr for addr, _ in rows])
    by_line, by_function = collections.Counter(), collections.Counter()
    for addr, count in rows:
        chain = chains.get(addr) or [("?", "?")]
        if a.function and chain[-1][0] != a.function:
            continue
        function, where = chain[0]
        by_line[f"{function} {where}"] += count
        for name in {f for f, _ in chain}:
            by_function[name] += count
    total = sum(by_line.values())
    print(f"total {total}")
    print_top(by_line, total, a.top)
    print("inclusive")
    print_top(by_function, total, a.top)


if __name__ == "__main__":
    main()
