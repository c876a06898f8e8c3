# tests/board/other_user_lib.sh: another local user, for the tests that
# play one (sourced after lib.sh, not run).  As root, other_user_make makes
# a throw-away account with no home and no login shell; as_other runs a
# command as it; the account is deleted when the script exits (before the
# script's own EXIT trap, set before other_user_make, runs).  Not as
# root, other_user_make prints "SKIP name: why" for every named check and
# fails, so a test says what it did not run.
#
#   other_user_make CHECK... || exit 0
#   as_other sh -c 'ln -s ... /tmp/x/planted'
#   other_user_dir PATH   a fresh directory the other user owns, mode 1777
OTHER_USER=""

other_user_make() { # CHECK...: names to SKIP when it cannot be made
    local why=""
    if [ "$(id -u)" -ne 0 ]; then
        why="needs root to make a second account (run as root, as CI does)"
    elif ! command -v useradd >/dev/null || ! command -v runuser >/dev/null; then
        why="useradd or runuser is missing (the Debian packages passwd and util-linux)"
    fi
    if [ -z "$why" ]; then
        OTHER_USER="l1other$$"
        if ! useradd --system --no-create-home --home-dir /nonexistent \
            --shell /usr/sbin/nologin --user-group "$OTHER_USER" 2>/dev/null; then
            why="useradd $OTHER_USER failed"
            OTHER_USER=""
        fi
    fi
    if [ -n "$why" ]; then
        local name
        for name in "$@"; do echo "SKIP $name: $why"; done
        return 1
    fi
    # run before the script's own EXIT trap, which stays
    local prev
    prev=$(trap -p EXIT)
    prev=${prev#"trap -- '"}
    prev=${prev%"' EXIT"}
    trap "other_user_remove; $prev" EXIT
    return 0
}

other_user_remove() {
    [ -n "$OTHER_USER" ] || return 0
    pkill -KILL -u "$OTHER_USER" 2>/dev/null
    userdel "$OTHER_USER" 2>/dev/null
    OTHER_USER=""
}

as_other() { # CMD...: run as the other user, in /
    (cd / && runuser -u "$OTHER_USER" -- "$@")
}

other_user_dir() { # PATH: a directory the other user owns, open to all
    mkdir -p "$1" && chown "$OTHER_USER:" "$1" && chmod 1777 "$1"
}
