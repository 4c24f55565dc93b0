"""The binned objects of the note: importance functions and patterns over N
bins (importance.h, pattern.h), the accumulators of measured spectra
(spectrum.h, moment.h, autocorr.h) and the exact theory beside them
(theory.h). Each holds its C struct as an opaque 64-byte aligned buffer
sized by mcs_abi_sizeof; read-outs are whole arrays."""
import ctypes

import numpy as np

from . import _lib
from ._lib import Error, addr, check, fn, struct
from ._points import where_bad

_INDEX = np.uintp  # size_t


def _doubles(a, what, n=None):
    if a is None:
        raise Error(_lib.ERR_NULL, "%s is None" % what)
    arr = np.asarray(a)
    if arr.dtype.kind not in "fiu":
        raise Error(_lib.ERR_NOT_FINITE, "%s has dtype %s: give real numbers" % (what, arr.dtype))
    arr = np.ascontiguousarray(arr, dtype=np.float64)
    if n is not None and arr.shape != (n,):
        raise Error(_lib.ERR_MISMATCH, "%s has shape %s, not (%d,)" % (what, arr.shape, n))
    return arr


def _complex_matrix(name, obj, n):
    """An (n, n) complex read-out of obj by mcs_<name>(obj, n, re, im)."""
    re = np.empty((n, n))
    im = np.empty((n, n))
    check(getattr(fn, name)(obj.addr, n, re.ctypes.data, im.ctypes.data), "mcs_" + name)
    return re + 1j * im


def _bins(b, k, n):
    arr = np.asarray(b)
    if arr.dtype.kind not in "iu":
        raise Error(-7, "bins have dtype %s: give integers in [0, N)" % arr.dtype)
    if arr.shape != (k,):
        raise Error(_lib.ERR_MISMATCH, "bins have shape %s, not (%d,)" % (arr.shape, k))
    if k and (arr.min() < 0 or arr.max() >= n):
        raise Error(-7, "a bin is outside [0, %d)" % n)  # MCS_ERR_BIN_RANGE
    return np.ascontiguousarray(arr, dtype=_INDEX)


class Importance:
    """An importance function over n = len(weights) bins (mcs_importance)."""

    def __init__(self, weights):
        w = _doubles(weights, "weights")
        if w.ndim != 1:
            raise Error(_lib.ERR_MISMATCH, "weights must be one-dimensional")
        self.n = w.shape[0]
        self._obj = struct("importance")
        check(fn.importance_init(self._obj.addr, self.n, w.ctypes.data), "mcs_importance_init")


class Pattern:
    """A 1D pattern kind over n bins with k samples per trial (mcs_pattern),
    optionally warped by an Importance of n bins (kept alive here)."""

    def __init__(self, kind, n, k, importance=None):
        from .sampling import PATTERNS_1D
        if kind not in PATTERNS_1D:
            raise Error(_lib.ERR_KIND, "unknown pattern %r (%s)" % (kind, ", ".join(PATTERNS_1D)))
        self.kind, self.n, self.k, self.importance = kind, int(n), int(k), importance
        self._obj = struct("pattern")
        imp = importance._obj.addr if importance is not None else None
        check(fn.pattern_init(self._obj.addr, PATTERNS_1D[kind], self.n, self.k, imp),
              "mcs_pattern_init(%s, N = %d, K = %d)" % (kind, self.n, self.k))

    def draw(self, trials=1, seed=1, stream=0):
        """trials trials from PCG32 seeded (seed, stream): (bins, weights),
        arrays (trials, k) of bin indices and weights 1/p (mcs_pattern_draw)."""
        from .sampling import _rng
        rng = _rng(seed, stream)
        bins = np.empty((int(trials), self.k), dtype=_INDEX)
        w = np.empty((int(trials), self.k))
        for t in range(int(trials)):  # the library draws one trial per call
            check(fn.pattern_draw(self._obj.addr, rng.addr, self.k, bins[t].ctypes.data,
                                  w[t].ctypes.data, None), "mcs_pattern_draw")
        return bins, w


class _Binned:
    """Shared by the accumulators over N bins: add of bins and weights
    (arrays (k,) or a batch (T, k)), merge, count, copy, save."""
    _kind = None

    def __init__(self, n):
        self.n = int(n)
        self._obj = struct(self._kind)
        check(getattr(fn, self._kind + "_init")(self._obj.addr, self.n),
              "mcs_%s_init(N = %d)" % (self._kind, self.n))

    def add(self, bins, weights=None):
        """Adds trials: bins (k,) or (T, k) integers in [0, N), weights of the
        same shape (default all 1). One call per trial (T calls)."""
        b = np.asarray(bins)
        if b.ndim == 1:
            b = b[np.newaxis]
        if b.ndim != 2 or b.shape[1] == 0:
            raise Error(_lib.ERR_K_RANGE, "bins must be (k,) or (T, k) with k >= 1")
        w = np.ones(b.shape) if weights is None else _doubles(weights, "weights")
        if w.ndim == 1:
            w = w[np.newaxis]
        if w.shape != b.shape:
            raise Error(_lib.ERR_MISMATCH, "weights %s and bins %s differ" % (w.shape, b.shape))
        t_, k = b.shape
        b = _bins(b.reshape(-1), t_ * k, self.n).reshape(t_, k)
        before = self._obj.bytes() if t_ > 1 else None
        f = getattr(fn, self._kind + "_add_bins")
        for t in range(t_):
            st = f(self._obj.addr, k, b[t].ctypes.data, w[t].ctypes.data)
            if st != 0:
                if before is not None:  # the trials added before it are taken back
                    self._obj.array[:] = np.frombuffer(before, dtype=np.uint8)
                check(st, "mcs_%s_add_bins (trial %d)" % (self._kind, t))
        return self

    def merge(self, other):
        if type(other) is not type(self):
            raise Error(_lib.ERR_MISMATCH, "merge takes a %s" % type(self).__name__)
        check(getattr(fn, self._kind + "_merge")(self._obj.addr, other._obj.addr),
              "mcs_%s_merge" % self._kind)
        return self

    def copy(self):
        dup = type(self).__new__(type(self))
        dup.__dict__.update(self.__dict__)
        dup._obj = struct(self._kind)
        dup._obj.array[:] = self._obj.array  # these structs hold no pointers
        return dup

    @property
    def count(self):
        c = ctypes.c_uint64()
        check(getattr(fn, self._kind + "_count")(self._obj.addr, ctypes.addressof(c)), "count")
        return c.value

    def save(self):
        from .records import save
        return save(self)

    def __repr__(self):
        return "<mcspec.%s N=%d trials=%d>" % (type(self).__name__, self.n, self.count)


class Spectrum(_Binned):
    """The spectrum accumulator (mcs_spectrum, eq. 7, 13, 14). batch: the
    PAIR path's fixed batch (1: every trial its own unit, as the command
    runs it); None keeps the library's batch rule. Read-outs per stored
    frequency k = 0..N/2 (mcs_spectrum_read_all, one call per array)."""
    _kind = "spectrum"

    def __init__(self, n, batch=1):
        super().__init__(n)
        if batch is not None:
            check(fn.spectrum_set_batch(self._obj.addr, int(batch)), "mcs_spectrum_set_batch")

    def add_points(self, points, weights=None):
        """Adds trials of caller points in [0, 1): (k,) or (T, k) float64 or
        float32, binned at floor(N x). One call per trial."""
        p = np.asarray(points)
        if p.dtype not in (np.float64, np.float32):
            raise Error(_lib.ERR_POINT_RANGE, "points have dtype %s" % p.dtype)
        p = np.ascontiguousarray(p[np.newaxis] if p.ndim == 1 else p)
        w = None if weights is None else _doubles(weights, "weights").reshape(p.shape)
        f = fn.spectrum_add_points_f if p.dtype == np.float32 else fn.spectrum_add_points
        before = self._obj.bytes() if p.shape[0] > 1 else None
        for t in range(p.shape[0]):
            st = f(self._obj.addr, p.shape[1], p[t].ctypes.data,
                   None if w is None else w[t].ctypes.data)
            if st != 0:
                if before is not None:
                    self._obj.array[:] = np.frombuffer(before, dtype=np.uint8)
                if st == _lib.ERR_POINT_RANGE:
                    raise Error(st, where_bad(p))
                check(st, "mcs_spectrum_add_points (trial %d)" % t)
        return self

    def add_dense(self, s):
        s = _doubles(s, "s", self.n)
        check(fn.spectrum_add_dense(self._obj.addr, self.n, s.ctypes.data), "add_dense")
        return self

    def _read(self, which):
        m = self.n // 2 + 1
        arrs = [np.empty(m) if w else None for w in which]
        check(fn.spectrum_read_all(self._obj.addr, m, *[addr(a) for a in arrs]),
              "mcs_spectrum_read_all")
        return arrs

    @property
    def mean(self):
        """<S_k>, complex, k = 0..N/2."""
        re, im, _, _, _ = self._read((1, 1, 0, 0, 0))
        return re + 1j * im

    @property
    def mean_stderr(self):
        return self._read((0, 0, 1, 0, 0))[2]

    @property
    def power(self):
        """<|S_k|^2>, k = 0..N/2."""
        return self._read((0, 0, 0, 1, 0))[3]

    @property
    def power_stderr(self):
        return self._read((0, 0, 0, 0, 1))[4]

    def read_all(self):
        """dict of every read-out array from one library call."""
        re, im, ms, p, ps = self._read((1, 1, 1, 1, 1))
        return {"mean_re": re, "mean_im": im, "mean_stderr": ms, "power": p, "power_stderr": ps}

    @property
    def units(self):
        c = ctypes.c_uint64()
        check(fn.spectrum_units(self._obj.addr, ctypes.addressof(c)), "units")
        return c.value


class Moment(_Binned):
    """The full second moment (mcs_moment, N <= MCS_MAX_COV_N): the cross
    and covariance matrices of S (eq. 16) and Var[I] of an integrand."""
    _kind = "moment"

    def _matrix(self, which):
        return _complex_matrix("moment_" + which, self._obj, self.n)

    @property
    def cross_matrix(self):
        """<S_k S_l*> as an (N, N) complex array."""
        return self._matrix("cross_matrix")

    @property
    def covariance_matrix(self):
        return self._matrix("covariance_matrix")

    @property
    def power(self):
        """<|S_k|^2>, k = 0..N-1 (the real diagonal of the cross matrix)."""
        return self.cross_matrix.diagonal().real.copy()

    def variance(self, f, k):
        """Var[I] of integrand f[N] with k samples per trial."""
        f = _doubles(f, "f", self.n)
        v = ctypes.c_double()
        check(fn.moment_variance(self._obj.addr, self.n, int(k), f.ctypes.data,
                                 ctypes.addressof(v)), "mcs_moment_variance")
        return v.value


class Autocorr(_Binned):
    """The autocorrelation accumulator (mcs_autocorr): mean and power for
    every k = 0..N-1 by one DFT each."""
    _kind = "autocorr"

    def _plan(self):
        plan = struct("dft")
        check(fn.dft_init(plan.addr, self.n), "mcs_dft_init")
        return plan

    @property
    def mean(self):
        re, im = np.empty(self.n), np.empty(self.n)
        plan = self._plan()  # held: a temporary's memory is freed before the call
        check(fn.autocorr_mean(self._obj.addr, plan.addr, self.n, re.ctypes.data,
                               im.ctypes.data), "mcs_autocorr_mean")
        return re + 1j * im

    @property
    def power(self):
        p = np.empty(self.n)
        plan = self._plan()
        check(fn.autocorr_power(self._obj.addr, plan.addr, self.n, p.ctypes.data),
              "mcs_autocorr_power")
        return p


class TheorySpectrum:
    """The exact spectrum of a Pattern for any N (mcs_theory_spectrum):
    mean, variance and power at k = 0..N/2 (mcs_theory_spectrum_read_all)."""

    def __init__(self, pattern):
        self.pattern = pattern
        self.n = pattern.n
        self._obj = struct("theory_spectrum")
        check(fn.theory_spectrum_init(self._obj.addr, pattern._obj.addr),
              "mcs_theory_spectrum_init")

    def read_all(self):
        m = self.n // 2 + 1
        re, im, var, p = (np.empty(m) for _ in range(4))
        check(fn.theory_spectrum_read_all(self._obj.addr, m, re.ctypes.data, im.ctypes.data,
                                          var.ctypes.data, p.ctypes.data),
              "mcs_theory_spectrum_read_all")
        return {"mean": re + 1j * im, "variance": var, "power": p}

    @property
    def mean(self):
        return self.read_all()["mean"]

    @property
    def variance(self):
        return self.read_all()["variance"]

    @property
    def power(self):
        return self.read_all()["power"]

    def estimator_variance(self, f, k=None):
        """Exact Var[I] of integrand f[N] (mcs_theory_spectrum_variance)."""
        f = _doubles(f, "f", self.n)
        v = ctypes.c_double()
        check(fn.theory_spectrum_variance(self._obj.addr, self.n, int(k or self.pattern.k),
                                          f.ctypes.data, ctypes.addressof(v)),
              "mcs_theory_spectrum_variance")
        return v.value


class Theory:
    """Exact first and second moments of a Pattern, N <= MCS_MAX_COV_N
    (mcs_theory): the exact counterpart of Moment."""

    def __init__(self, pattern):
        self.pattern = pattern
        self.n = pattern.n
        self._obj = struct("theory")
        check(fn.theory_init(self._obj.addr, pattern._obj.addr), "mcs_theory_init")

    def _matrix(self, which):
        return _complex_matrix("theory_" + which, self._obj, self.n)

    @property
    def cross_matrix(self):
        return self._matrix("cross_matrix")

    @property
    def covariance_matrix(self):
        return self._matrix("covariance_matrix")

    def variance(self, f, k=None):
        f = _doubles(f, "f", self.n)
        v = ctypes.c_double()
        check(fn.theory_variance(self._obj.addr, self.n, int(k or self.pattern.k), f.ctypes.data,
                                 ctypes.addressof(v)), "mcs_theory_variance")
        return v.value
