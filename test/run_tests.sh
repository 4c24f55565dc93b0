#!/bin/sh
# Runs every Unity runner given as an argument, shows its output, and ends
# with one line "N passed, N failed" summed over all of them. A runner that
# dies before printing Unity's summary counts as one failure. Exit status is
# non-zero if anything failed.
#
# The runners run $TEST_JOBS at a time (default: one per core), each into
# its own file; their outputs are then shown one after another in the order
# given, so the log reads as a serial run. Runners share nothing on disk
# (each check script makes its own scratch directory).
jobs=${TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
dir=$(mktemp -d "${TMPDIR:-/tmp}/run_tests.XXXXXX") || exit 1
trap 'rm -rf "$dir"' EXIT INT TERM
i=0
for runner in "$@"; do
    i=$((i + 1))
    printf '%s %s\n' "$i" "$runner"
done >"$dir/list"
# shellcheck disable=SC2016 # $1, $2 and $0 are the inner shell's
xargs -P "$jobs" -n 2 sh -c '"$2" >"$0/$1.out" 2>&1; echo $? >"$0/$1.rc"' "$dir" <"$dir/list"
passed=0
failed=0
i=0
for runner in "$@"; do
    i=$((i + 1))
    echo "== $runner"
    out=$(cat "$dir/$i.out" 2>/dev/null)
    rc=$(cat "$dir/$i.rc" 2>/dev/null || echo 127)
    printf '%s\n' "$out"
    summary=$(printf '%s\n' "$out" | sed -n 's/^\([0-9][0-9]*\) Tests \([0-9][0-9]*\) Failures \([0-9][0-9]*\) Ignored.*$/\1 \2 \3/p' | tail -n 1)
    if [ -z "$summary" ]; then
        echo "!! $runner ended (status $rc) without a Unity summary"
        failed=$((failed + 1))
        continue
    fi
    total=$(echo "$summary" | cut -d' ' -f1)
    fails=$(echo "$summary" | cut -d' ' -f2)
    ignored=$(echo "$summary" | cut -d' ' -f3)
    passed=$((passed + total - fails - ignored))
    failed=$((failed + fails))
    if [ "$rc" -ne 0 ] && [ "$fails" -eq 0 ]; then
        echo "!! $runner exited with status $rc"
        failed=$((failed + 1))
    fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
