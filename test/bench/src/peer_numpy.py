"""The numpy peer of the mcspec bench: what a careful numpy user would write
instead of mcspec, driven by the C harness over a pipe so that its slices
interleave with the C contenders' rounds.

Per batch of B trials: draw every trial's K bins at once (numpy's own
generator; stratified bins floor((j + u) N / K), random bins uniform in
[0, N)), build the dense s of all B trials with one weighted bincount (the
(bin, weight) form, weights 1 here), one batched rfft along the rows,
normalise by 1/sqrt(N) (eq. 7), then per frequency the batch's mean and M2
of S_k and of |S_k|^2, merged into the running ones by Chan et al. (the same
read-outs as mcs_spectrum). The batch size is the best of a few, measured
when a cell starts.

Protocol (one line each way, the reply flushed):
  clock cpu|wall      -> ok 0              time by the thread's CPU clock (the
                                           default) or by the wall clock
  cell N K KIND SEED  -> ok BATCH          set up a cell, pick the batch size
  slice SECONDS       -> done TRIALS SECS  run whole batches for >= SECONDS
  read FREQ           -> power VALUE SE    <|S_k|^2> and its standard error
  quit                                      exit
On start it prints: ready NUMPY_VERSION PYTHON_VERSION.
"""
import math
import platform
import sys
import time

import numpy as np

BATCHES = (16, 64, 256, 1024, 4096)
MAX_BATCH_VALUES = 1 << 20  # B * N cap: 8 MB per dense batch
CALIBRATE_SECONDS = 0.01
CALIBRATE_PASSES = 3
CLOCKS = {"cpu": time.thread_time, "wall": time.perf_counter}
clock = CLOCKS["cpu"]


class Peer:
    def __init__(self, n, k, kind, seed):
        self.n, self.k = n, k
        self.stratified = kind == "stratified"
        self.rng = np.random.default_rng(seed)
        self.scale = 1.0 / math.sqrt(n)
        self.strata = np.arange(k, dtype=np.float64)
        self.weights = {}
        self.batch = BATCHES[0]
        self.reset()

    def reset(self):
        h1 = self.n // 2 + 1
        self.count = 0
        self.mean = np.zeros(h1, dtype=np.complex128)
        self.m2_s = np.zeros(h1)
        self.mean_pow = np.zeros(h1)
        self.m2_pow = np.zeros(h1)

    def dense(self, b):
        n, k = self.n, self.k
        if self.stratified:
            bins = ((self.strata + self.rng.random((b, k))) * (n / k)).astype(np.intp)
            np.minimum(bins, n - 1, out=bins)
        else:
            bins = self.rng.integers(0, n, size=(b, k), dtype=np.intp)
        bins += (np.arange(b, dtype=np.intp) * n)[:, None]
        weights = self.weights.get(b)
        if weights is None:  # w_j = 1 without importance, as mcs_pattern_draw gives
            weights = self.weights[b] = np.ones(b * k)
        return np.bincount(bins.ravel(), weights=weights, minlength=b * n).reshape(b, n)

    def run_batch(self, b):
        spec = np.fft.rfft(self.dense(b), axis=1)
        spec *= self.scale
        mean_b = spec.mean(axis=0)
        dev = spec - mean_b
        m2s_b = (dev.real * dev.real + dev.imag * dev.imag).sum(axis=0)
        power = spec.real * spec.real + spec.imag * spec.imag
        mean_pow_b = power.mean(axis=0)
        power -= mean_pow_b
        m2p_b = (power * power).sum(axis=0)
        self.merge(b, mean_b, m2s_b, mean_pow_b, m2p_b)

    def merge(self, nb, mean_b, m2s_b, mean_pow_b, m2p_b):
        """Chan, Golub and LeVeque: shift each mean by its gap times nb/n and
        add the gap's share na nb / n to M2."""
        na = self.count
        nt = na + nb
        wb, wab = nb / nt, na * nb / nt
        d = mean_b - self.mean
        self.mean += d * wb
        self.m2_s += m2s_b + (d.real * d.real + d.imag * d.imag) * wab
        dp = mean_pow_b - self.mean_pow
        self.mean_pow += dp * wb
        self.m2_pow += m2p_b + dp * dp * wab
        self.count = nt

    def timed(self, b, seconds):
        """Whole batches of b until `seconds` have passed: (trials, seconds)."""
        trials = 0
        t0 = clock()
        while True:
            self.run_batch(b)
            trials += b
            t = clock() - t0
            if t >= seconds:
                return trials, t

    def calibrate(self):
        """Best trials/s of each batch size over a few passes that alternate
        between the sizes (a pass another process slowed down is outvoted)."""
        sizes = [b for b in BATCHES if b * self.n <= MAX_BATCH_VALUES] or [BATCHES[0]]
        best = dict.fromkeys(sizes, 0.0)
        for b in sizes:
            self.run_batch(b)  # warm-up
        for _ in range(CALIBRATE_PASSES):
            for b in sizes:
                trials, t = self.timed(b, CALIBRATE_SECONDS)
                best[b] = max(best[b], trials / t)
        self.batch = max(sizes, key=lambda b: best[b])
        self.reset()
        return self.batch

    def read(self, freq):
        q = freq if freq <= self.n // 2 else self.n - freq
        t = self.count
        return self.mean_pow[q], math.sqrt(self.m2_pow[q] / (t - 1) / t)


def reply(text):
    sys.stdout.write(text + "\n")
    sys.stdout.flush()


def main():
    global clock
    reply("ready %s %s" % (np.__version__, platform.python_version()))
    peer = None
    for line in sys.stdin:
        words = line.split()
        if not words:
            continue
        if words[0] == "clock" and words[1] in CLOCKS:
            clock = CLOCKS[words[1]]
            reply("ok 0")
        elif words[0] == "cell":
            n, k, kind, seed = int(words[1]), int(words[2]), words[3], int(words[4])
            peer = Peer(n, k, kind, seed)
            reply("ok %d" % peer.calibrate())
        elif words[0] == "slice":
            trials, t = peer.timed(peer.batch, float(words[1]))
            reply("done %d %.9f" % (trials, t))
        elif words[0] == "read":
            value, se = peer.read(int(words[1]))
            reply("power %.17g %.17g" % (value, se))
        elif words[0] == "quit":
            return
        else:
            reply("error unknown command %s" % words[0])


if __name__ == "__main__":
    main()
