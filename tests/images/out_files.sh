#!/usr/bin/env bash
# tests/images/out_files.sh: every writer of -o (compile's .l1s, import's
# .scn, export-pov's .pov, ref's image) writes through a temporary file
# beside OUT (host-tools/opts/out_file.c): an OUT that is a FIFO, a symbolic
# link or a directory is refused with a message naming it, and the FIFO or
# the link's target is left as it was (no hang on a FIFO, no write through
# a link); a refused or failed write leaves nothing beside OUT; a written
# OUT has a plain create's mode.
# Prints "PASS out_NAME" / "FAIL out_NAME: why".
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
T=$(mktemp -d /tmp/links1-out-test.XXXXXX)
trap 'rm -rf "$T"' EXIT
umask 022

# writer NAME OUT: runs that writer of -o onto OUT (within 20 s).
writer() {
    case $1 in
    compile) timeout 20 "$LINKS1" compile scenes/demo.scn -o "$2" ;;
    import) timeout 20 "$LINKS1" import tests/models/cube.obj --camera auto -o "$2" ;;
    export-pov) timeout 20 "$LINKS1" export-pov scenes/demo.scn -o "$2" ;;
    ref) timeout 20 "$LINKS1" ref scenes/demo.scn --size 16x12 -o "$2" ;;
    esac
}
ext() { case $1 in compile) echo l1s ;; import) echo scn ;; export-pov) echo pov ;; ref) echo ppm ;; esac; }

for w in compile import export-pov ref; do
    d="$T/$w"
    mkdir -p "$d"
    e=$(ext $w)
    # written, with a plain create's mode, nothing beside it
    if writer $w "$d/ok.$e" >"$d/ok.log" 2>&1 && [ -s "$d/ok.$e" ] &&
        [ "$(stat -c %a "$d/ok.$e")" = 644 ] && [ "$(ls -A "$d" | sort | tr '\n' ' ')" = "$(printf 'ok.%s\nok.log\n' $e | sort | tr '\n' ' ')" ]; then
        echo "PASS out_${w}_written"
    else
        echo "FAIL out_${w}_written: exit, mode $(stat -c %a "$d/ok.$e" 2>/dev/null) or leftovers: $(ls -A "$d" | tr '\n' ' ')"
        sed 's/^/    /' "$d/ok.log"
    fi
    # a FIFO at OUT: refused, no hang, still a FIFO
    mkfifo "$d/fifo.$e"
    writer $w "$d/fifo.$e" >"$d/fifo.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ] && [ $rc -ne 124 ] && [ -p "$d/fifo.$e" ] && grep -q "FIFO" "$d/fifo.log"; then
        echo "PASS out_${w}_fifo"
    else
        echo "FAIL out_${w}_fifo: exit $rc (124: hung on the FIFO), or the FIFO was replaced, or no message naming it"
        sed 's/^/    /' "$d/fifo.log"
    fi
    # a symbolic link at OUT: refused, its target untouched, still a link
    echo "the victim's" >"$d/victim"
    ln -s "$d/victim" "$d/link.$e"
    writer $w "$d/link.$e" >"$d/link.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ] && [ "$(cat "$d/victim")" = "the victim's" ] && [ -L "$d/link.$e" ] &&
        grep -q "symbolic link" "$d/link.log"; then
        echo "PASS out_${w}_link"
    else
        echo "FAIL out_${w}_link: exit $rc, the link's target was written or the link replaced, or no message naming it"
        sed 's/^/    /' "$d/link.log"
    fi
    # a directory at OUT: refused, nothing left beside it
    mkdir "$d/sub.$e"
    before=$(ls -A "$d" | sort)
    writer $w "$d/sub.$e" >"$T/sub-$w.log" 2>&1
    rc=$?
    after=$(ls -A "$d" | sort)
    if [ $rc -ne 0 ] && [ "$before" = "$after" ] && [ -z "$(ls -A "$d/sub.$e")" ]; then
        echo "PASS out_${w}_error"
    else
        echo "FAIL out_${w}_error: exit $rc, or left behind: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
    fi
done
