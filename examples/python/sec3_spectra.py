"""Section 3 of the note from Python: the power spectra of random,
stratified and uniform-jitter sampling over N bins (sections 3.1-3.3),
measured over trials beside the exact spectrum (mcs_theory_spectrum) and
the note's closed forms: random K/N at k != 0 (eq. 23); stratified
(K/N)(1 - sinc^2(pi k / K)) as N -> infinity (eq. 33); jitter K^2/N at
multiples of K, else 0 (eq. 36). Every number printed is computed.

    PYTHONPATH=python /usr/bin/python3 examples/python/sec3_spectra.py [--plot sec3.png]
"""
import argparse

import numpy as np

import mcspec


def closed(kind, n, k, freq):
    f = np.asarray(freq, dtype=float)
    if kind == "random":
        return np.full_like(f, k / n)
    if kind == "stratified":
        return (k / n) * (1.0 - np.sinc(f / k) ** 2)
    return np.where(np.asarray(freq) % k == 0, k * k / n, 0.0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=256)
    ap.add_argument("--k", type=int, default=16)
    ap.add_argument("--trials", type=int, default=4000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--plot")
    a = ap.parse_args()
    show = sorted({f for f in (1, 2, 4, 8, a.k, a.k + 1, 2 * a.k, a.n // 2) if f <= a.n // 2})
    print("N = %d bins, K = %d samples, %d trials, seed %d; z = (measured - exact) / stderr"
          % (a.n, a.k, a.trials, a.seed))
    results = {}
    for kind in ("random", "stratified", "jitter"):
        pat = mcspec.Pattern(kind, a.n, a.k)
        bins, w = pat.draw(a.trials, seed=a.seed)
        acc = mcspec.Spectrum(a.n).add(bins, w)
        r = acc.read_all()
        exact = mcspec.TheorySpectrum(pat).power
        cf = closed(kind, a.n, a.k, np.arange(len(exact)))
        results[kind] = (r, exact)
        print("\n%s (section 3.%d)" % (kind, {"random": 1, "stratified": 2, "jitter": 3}[kind]))
        print("%6s %12s %10s %12s %12s %8s" % ("k", "measured", "stderr", "exact", "closed", "z"))
        diff = r["power"] - exact
        # a deterministic entry that agrees to rounding has z = 0 (as the command)
        agree = np.abs(diff) <= 1e-12 * np.maximum(1.0, np.abs(exact))
        zs = np.where(agree, 0.0, diff / np.where(r["power_stderr"] > 0, r["power_stderr"], 1.0))
        for k in show:
            z = zs[k]
            se = r["power_stderr"][k]
            print("%6d %12.6f %10.6f %12.6f %12.6f %8.2f"
                  % (k, r["power"][k], se, exact[k], cf[k], z))
        print("largest |z| over k = 1..N/2: %.2f" % np.abs(zs[1:]).max())
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4))
        for kind, (r, exact) in results.items():
            k = np.arange(1, len(exact))
            ax.plot(k, r["power"][1:], label="%s measured" % kind)
            ax.plot(k, exact[1:], "k--", lw=0.8)
        ax.set_xlabel("frequency k")
        ax.set_ylabel("<|S_k|^2>")
        ax.legend()
        fig.savefig(a.plot, dpi=80)


if __name__ == "__main__":
    main()
