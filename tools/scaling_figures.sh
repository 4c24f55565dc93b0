#!/bin/sh
# The figures of docs/scaling.md, measured here (make scaling-figures):
# the per-level cost of a reduction (record size, save, load, merge per N,
# tools/io_cost.c) and the trials per second per rank of mcspec-mpi for a
# few pattern runs at P = 1, 2, 4 ranks (--oversubscribe beyond the cores:
# per-rank rates then fall as ranks share a core).
set -eu
MCSPEC_MPI=${MCSPEC_MPI:-build/bin/mcspec-mpi}
MPIRUN=${MPIRUN:-mpirun}
IO_COST=${IO_COST:-build/tools/io_cost}
mpiflags="--oversubscribe"
[ "$(id -u)" -eq 0 ] && mpiflags="$mpiflags --allow-run-as-root"
work=$(mktemp -d "${TMPDIR:-/tmp}/mcspec-scaling.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM

echo "cores: $(getconf _NPROCESSORS_ONLN 2>/dev/null || echo '?')"
echo
echo "== one level of the reduction: save + load + merge of a spectrum (best of 5)"
"$IO_COST"
echo
echo "== mcspec-mpi --timing (trials per second per rank; reduction after a barrier)"
while read -r kind n k t; do
    for p in 1 2 4; do
        printf '%-10s N=%-5s K=%-4s T=%-7s P=%s: ' "$kind" "$n" "$k" "$t" "$p"
        # shellcheck disable=SC2086
        "$MPIRUN" $mpiflags -np "$p" "$MCSPEC_MPI" pattern "$kind" --n "$n" --k "$k" \
            --trials "$t" --seed 1 --save "$work/s.rec" --timing 2>&1 >/dev/null </dev/null |
            sed -n 's/^mcspec-mpi: //p'
    done
done <<'RUNS'
stratified 4096 64 20000
random 256 16 400000
jitter 64 8 2000000
RUNS
