#!/bin/sh
# Runs every Unity runner given as an argument, shows its output, and ends
# with one line "N passed, N failed" summed over all of them. A runner that
# dies before printing Unity's summary counts as one failure. Exit status is
# non-zero if anything failed.
passed=0
failed=0
for runner in "$@"; do
    echo "== $runner"
    out=$("$runner" 2>&1)
    rc=$?
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
