#!/usr/bin/env bash
# tests/bench/insn_funcs.sh PROFILE ELF: the instructions of a profile that
# `links1 render --insn-profile PROFILE` wrote ("ADDR COUNT" per translated
# block), summed by the function of ELF that holds each block's start
# ("FUNCTION COUNT" lines, unsorted).  Function symbols from the
# toolchain's nm (a Thumb function's address has bit 0 set: cleared on the
# last hex digit), then the blocks, both by address (8 lowercase hex digits
# sort as numbers); each block goes to the last function at or below it.
set -eu
[ $# -eq 2 ] || { echo "usage: insn_funcs.sh PROFILE ELF" >&2; exit 2; }
prof=$1 elf=$2
NM=${NM:-arm-none-eabi-nm}
if grep -q '^oom' "$prof"; then
    echo "insn_funcs: the plugin ran out of memory writing $prof" >&2
    exit 1
fi
tmp=$(mktemp -d /tmp/links1-insn-funcs.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
"$NM" -n --defined-only "$elf" |
    awk '$2 ~ /^[TtWw]$/ && length($1) == 8 {
             d = index("0123456789abcdef", substr($1, 8, 1)) - 1
             d -= d % 2
             print substr($1, 1, 7) substr("0123456789abcdef", d + 1, 1), 0, $3 }' >"$tmp/syms"
awk '{ print $1, 1, $2 }' "$prof" >"$tmp/blocks"
LC_ALL=C sort -s -k1,1 -k2,2n "$tmp/syms" "$tmp/blocks" |
    awk '$2 == 0 { f = $3; next } { c[f == "" ? "?" : f] += $3 }
         END { for (k in c) printf "%s %.0f\n", k, c[k] }'
