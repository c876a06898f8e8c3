#!/usr/bin/env bash
# tests/bench/bench_apu.sh: the paper's Table 1 on the board's CPU
# (docs/results/paper-figures.md, "Table 1").  Builds tests/bench/apu/ for
# cortex-a15 bare metal (picolibc, semihosting), runs it on two cores with
# `links1 semihost --cores 2 --trace-marks`, and turns each core's marked
# instruction counts into instructions per operation: locally in soft
# float, fixed point and VFP, and handed to the neighbour core (the unit
# computer's sending and reading, the APU's work).  Time at 1 MIPS per
# core, as the replay prices work (docs/trace.md): local = its
# instructions; handed off = the unit computer's + the APU's (the unit
# computer waits) + twice a hand-off latency L, which shared memory on one
# chip makes next to nothing and LINKS-1's transfer to its APU did not; the
# table gives the L at which handing off stops paying.  Runs twice and
# checks the counts are the same (the waiting is not counted).  Prints
# PASS/FAIL lines and the table, and writes the table to APU_OUT when set
# (APU_OUT=docs/figures/table1.md for the docs); exits 1 on a FAIL.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
b=$(mktemp -d /tmp/links1-apu.XXXXXX)
OUT=${APU_OUT:-$b/table1.md}
trap 'rm -rf "$b"' EXIT
fail() { echo "FAIL bench_apu: $*"; exit 1; }
ld="--specs=picolibc.specs --oslib=semihost -Wl,--defsym=__flash=0x40000000
    -Wl,--defsym=__flash_size=0x1000000 -Wl,--defsym=__ram=0x41000000
    -Wl,--defsym=__ram_size=0x4000000 -Wl,--defsym=__stack_size=0x100000"
cc="arm-none-eabi-gcc -mcpu=cortex-a15 -mthumb -mfpu=vfpv4 -mfloat-abi=hard -ffreestanding
    -std=gnu11 -O2 -I. -ffp-contract=off -Wall -Wextra -Werror $ld"
$cc -DLINKS1_NUM_FIXED -c tests/bench/apu/apu_fixed.c -o "$b/apu_fixed.o" || fail "build"
$cc tests/bench/apu/apu_bench.c "$b/apu_fixed.o" -o "$b/apu.elf" || fail "build"
for run in 1 2; do
    timeout 300 "$LINKS1" semihost "$b/apu.elf" --cores 2 --trace-marks "$b/marks$run.txt" \
        >"$b/out$run.txt" 2>&1 || fail "links1 semihost: $(tail -n 2 "$b/out$run.txt")"
    grep -q '^done' "$b/out$run.txt" || fail "the program did not finish: $(tail -n 2 "$b/out$run.txt")"
done
grep -E '^(PASS|FAIL) ' "$b/out1.txt"
grep -q '^FAIL' "$b/out1.txt" && fail "a result was wrong"
rounds=$(sed -n 's/^rounds //p' "$b/out1.txt")
# Per core, the spans in order (end - begin), then per operation:
#   core 0: soft, fixed, vfp (rounds each), then rounds x (send, read);
#   core 1: rounds x (one request), the last span the stop.
spans() {
    awk -v core="$1" '$1 == core && $2 == 5 { b = $3 } $1 == core && $2 == 6 { print $3 - b }' "$2"
}
spans 0 "$b/marks1.txt" >"$b/c0"
spans 1 "$b/marks1.txt" >"$b/c1"
if [ "$(spans 0 "$b/marks1.txt" | md5sum)" = "$(spans 0 "$b/marks2.txt" | md5sum)" ] &&
    [ "$(spans 1 "$b/marks1.txt" | md5sum)" = "$(spans 1 "$b/marks2.txt" | md5sum)" ]; then
    echo "PASS apu_counts_deterministic"
else
    fail "apu_counts_deterministic: two runs counted differently"
fi
[ "$(wc -l <"$b/c0")" = $((4 * (3 + 2 * rounds))) ] && [ "$(wc -l <"$b/c1")" = $((4 * rounds + 1)) ] ||
    fail "unexpected span counts: $(wc -l <"$b/c0") and $(wc -l <"$b/c1")"
mkdir -p "$(dirname "$OUT")"
awk -v n="$rounds" 'NR == FNR { c1[FNR] = $1; next } { c0[FNR] = $1 }
END {
    split("vector add (3),vector product (3: dot),matrix add (3x3),matrix multiply (3x3)", name, ",")
    split("0.43 0.79 1.4 8.4", z, " "); split("0.51 0.57 0.80 1.8", p, " ")
    i = 0; j = 0
    printf "| operation | soft float | fixed point | VFP (local) | handed off: unit computer | APU | handed off, total | soft / handed off | fixed / handed off | L where handing off stops paying against soft, fixed (µs) | the paper: Z8001, APU (ms); Z8001 / APU |\n"
    printf "|---|---|---|---|---|---|---|---|---|---|---|\n"
    for (op = 1; op <= 4; op++) {
        soft = c0[++i] / n; fixed = c0[++i] / n; vfp = c0[++i] / n
        u = 0; for (k = 0; k < n; k++) { u += c0[++i] + c0[++i] }
        u /= n
        a = 0; for (k = 0; k < n; k++) a += c1[++j]
        a /= n
        tot = u + a
        l = (soft > tot) ? sprintf("%.0f", (soft - tot) / 2) : "never pays"
        lf = (fixed > tot) ? sprintf("%.0f", (fixed - tot) / 2) : "never pays"
        printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.2fx | %.2fx | %s, %s | %s, %s; %.2fx |\n", name[op], soft, fixed, vfp, u, a, tot, soft / tot, \
            fixed / tot, l, lf, z[op], p[op], z[op] / p[op]
    }
}' "$b/c1" "$b/c0" >"$b/table"
{
    echo "Table 1 on the board's CPU: instructions per operation (mean of $rounds rounds, the loop"
    echo "included), core 0 the unit computer, core 1 its APU, single precision; time at 1 MIPS is"
    echo "the instructions in µs, a hand-off adding 2 L (APU_OUT=F bash tests/bench/bench_apu.sh: links1 semihost"
    echo "APU.ELF --cores 2 --trace-marks F, twice, the counts the same)."
    echo
    cat "$b/table"
} >"$OUT"
cat "$OUT"
