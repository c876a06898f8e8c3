# tests/board/render_lib.sh: helpers of the rendering board tests (sourced
# after lib.sh, not run).  Images are compared byte for byte as PPM: the
# board must give exactly what the host build of the same arithmetic gives.
RENDER_TMP=$(mktemp -d /tmp/links1-render-test.XXXXXX)
trap 'rm -rf "$RENDER_TMP"' EXIT

# render_ref SCENE ARITH SIZE [FRAMES]: path of the host reference image
# (made once per scene, arithmetic, size and frames).  soft is the float build.
render_ref() {
    local scene=$1 arith=$2 size=$3 frames=${4:-}
    # soft: on the host the float build, without escalation as on the board
    local out="$RENDER_TMP/ref-$(basename "$scene" .scn)-$arith-$size${frames:+-f}.ppm"
    if [ ! -e "$out.done" ]; then
        "$LINKS1" ref "$scene" -o "$out" --arith "$arith" --size "$size" \
            ${frames:+--frames "$frames"} >"$out.log" 2>&1 && touch "$out.done"
    fi
    echo "$out"
}

# render_same NAME REF OUT: PASS when OUT equals REF byte for byte.
render_same() {
    local name=$1 ref=$2 out=$3
    if [ ! -s "$ref" ]; then
        echo "FAIL $name: no host reference image $ref"
    elif [ ! -s "$out" ]; then
        echo "FAIL $name: the board wrote no image $out"
    elif cmp -s "$ref" "$out"; then
        echo "PASS $name"
    else
        echo "FAIL $name: the board's image differs from the host build's ($("$LINKS1" compare "$ref" "$out" 2>&1 | grep -m1 'largest difference' | sed 's/.*largest/largest/'))"
    fi
}

# render_board NAME OUT [links1 render args...]: runs the board; on a
# non-zero exit prints FAIL with the tool's last error line and returns 1.
render_board() {
    local name=$1 out=$2; shift 2
    local log="$RENDER_TMP/$name.log" rc
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render "$@" >"$log" 2>&1
    rc=$?
    echo "--- $LINKS1 render $* (exit $rc)"
    sed 's/^/    /' "$log"
    if [ $rc -ne 0 ]; then
        echo "FAIL $name: links1 render exited $rc: $(grep 'links1' "$log" | tail -n 1)"
        return 1
    fi
    return 0
}

# render_frames_same NAME SCENE ARITH FRAMES [ARGS...]: the board's frames
# A..B at $SIZE on 4 NCs (with ARGS, and BOARD_ONLY's on the board alone)
# equal links1 ref's with ARGS, frame by frame (one PASS or FAIL)
render_frames_same() {
    local name=$1 scene=$2 a=$3 frames=$4 ref=$RENDER_TMP/$1-host.ppm out=$RENDER_TMP/$1.ppm
    local first=${frames%%:*} last=${frames##*:} bad=""
    shift 4
    "$LINKS1" ref "$scene" --arith "$a" --size "$SIZE" --frames "$frames" -o "$ref" "$@" \
        >"$ref.log" 2>&1 || { echo "FAIL $name: links1 ref failed: $(tail -n 1 "$ref.log")"; return; }
    local -a board_only
    read -r -a board_only <<<"${BOARD_ONLY:-}"
    render_board "$name" "$out" "$scene" -o "$out" --arith "$a" --ncs 4 --size "$SIZE" \
        --frames "$frames" "${board_only[@]}" "$@" || return 0
    for ((f = first; f <= last; f++)); do
        local r="${ref%.ppm}-$(printf %04d $f).ppm" o="${out%.ppm}-$(printf %04d $f).ppm"
        [ -s "$r" ] && [ -s "$o" ] && cmp -s "$r" "$o" || bad="$bad $f"
    done
    if [ -z "$bad" ]; then
        echo "PASS $name"
    else
        echo "FAIL $name: frames$bad differ from the host build's (or are missing)"
    fi
}

# render_grid_one SCENE ARITH NCS MODE SIZE: one cell of the grid.
render_grid_one() {
    local scene=$1 arith=$2 ncs=$3 mode=$4 size=$5
    local name="render_$(basename "$scene" .scn)_${arith}_${ncs}nc_$mode"
    local out="$RENDER_TMP/$name.ppm"
    local ref
    ref=$(render_ref "$scene" "$arith" "$size")
    render_board "$name" "$out" "$scene" -o "$out" --arith "$arith" --ncs "$ncs" \
        --balance "$mode" --size "$size" || return 0
    render_same "$name" "$ref" "$out"
}

# render_faults_one NAME SCENE SIZE NCS K SEED KIND [BALANCE]: renders with K
# of NCS NCs failing (links1 render --inject-faults K:SEED --inject-kind KIND
# [--balance BALANCE]) and
# checks the image equals the host build's (float), the summary names K
# failed NCs, each caught the way its kind is (a fault or the watchdog),
# and lists the re-issued areas it counts.
render_faults_one() {
    local name=$1 scene=$2 size=$3 ncs=$4 k=$5 seed=$6 kind=$7 balance=${8:-}
    local out="$RENDER_TMP/$name.ppm" log="$RENDER_TMP/$name.log"
    local ref
    ref=$(render_ref "$scene" float "$size")
    render_board "$name" "$out" "$scene" -o "$out" --ncs "$ncs" --size "$size" \
        --inject-faults "$k:$seed" --inject-kind "$kind" ${balance:+--balance "$balance"} || return 0
    render_same "$name" "$ref" "$out"
    local line failed caught want
    line=$(grep -m1 'failed during the frame' "$log")
    failed=$(echo "$line" | sed -n 's/.*frame [0-9]*: \([0-9]*\) NC(s) failed.*/\1/p')
    case $kind in
    undef | abort) want=fault ;;
    hang | silent) want=watchdog ;;
    *) want='fault\|watchdog' ;;
    esac
    caught=$(echo "$line" | grep -o "NC [0-9]* ($want)" | wc -l)
    local planned reissued listed
    planned=$(grep -m1 'fault plan' "$log" | grep -o 'NC [0-9]*' | sort | tr '\n' ' ')
    reissued=$(echo "$line" | sed -n 's/.*; \([0-9]*\) area(s) re-issued.*/\1/p')
    listed=$(echo "$line" | grep -o 'from NC [0-9]*' | wc -l)
    # The board lists at most LINK_REISSUE_LIST_MAX (48) of them.
    [ -n "$reissued" ] && [ "$reissued" -gt 48 ] && [ "$listed" = 48 ] && listed=$reissued
    if [ "$failed" = "$k" ] && [ "$caught" = "$k" ] &&
        [ "$(echo "$line" | grep -o 'NC [0-9]* (' | sed 's/ (//' | sort | tr '\n' ' ')" = "$planned" ] &&
        [ -n "$reissued" ] && [ "$listed" = "$reissued" ]; then
        echo "PASS ${name}_summary"
    else
        echo "FAIL ${name}_summary: want $k NCs ($planned) caught by $want and the re-issued areas listed; got: ${line:-no failure line}"
    fi
}

# render_tiny_sphere_scene FILE: issue 11's scene, a sphere of radius 1e-6
# (one step of fixed Q12.19) beside the eye in a scene spanning 12: fixed
# point refuses it (RENDER_ERR_DETAIL), float renders it
# (render_refuse.sh, render_auto.sh).
render_tiny_sphere_scene() {
    cat >"$1" <<'EOF'
camera { eye 0 1 -0.00001  look_at 0 1 0  up 0 1 0  fov 40 }  resolution 64 48
light point { colour 1 1 1  position -4 9 -5 }  material m { colour 1 1 1 dic 0.3 drc 0.7 }
box { material m  min -6 -0.5 -4  max 6 0 8 }   sphere { material m centre 0 1 0 radius 0.000001 }
EOF
}

# The loader's refusal of render_damaged_scene's file, as the board says it.
RENDER_DAMAGED_REFUSAL='scene upload: the board says: scene refused: checksum mismatch: the scene is corrupt'

# render_damaged_scene GOOD OUT: OUT is GOOD compiled, then its first
# section table entry (after the 16-byte header) pointed far past the end
# of the file.  0, or 1 after printing why (the compile failed: a test that
# went on would pass on a missing file).
render_damaged_scene() {
    local err
    if ! err=$("$LINKS1" compile "$1" -o "$2" 2>&1) || [ ! -s "$2" ]; then
        echo "links1 compile $1 failed: $err"
        return 1
    fi
    printf '\xff\xff\xff\x7f' | dd of="$2" bs=1 seek=20 conv=notrunc status=none
}

# render_run NAME ARGS...: runs links1 ARGS, its output in $RENDER_TMP/NAME.log
# (and echoed); returns its exit status (named-board tests).
render_run() {
    local name=$1; shift
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" "$@" >"$RENDER_TMP/$name.log" 2>&1
    local rc=$?
    echo "--- links1 $* (exit $rc)"; sed 's/^/    /' "$RENDER_TMP/$name.log"
    return $rc
}

# render_board_pid NAME: the QEMU pid in named board NAME's record
# ($LINKS1_BOARDS/NAME/board).
render_board_pid() { awk '/^pid/ {print $2}' "$LINKS1_BOARDS/$1/board" 2>/dev/null; }

# farm_frames_same NAME DIR: PASS when frames 0..3 in DIR (frame-000F.ppm)
# equal one board's render of them ($RENDER_TMP/ref-000F.ppm).
farm_frames_same() {
    local bad="" f
    for f in 0 1 2 3; do cmp -s "$RENDER_TMP/ref-000$f.ppm" "$2/frame-000$f.ppm" || bad+=" $f"; done
    if [ -z "$bad" ]; then echo "PASS $1"; else echo "FAIL $1: frame(s)$bad missing or not the board's"; fi
}

# farm NAME ARGS...: runs links1 farm, its output in $RENDER_TMP/NAME.log
# (echoed, with $PARALLEL_SSH when set); returns its exit status.
farm() {
    local name=$1; shift
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" farm "$@" >"$RENDER_TMP/$name.log" 2>&1
    local rc=$?
    echo "--- ${PARALLEL_SSH:+PARALLEL_SSH='$PARALLEL_SSH' }$LINKS1 farm $* (exit $rc)"
    sed 's/^/    /' "$RENDER_TMP/$name.log"
    return $rc
}
