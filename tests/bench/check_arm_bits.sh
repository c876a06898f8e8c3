#!/usr/bin/env bash
# tests/bench/check_arm_bits.sh: the renderer on the board's CPU gives the same
# image bits as the host build of the same arithmetic.
#
# Renders the demo and paper-like scenes (96x72) with tests/host/test_render_bits.c
# built for the host (float, fixed) and for cortex-a15 bare metal (float with
# VFP, soft float, fixed; picolibc, semihosting, run by `links1 semihost`), and
# compares the CRC-32 of every image; also that each scene copied to another
# block, relocated and rendered by areas with screen clipping (the board's
# way) gives the same CRC.  Prints PASS/FAIL lines.  A reproduce command
# (docs/results/accuracy-and-pov.md), not part of `make test`.
set -u
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
out=build/arm-bits
mkdir -p "$out"
make -s --no-print-directory build/links1 || exit 1
scenes="demo glass molecule city"
{
    for s in $scenes; do
        build/links1 compile "$(scene_of $s)" -o "$out/$s.bin" >/dev/null || exit 1
        (cd "$out" && xxd -i "$s.bin")
    done
    echo "static const struct { const char *name; const unsigned char *data; unsigned len; } bits_scenes[] = {"
    for s in $scenes; do echo "    {\"$s\", ${s}_bin, sizeof ${s}_bin},"; done
    echo "};"
} >"$out/bits_scenes.h"
srcs="tests/host/test_render_bits.c fixed/num.c render/arena.c render/xform.c render/prim.c
      render/prepare.c render/shade.c render/maps.c render/trace.c render/scene_load.c proto/crc32.c
      render/relocate.c render/clip.c"
common="-std=gnu11 -O2 -I. -I$out -ffp-contract=off"
cc $common -DLINKS1_NUM_FLOAT $srcs -lm -o "$out/host-float" || exit 1
cc $common -DLINKS1_NUM_FIXED $srcs -lm -o "$out/host-fixed" || exit 1
ld="--specs=picolibc.specs --oslib=semihost -Wl,--defsym=__flash=0x40000000
    -Wl,--defsym=__flash_size=0x1000000 -Wl,--defsym=__ram=0x41000000
    -Wl,--defsym=__ram_size=0x4000000 -Wl,--defsym=__stack_size=0x100000"
arm="arm-none-eabi-gcc -mcpu=cortex-a15 -mthumb -ffreestanding $common $ld"
$arm -mfpu=vfpv4 -mfloat-abi=hard -DLINKS1_NUM_FLOAT $srcs -o "$out/arm-float.elf" || exit 1
$arm -mfloat-abi=soft -DLINKS1_NUM_FLOAT $srcs -o "$out/arm-soft.elf" || exit 1
$arm -mfloat-abi=soft -DLINKS1_NUM_FIXED $srcs -o "$out/arm-fixed.elf" || exit 1
"$out/host-float" >"$out/host-float.txt"
"$out/host-fixed" >"$out/host-fixed.txt"
for v in float soft fixed; do
    ref=float
    [ $v = fixed ] && ref=fixed
    timeout 600 build/links1 semihost "$out/arm-$v.elf" >"$out/arm-$v.txt" 2>&1
    for s in $scenes; do
        want=$(grep " $s " "$out/host-$ref.txt")
        got=$(grep " $s " "$out/arm-$v.txt")
        if [ -n "$want" ] && [ "$want" = "$got" ]; then
            echo "PASS arm_bits_${v}_$s"
        else
            echo "FAIL arm_bits_${v}_$s: host '$want', arm '$got'"
        fi
        # relocated copy rendered by clipped areas: the same CRC as the
        # host's plain render
        crc_want=$(echo "$want" | sed -n 's/.* crc \([0-9a-f]*\) .*/\1/p')
        area=$(grep " $s/area " "$out/arm-$v.txt" | sed -n 's/.* crc \([0-9a-f]*\) .*/\1/p')
        if [ -n "$crc_want" ] && [ "$crc_want" = "$area" ]; then
            echo "PASS arm_bits_area_${v}_$s"
        else
            echo "FAIL arm_bits_area_${v}_$s: host plain crc '$crc_want', arm relocated+clipped '$area'"
        fi
    done
done
