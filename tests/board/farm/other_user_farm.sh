#!/usr/bin/env bash
# links1 farm's inputs as another local user would shape them (issue 37,
# holes 1 and 2).  The hosts file is code for GNU parallel (a line of
# several words is an ssh command and a host), so the farm takes it only
# when no one but you (or root) can change it, and every line is a host
# line; DIR (-o) only when no one but you can write it, so no one can plant
# a link where the farm or parallel writes, or a frame it would keep.
# Nothing here boots a board: a refused farm stops before parallel starts,
# and the farms that today's code would start run parallel with
# PARALLEL_SSH=false and a host "x", whose jobs fail at once.
# First, as yourself: a hosts file with each form of host line, blank
# lines and comments is taken; a hosts line that is not a host line is refused with
# its line number (one starting with '-' too), a scene path holding a
# newline is refused, and a DIR the farm makes is writable by you alone
# even under umask 000.  Then, as root, with a throw-away second account
# (tests/board/other_user_lib.sh; SKIP lines otherwise): its hosts file
# (mode 666, in its 1777 directory) holding `sh -c id>.../ran_as;: x` is
# refused naming the file and runs nothing, and so is a hosts file of yours
# in that directory (it may replace it); a hosts file of yours of mode
# 666, and a hosts file that is a symbolic link, are refused and run
# nothing; a DIR of mode 2775 (its group the other account's) or 0777 where
# the other account planted farm-joblog.tsv -> a file of yours is refused
# and the file is left as it was; a DIR the other account owns is refused.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../other_user_lib.sh"
OWN="farm_hosts_lines_taken farm_hosts_bad_line farm_hosts_dash_line farm_scene_newline
     farm_dir_made_private farm_render_args_checked"
OTHER="other_farm_hosts_theirs other_farm_hosts_in_their_dir other_farm_hosts_mode666
       other_farm_hosts_link other_farm_dir_2775 other_farm_dir_0777 other_farm_dir_theirs"
if [ ! -x "$LINKS1" ]; then
    checks_fail "$LINKS1 is not built (run make)" $OWN $OTHER
    exit 0
fi
if ! command -v parallel >/dev/null; then
    checks_fail "GNU parallel is not installed (the Debian package parallel)" $OWN $OTHER
    exit 0
fi
T=$(mktemp -d /tmp/links1-farm-other.XXXXXX) # yours, 0700
A=""                                       # the other account's 1777 directory
S=""                                       # yours, 0755: the other account may enter it
trap 'rm -rf "$T" ${A:+"$A"} ${S:+"$S"}' EXIT
umask 022
printf ':\n' >"$T/hosts_ok"
export PARALLEL_SSH=false # a job that gets as far as a host fails at once

# farm NAME ARGS...: links1 farm, its output in $T/NAME.log (echoed); its exit status
farm() {
    local name=$1; shift
    timeout 60 "$LINKS1" farm "$@" >"$T/$name.log" 2>&1
    local rc=$?
    echo "--- $LINKS1 farm $* (exit $rc)"
    sed 's/^/    /' "$T/$name.log"
    return $rc
}
# refused NAME PATTERN GONE SCENE ARGS...: `links1 farm SCENE --frames 0:0
# ARGS...` exits 1 with PATTERN (fixed text) in its output, GONE (a file a
# line of the hosts file would make) does not exist, and no joblog was
# written in $T/out
refused() {
    local name=$1 pat=$2 gone=$3 scene=$4; shift 4
    rm -rf "$T/out"
    farm "$name" "$scene" --frames 0:0 --retries 1 "$@"
    local rc=$?
    if [ $rc -eq 1 ] && grep -qF -- "$pat" "$T/$name.log" && [ ! -e "$gone" ] &&
        [ ! -e "$T/out/farm-joblog.tsv" ]; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc, want 1 and a refusal with '$pat'$([ -e "$gone" ] &&
            echo ", and $gone exists: a line ran"): $(tail -n 1 "$T/$name.log")"
    fi
}

# The render arguments after "--" are read with render's own definitions
# before any host runs: one render does not take, a bad value, and one the
# farm sets itself are each refused (exit 2), naming it.
farm farm_args_unknown scenes/anim.scn --frames 0:0 -o "$T/args" --hosts "$T/hosts_ok" \
    -- --size 32x24 --no-such-option
rc1=$?
farm farm_args_value scenes/anim.scn --frames 0:0 -o "$T/args" --hosts "$T/hosts_ok" -- --ncs 0
rc2=$?
farm farm_args_own scenes/anim.scn --frames 0:0 -o "$T/args" --hosts "$T/hosts_ok" -- --frames 1:2
rc3=$?
if [ $rc1 -eq 2 ] && grep -qF "unknown option '--no-such-option' (see links1 farm --help)" "$T/farm_args_unknown.log" &&
    [ $rc2 -eq 2 ] && grep -qF -- "--ncs '0': want" "$T/farm_args_value.log" &&
    [ $rc3 -eq 2 ] && grep -qF -- "render argument --frames: the farm sets it" "$T/farm_args_own.log" &&
    [ ! -e "$T/args/farm-joblog.tsv" ]; then
    echo "PASS farm_render_args_checked"
else
    echo "FAIL farm_render_args_checked: exits $rc1 $rc2 $rc3 (want 2 each and the option named)"
fi

# As yourself: the lines of a hosts file, a newline in a path, a new DIR.
# Every form of a host line is taken (7 hosts; parallel starts)
printf '# c\n  # indented\n:\n2/:\nuser@host-a.example\n4/u_1@h.b_c:2222\n\n\t\n[::1]:22\nroot@[2001:db8::1]  \r\nh\n' >"$T/good"
rm -rf "$T/out"
farm farm_hosts_lines_taken scenes/anim.scn --frames 0:0 --retries 1 -o "$T/out" --hosts "$T/good"
if grep -qF "1 to render on 7 host(s) of $T/good" "$T/farm_hosts_lines_taken.log"; then
    echo "PASS farm_hosts_lines_taken"
else
    echo "FAIL farm_hosts_lines_taken: $(head -n 1 "$T/farm_hosts_lines_taken.log")"
fi
printf '# hosts\n:\n\nok-host.example\nbad/host x\n' >"$T/bad_line"
refused farm_hosts_bad_line "--hosts $T/bad_line: line 5 'bad/host x' is not a host line" \
    "$T/none" scenes/anim.scn -o "$T/out" --hosts "$T/bad_line"
printf -- '-oProxyCommand=false\n' >"$T/dash_line"
refused farm_hosts_dash_line "--hosts $T/dash_line: line 1 '-oProxyCommand=false' is not a host line" \
    "$T/none" scenes/anim.scn -o "$T/out" --hosts "$T/dash_line"
printf 'x\n' >"$T/hosts_x"
nl_scene="$T/a
b.scn"
cp scenes/anim.scn "$nl_scene"
refused farm_scene_newline "the scene '$T/a\\nb.scn' holds a newline" "$T/none" "$nl_scene" \
    -o "$T/out" --hosts "$T/hosts_x"
rm -rf "$T/made"
(umask 000 && farm farm_made scenes/anim.scn --frames 0:0 --retries 1 -o "$T/made" \
    --hosts "$T/hosts_x")
mode=$(stat -c %a "$T/made" 2>/dev/null)
if [ "$mode" = 755 ]; then
    echo "PASS farm_dir_made_private"
else
    echo "FAIL farm_dir_made_private: a DIR made under umask 000 has mode '$mode', want 755 (only you write it)"
fi

other_user_make $OTHER || exit 0
# the other account's world-writable directory and its hosts file of mode 666
A=$(mktemp -u /tmp/links1-farm-theirs.XXXXXX)
other_user_dir "$A"
as_other sh -c "printf 'sh -c id>$A/ran_as;: x\n' >'$A/hosts' && chmod 666 '$A/hosts'"
refused other_farm_hosts_theirs "--hosts $A/hosts: the file belongs to uid $(id -u "$OTHER_USER")" \
    "$A/ran_as" scenes/anim.scn -o "$T/out" --hosts "$A/hosts"
# yours, but in its directory: it may replace the file with its own
printf 'sh -c id>%s/ran_theirs;: x\n' "$T" >"$A/mine"
refused other_farm_hosts_in_their_dir "--hosts $A/mine: the directory $A above it belongs to uid $(id -u "$OTHER_USER")" \
    "$T/ran_theirs" scenes/anim.scn -o "$T/out" --hosts "$A/mine"
# yours, but mode 666: anyone may make it say anything
printf 'sh -c id>%s/ran_666;: x\n' "$T" >"$T/hosts666"
chmod 666 "$T/hosts666"
refused other_farm_hosts_mode666 "--hosts $T/hosts666: mode 0666, its group or others may write it: refused (chmod go-w $T/hosts666)" \
    "$T/ran_666" scenes/anim.scn -o "$T/out" --hosts "$T/hosts666"
# a symbolic link (its target could change between the check and parallel)
printf 'sh -c id>%s/ran_link;: x\n' "$T" >"$T/hosts_target"
ln -s "$T/hosts_target" "$T/hosts_link"
refused other_farm_hosts_link "--hosts $T/hosts_link: a symbolic link: refused" "$T/ran_link" \
    scenes/anim.scn -o "$T/out" --hosts "$T/hosts_link"

# DIR that the other account can write, with a link it planted where
# parallel writes its joblog; DIR that it owns
S=$(mktemp -d /tmp/links1-farm-shared.XXXXXX)
chmod 755 "$S"
echo "a file of yours" >"$T/victim"
shared_dir() { # NAME MODE: refused, the victim as it was
    local d="$S/d$2"
    mkdir "$d" && chgrp "$OTHER_USER" "$d" && chmod "$2" "$d"
    as_other ln -s "$T/victim" "$d/farm-joblog.tsv"
    rm -rf "$T/out"
    farm "$1" scenes/anim.scn --frames 0:0 --retries 1 -o "$d" --hosts "$T/hosts_x"
    local rc=$?
    if [ $rc -eq 1 ] && grep -qF -- "-o $d: mode $2, its group or others may write it: refused (chmod go-w $d)" "$T/$1.log" &&
        [ "$(cat "$T/victim")" = "a file of yours" ] && [ -L "$d/farm-joblog.tsv" ]; then
        echo "PASS $1"
    else
        echo "FAIL $1: exit $rc, want 1 and DIR refused; $T/victim now: '$(head -c 80 "$T/victim" | tr '\n\t' '  ')': $(tail -n 1 "$T/$1.log")"
    fi
}
shared_dir other_farm_dir_2775 2775
shared_dir other_farm_dir_0777 0777
mkdir "$S/theirs" && chown "$OTHER_USER:" "$S/theirs"
refused other_farm_dir_theirs "-o $S/theirs: the directory belongs to uid $(id -u "$OTHER_USER")" \
    "$T/none" scenes/anim.scn -o "$S/theirs" --hosts "$T/hosts_x"
