#!/bin/sh
# Prints the first Python interpreter that imports numpy (and the modules
# given as arguments, e.g. pytest), trying in order: $PYTHON if set, python3
# on PATH, /usr/bin/python3 (the first python3 on PATH may be one without
# numpy). Prints nothing and exits 1 if none does.
#   sh python/find_python.sh [MODULE...]
mods="numpy"
for m in "$@"; do mods="$mods, $m"; done
for py in ${PYTHON:+"$PYTHON"} python3 /usr/bin/python3; do
    exe=$(command -v "$py" 2>/dev/null) || continue
    if "$exe" -c "import $mods" >/dev/null 2>&1; then
        echo "$exe"
        exit 0
    fi
done
exit 1
