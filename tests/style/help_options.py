#!/usr/bin/env python3
"""help_options.py: every command says what it takes.  For every command
`links1 --help` lists, and every program it lists beside links1, prints:

  help_lists_programs     `links1 --help` lists every command and program,
                          and each answers --help (exit 0, a usage line)
  help_options_accepted   every --option a command's --help shows at the
                          start of a help line is one it accepts
  help_accepted_shown     every option name the sources define that a
                          command accepts (given exactly, it is not refused
                          as unknown) appears in that command's --help
  usage_error_one_line    an unknown option is refused with exit 2 and one
                          line that names it and says "see ... --help"

An option is tried as `PROG --option --help`: the option is read, then the
usage shown or --help taken as its value; nothing runs.

  python3 tests/style/help_options.py
"""
import glob
import os
import re
import subprocess
from concurrent.futures import ThreadPoolExecutor

BUILD = "build"


def run(argv):
    try:
        r = subprocess.run(argv, capture_output=True, text=True, timeout=20,
                           stdin=subprocess.DEVNULL)
        return r.returncode, r.stdout, r.stderr
    except subprocess.TimeoutExpired:
        return 124, "", "timed out"


def programs():
    """(label, argv prefix) of every command and program."""
    rc, out, _ = run([f"{BUILD}/links1", "--help"])
    cmds = re.findall(r"^  ([a-z][a-z0-9-]*) ", out.split("programs beside")[0], re.M)
    progs = re.findall(r"^  ([a-z][a-z0-9<>-]*) ", out.split("programs beside")[-1], re.M)
    found = [(f"links1 {c}", [f"{BUILD}/links1", c] + (["start"] if c == "board" else []))
             for c in cmds]
    for p in progs:
        name = p.replace("<arith>", "double")
        found.append((p, [f"{BUILD}/{name}"]))
    return out, found


def defined_names():
    """Every long option name the host sources define."""
    names = set()
    for path in glob.glob("host-tools/**/*.c", recursive=True):
        text = open(path, encoding="utf-8").read()
        names.update(re.findall(r'\{"([a-z][a-z0-9-]+)", (?:"[^"]*"|NULL|no_argument|'
                                r'required_argument|optional_argument)', text))
    names.discard("help")
    return names


def accepted(prefix, opt):
    rc, out, err = run(prefix + [opt, "--help"])
    return not re.search(r"unknown option|unrecognized option", err)


def check_program(label, prefix, names):
    """(bad_prog, bad_accept, bad_shown, bad_err) of one program."""
    rc, out, _ = run(prefix + ["--help"])
    if rc != 0 or not out.startswith("usage:"):
        return [f"{label} --help exits {rc}"], [], [], []
    shown = set(re.findall(r"^  (--[a-z][a-z0-9-]*)", out, re.M))
    bad_accept = [f"{label} {o}" for o in sorted(shown) if not accepted(prefix, o)]
    bad_shown = [f"{label} --{n}" for n in sorted(names)
                 if f"--{n}" not in out and accepted(prefix, f"--{n}")]
    bad_err = []
    rc, out, err = run(prefix + ["--no-such-option"])
    lines = err.strip().split("\n")
    if rc != 2 or len(lines) != 1 or "--no-such-option" not in lines[0] or \
            "--help)" not in lines[0]:
        bad_err.append(f"{label}: exit {rc}, {len(lines)} line(s): {lines[0][:80]}")
    return [], bad_accept, bad_shown, bad_err


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    top, progs = programs()
    bad_prog, bad_shown, bad_accept, bad_err = [], [], [], []
    names = defined_names()
    with ThreadPoolExecutor(max_workers=4) as pool:
        results = list(pool.map(lambda p: check_program(p[0], p[1], names), progs))
    for bp, ba, bs, be in results:
        bad_prog += bp
        bad_accept += ba
        bad_shown += bs
        bad_err += be
    for name, bad in [("help_lists_programs", bad_prog), ("help_options_accepted", bad_accept),
                      ("help_accepted_shown", bad_shown), ("usage_error_one_line", bad_err)]:
        print(f"FAIL {name}: " + "; ".join(bad[:10]) if bad else f"PASS {name}")


if __name__ == "__main__":
    main()
