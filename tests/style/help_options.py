#!/usr/bin/env python3
"""help_options.py: every command says what it takes.  For every command
`links1 --help` lists, and every program the project builds beside links1,
prints:

  help_lists_programs     every program make builds (its HOST_TOOLS) is
                          listed by `links1 --help` (links1-ref-<arith>
                          stands for each links1-ref-*), every one listed is
                          built, and each answers --help (exit 0, a usage line)
  help_options_accepted   every --option a command's --help shows at the
                          start of a help line is one it accepts
  help_accepted_shown     every option name the sources define that a
                          command accepts (given exactly, it is not refused
                          as unknown) starts a help line of that command's
                          --help (a mention in the usage line or in another
                          option's text is not enough)
  help_values_as_shown    an option shown with a VALUE refuses to come
                          without one, an option shown without one refuses
                          a value: exit 2, one line naming it
  usage_error_one_line    an unknown option is refused with exit 2 and one
                          line that names it and says "see ... --help"
  parsers_from_tables     no getopt table is written by hand under
                          host-tools/: every source that reads a command
                          line (cli_init) makes its table from struct
                          cli_optdef definitions (cli_optdefs_table)
  generators_take_no_option_as_a_file
                          each generator host-tools/gen/make_*.py given
                          --help, or an option it does not take, writes
                          nothing (no file or directory of that name)

An option is tried as `PROG --option --help`: the option is read, then the
usage shown or --help taken as its value; nothing runs.

  python3 tests/style/help_options.py
"""
import fnmatch
import glob
import os
import re
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor

BUILD = "build"
OPTION_LINE = re.compile(r"^  (--[a-z][a-z0-9-]*)( [^ ]+)?", re.M)


def run(argv):
    try:
        r = subprocess.run(argv, capture_output=True, text=True, timeout=20,
                           stdin=subprocess.DEVNULL)
        return r.returncode, r.stdout, r.stderr
    except (subprocess.TimeoutExpired, OSError) as e:
        return 124, "", str(e)


def built_programs():
    """The host programs make builds (HOST_TOOLS), links1 left out."""
    r = subprocess.run(["make", "-s", "--no-print-directory", "-f", "Makefile", "-f", "-",
                        "help-options-host-tools"],
                       input="help-options-host-tools: ; @echo $(HOST_TOOLS)\n",
                       capture_output=True, text=True, timeout=60)
    return [p for p in r.stdout.split() if p != "links1"]


def programs():
    """(top help, [(label, argv prefix, in full)] of every command and
    program, [what is wrong with the list of programs]).  The builds of one
    source (links1-ref-<arith>) are checked in full once; the others answer
    --help."""
    rc, out, _ = run([f"{BUILD}/links1", "--help"])
    cmds = re.findall(r"^  ([a-z][a-z0-9-]*) ", out.split("programs beside")[0], re.M)
    listed = re.findall(r"^  ([a-z][a-z0-9<>-]*) ", out.split("programs beside")[-1], re.M)
    found = [(f"links1 {c}", [f"{BUILD}/links1", c] + (["start"] if c == "board" else []),
              True) for c in cmds]
    built = built_programs()
    bad = [f"links1 --help exits {rc}"] if rc != 0 else []
    if not built:
        bad.append("make names no HOST_TOOLS")
    patterns = [p.replace("<arith>", "*") for p in listed]
    full = set()  # the patterns with one build checked in full
    for name in built:
        match = [p for p in patterns if fnmatch.fnmatchcase(name, p)]
        if not match:
            bad.append(f"{name} is built but not listed by links1 --help")
        found.append((name, [f"{BUILD}/{name}"], not match or match[0] not in full))
        full.update(match)
    for p, pattern in zip(listed, patterns):
        if not fnmatch.filter(built, pattern):
            bad.append(f"links1 --help lists {p}, which make does not build")
    return out, found, bad


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


def abbreviates(opt, shown):
    """Whether opt is a shown option or the start of one (getopt takes
    "--area" for "--areas")."""
    return any(s.startswith(opt) for s in shown)


def one_line_naming(rc, err, opt):
    """Whether a refusal is exit 2 and one line naming opt and --help."""
    lines = err.strip().split("\n")
    return rc == 2 and len(lines) == 1 and opt in lines[0] and "--help)" in lines[0]


def values_as_shown(label, prefix, help_text):
    """What is wrong with the options' values against the help lines."""
    bad = []
    for opt, value in OPTION_LINE.findall(help_text):
        if value:  # "--name VALUE": the value is wanted
            rc, _, err = run(prefix + [opt])
        else:      # "--name": no value is taken
            rc, _, err = run(prefix + [f"{opt}=x", "--help"])
        if not one_line_naming(rc, err, opt):
            bad.append(f"{label} {opt}{' without its' + value if value else '=x'}: "
                       f"exit {rc}, {err.strip()[:80]!r}")
    return bad


def check_program(label, prefix, in_full, names):
    """{check name: [what is wrong]} of one program."""
    rc, out, _ = run(prefix + ["--help"])
    if rc != 0 or not out.startswith("usage:"):
        return {"help_lists_programs": [f"{label} --help exits {rc}"]}
    if not in_full:
        return {}
    shown = {opt for opt, _ in OPTION_LINE.findall(out)}
    bad = {
        "help_options_accepted": [f"{label} {o}" for o in sorted(shown)
                                  if not accepted(prefix, o)],
        "help_accepted_shown": [f"{label} --{n}" for n in sorted(names)
                                if not abbreviates(f"--{n}", shown) and
                                accepted(prefix, f"--{n}")],
        "help_values_as_shown": values_as_shown(label, prefix, out),
        "usage_error_one_line": [],
    }
    rc, out, err = run(prefix + ["--no-such-option"])
    if not one_line_naming(rc, err, "--no-such-option"):
        lines = err.strip().split("\n")
        bad["usage_error_one_line"].append(f"{label}: exit {rc}, {len(lines)} line(s): "
                                           f"{lines[0][:80]}")
    return bad


def parsers_from_tables():
    """What is wrong with how the sources make their getopt tables."""
    bad = []
    for path in sorted(glob.glob("host-tools/**/*.c", recursive=True)):
        if path == "host-tools/opts/cli_opt.c":
            continue
        text = open(path, encoding="utf-8").read()
        if re.search(r"\b(no|required|optional)_argument\b", text):
            bad.append(f"{path}: a getopt table written by hand")
        if "cli_init(" in text and "cli_optdefs_table(" not in text:
            bad.append(f"{path}: cli_init without cli_optdefs_table")
    return bad


def generators_take_no_option_as_a_file():
    """Each generator run with --help and with --no-such-option in an
    empty directory: what it left there."""
    bad = []
    for gen in sorted(glob.glob("host-tools/gen/make_*.py")):
        for arg in ("--help", "--no-such-option"):
            with tempfile.TemporaryDirectory() as tmp:
                subprocess.run(["python3", os.path.abspath(gen), arg], cwd=tmp,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=60)
                left = os.listdir(tmp)
                if left:
                    bad.append(f"{gen} {arg}: wrote {', '.join(sorted(left))}")
    return bad


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    _, progs, bad_list = programs()
    names = defined_names()
    checks = ["help_lists_programs", "help_options_accepted", "help_accepted_shown",
              "help_values_as_shown", "usage_error_one_line"]
    bad = {c: [] for c in checks}
    bad["help_lists_programs"] += bad_list
    with ThreadPoolExecutor(max_workers=4) as pool:
        for result in pool.map(lambda p: check_program(*p, names), progs):
            for check, found in result.items():
                bad[check] += found
    bad["parsers_from_tables"] = parsers_from_tables()
    bad["generators_take_no_option_as_a_file"] = generators_take_no_option_as_a_file()
    for name, found in bad.items():
        print(f"FAIL {name}: " + "; ".join(found[:10]) if found else f"PASS {name}")


if __name__ == "__main__":
    main()
