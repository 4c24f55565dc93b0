"""The numpy peer of build/bench/pointset_jobs: the point-set periodogram by
the direct sum a numpy user writes, one batched exp of the phase matrix per
chunk of wave vectors (chunked to hold at most 2^22 complex entries, 64 MB),
then |S|^2 / K and a Welford update of the mean and M2 per wave vector, as
mcs_pointset2d keeps them.

A co-process: each line on stdin is "PATH K DIM F BUDGET": K points of DIM
coordinates (binary64, interleaved) in PATH, cutoff F. It times, by its
thread's CPU clock, whole chunks in the stored order (fy = 0..F, fx = -F..F
in 2D; f = 0..F in 1D) until BUDGET seconds are spent or the set is done,
and answers "SECONDS DONE TOTAL": the time of the DONE wave vectors of the
TOTAL a set has. The direct sum costs the same per wave vector everywhere,
so the set's time is SECONDS x TOTAL / DONE (the caller says it
extrapolates). An empty line ends it."""
import sys
import time

import numpy as np

CHUNK_ENTRIES = 1 << 22


def wave_vectors(dim, f):
    if dim == 1:
        return np.arange(0, f + 1, dtype=np.float64)[:, None]
    fy, fx = np.meshgrid(np.arange(0, f + 1), np.arange(-f, f + 1), indexing="ij")
    return np.stack([fx.ravel(), fy.ravel()], axis=1).astype(np.float64)


def time_set(pts, dim, f, budget):
    k = pts.shape[0]
    kv = wave_vectors(dim, f)
    total = kv.shape[0]
    mean = np.zeros(total)
    m2 = np.zeros(total)
    count = 1.0
    step = max(1, CHUNK_ENTRIES // k)
    spent = 0.0
    done = 0
    while done < total and spent < budget:
        t0 = time.thread_time()
        sl = slice(done, min(total, done + step))
        phase = kv[sl] @ pts.T  # k.x_j for the chunk's wave vectors
        s = np.exp(-2j * np.pi * phase).sum(axis=1)
        p = (s.real ** 2 + s.imag ** 2) / k
        d = p - mean[sl]
        mean[sl] += d / count
        m2[sl] += d * (p - mean[sl])
        spent += time.thread_time() - t0
        done = sl.stop
    return spent, done, total


def main():
    for line in sys.stdin:
        if not line.strip():
            break
        path, k, dim, f, budget = line.split()
        k, dim, f, budget = int(k), int(dim), int(f), float(budget)
        pts = np.fromfile(path, dtype="<f8").reshape(k, dim)
        spent, done, total = time_set(pts, dim, f, budget)
        print("%.9g %d %d" % (spent, done, total), flush=True)


if __name__ == "__main__":
    main()
