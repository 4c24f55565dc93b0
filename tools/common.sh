# shellcheck shell=sh
# Shell helpers shared by the check scripts; each sources this file with
#   . "$(dirname "$0")/common.sh"
# and sets USAGE to its one-line usage before calling usage_exit.

# Bad usage: the usage line on stderr, exit status 2.
usage_exit() {
    echo "$USAGE" >&2
    exit 2
}

# fail_exit STATUS MESSAGE...: the message on stderr, then exit STATUS.
fail_exit() {
    status=$1
    shift
    echo "$*" >&2
    exit "$status"
}

# A scratch directory in $tmp, removed however the script ends.
make_tmp() {
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT INT TERM
}

# opts_parse SPEC "$@": the options of a check script, each taking a value,
# with getopts. SPEC lists letter=VARIABLE pairs ("n=NM a=ALLOW"); -x VALUE
# sets VARIABLE, an unknown option exits through usage_exit. The caller then
# drops the options with
#   shift $((OPTIND - 1))
opts_parse() {
    spec=$1
    shift
    letters=
    for pair in $spec; do
        letters="$letters${pair%%=*}:"
    done
    OPTIND=1
    while getopts "$letters" opt; do
        var=
        for pair in $spec; do
            [ "${pair%%=*}" != "$opt" ] || var=${pair#*=}
        done
        [ -n "$var" ] || usage_exit
        eval "$var=\$OPTARG"
    done
}
