#!/usr/bin/env bash
# layers.sh: the include rules of docs/layers.md hold on the tree, and the
# checker (check_layers.sh, `make check-layers`) fails on each kind of wrong
# include planted in a copy of the tree, naming the file, the line and the rule.
set -u
cd "$(dirname "$0")/../.."
check=tests/layers/check_layers.sh
tmp=$(mktemp -d /tmp/links1-layers.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

if out=$(bash "$check" 2>&1); then
    echo "PASS layers_tree_follows_the_rules ($(tail -1 <<<"$out"))"
else
    echo "FAIL layers_tree_follows_the_rules:"
    sed 's/^/    /' <<<"$out"
fi

# A copy of the sources and the rules.
find boot kernel drivers roles render fixed proto linker scenes host-tools tests docs/layers.md \
    -type f \( -name '*.c' -o -name '*.h' -o -name '*.S' -o -name '*.ld' -o -name '*.md' \) \
    -print0 | tar --null -cf - -T - | tar -xf - -C "$tmp"

# plant NAME FILE INCLUDE WANT: FILE gets `#include "INCLUDE"` at its end;
# the checker must fail with a line holding WANT; FILE is restored after.
plant() {
    local name=$1 file=$2 inc=$3 want=$4
    local orig="$tmp/.orig"
    local existed=0
    if [ -e "$tmp/$file" ]; then
        cp "$tmp/$file" "$orig"
        existed=1
    else
        mkdir -p "$(dirname "$tmp/$file")"
    fi
    printf '#include "%s"\n' "$inc" >>"$tmp/$file"
    local line
    line=$(wc -l <"$tmp/$file")
    local out rc
    out=$(bash "$check" "$tmp" 2>&1)
    rc=$?
    if [ "$existed" = 1 ]; then mv "$orig" "$tmp/$file"; else rm -f "$tmp/$file"; fi
    # a wrong include is named with its line, a folder without a row without
    if [ $rc -eq 1 ] && { grep -qF "$file:$line: $want" <<<"$out" ||
        grep -qF "$file: $want" <<<"$out"; }; then
        echo "PASS layers_refuse_$name"
    else
        echo "FAIL layers_refuse_$name: checker exit $rc, wanted \"$file:$line: $want\"; it said:"
        sed 's/^/    /' <<<"$out" | head -5
    fi
}
plant launcher_knows_no_scene host-tools/launcher/board_opts.c host-tools/scene/scene_desc.h \
    "host-tools/launcher/ may not include host-tools/scene/scene_desc.h"
plant launcher_knows_no_trace host-tools/launcher/qemu.c host-tools/trace/trace_file.h \
    "host-tools/launcher/ may not include host-tools/trace/trace_file.h"
plant model_knows_no_scene host-tools/model/model_wire.c proto/scene_format.h \
    "host-tools/model/ may not include proto/scene_format.h"
plant host_tools_not_kernel host-tools/gigs/render_session.c kernel/param.h \
    "host-tools/gigs/ may not include kernel/param.h"
plant host_tools_not_roles host-tools/cli/cmd_render.c roles/gigs.h \
    "host-tools/cli/ may not include roles/gigs.h"
plant host_tools_not_drivers host-tools/trace/replay.c drivers/serial/linemsg.h \
    "host-tools/trace/ may not include drivers/serial/linemsg.h"
plant host_tools_not_boot host-tools/insn/insn_report.c boot/virt/start.h \
    "host-tools/insn/ may not include boot/virt/start.h"
plant render_not_host_tools render/clip.c host-tools/opts/cli_opt.h \
    "render/ may not include host-tools/opts/cli_opt.h"
plant fixed_not_host_tools fixed/num.h host-tools/image/image_io.h \
    "fixed/ may not include host-tools/image/image_io.h"
plant proto_not_host_tools proto/areas.c host-tools/link/board.h \
    "proto/ may not include host-tools/link/board.h"
plant kernel_knows_no_driver kernel/cpu.c drivers/imsu/imsu.h \
    "kernel/ may not include drivers/imsu/imsu.h"
plant kernel_knows_no_role kernel/task.c roles/unit.h \
    "kernel/ may not include roles/unit.h"
plant link_state_private host-tools/gigs/render_faults.c host-tools/link/board_arq.h \
    "host-tools/link/board_arq.h is private to"
plant folder_without_row host-tools/newroom/thing.c proto/units.h \
    "no row of docs/layers.md covers this folder"
