"""host-tools/gen/gen_args.py: the one output operand of a generator here
(make_city.py, make_fig9.py, make_normal_tex.py).  -h or --help prints the
generator's docstring; no operand, more than one, or one that starts with
'-' (an option it does not take, not a file to write) is a usage error
that names it, so a mistyped option never becomes a file or directory."""
import sys


def out_operand(doc):
    """sys.argv's output operand; exits 0 after -h/--help, 2 on misuse."""
    args = sys.argv[1:]
    name = sys.argv[0].rsplit("/", 1)[-1]
    if args in (["-h"], ["--help"]):
        print(doc.strip())
        sys.exit(0)
    if len(args) != 1 or args[0].startswith("-"):
        sys.stderr.write("%s: one output operand, not %s (--help for usage)\n"
                         % (name, " ".join(repr(a) for a in args) or "none"))
        sys.exit(2)
    return args[0]
