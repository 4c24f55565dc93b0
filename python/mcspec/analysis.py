"""Pair correlation (pcf.h), psa's spectral statistics (radial.h), the
integration error over integrand families (integrand.h, integrate.h) and
the 2D projections of a d-dimensional sampler (projections.h), each as the
matching command computes it (`mcspec pcf`, `stats`, `integrate`,
`projections`), so the numbers are the same bit for bit."""
import collections
import ctypes
import math

import numpy as np

from . import _lib
from ._lib import Buffer, Error, check, fn, struct
from ._points import call_points as _call, sets_array, where_bad
from .accumulators import IntegrationError
from .sampling import PATTERNS_2D, sample

Pcf = collections.namedtuple("Pcf", "r mean stderr exact")
SpectralStats = collections.namedtuple("SpectralStats", "mean stderr")


def _sets(parts):
    """(k, one set's array) of every set in order."""
    for arr in parts:
        for t in range(arr.shape[0]):
            yield arr.shape[1], np.ascontiguousarray(arr[t], dtype=np.float64)


def _all_in_range(parts):
    top = np.nextafter(1.0, 0.0)
    for arr in parts:
        if not ((arr >= 0) & (arr <= top)).all():
            raise Error(_lib.ERR_POINT_RANGE, where_bad(arr))


def _double(f, *args):
    v = ctypes.c_double()
    st = f(*args, ctypes.addressof(v))
    return st, v.value


# ---- pair correlation --------------------------------------------------------

class PairCorrelation:
    """The pair correlation accumulator (mcs_pcf over its own buffer): g(r)
    of 1D or 2D sets over bins bins of [0, radius) mean spacings, psa's RDF
    (rdf=True) or the Gaussian-kernel PCF of kernel sigma. add(sets) adds
    each set as one trial (one library call a set, every point checked
    before any is added), merge(other) takes another of the same shape;
    read-outs r, mean, stderr (NaN below 2 sets) and exact(pattern, k) are
    arrays [bins] (one library call per bin: pcf.h reads a bin at a time)."""

    def __init__(self, dim=2, radius=3.0, bins=60, sigma=0.1, rdf=False):
        bins, dim = int(bins), int(dim)
        size = ctypes.c_size_t(0)
        check(fn.pcf_size(bins, ctypes.addressof(size)), "mcs_pcf_size(B = %d)" % bins)
        self._acc = struct("pcf")
        self._mem = Buffer(size.value)
        check(fn.pcf_init(self._acc.addr, dim, 0 if rdf else 1, bins, float(radius), float(sigma),
                          self._mem.addr, self._mem.size),
              "mcs_pcf_init(dim %d, radius %r, sigma %r)" % (dim, radius, sigma))
        self.dim, self.bins, self.rdf = dim, bins, bool(rdf)
        self.radius, self.sigma = float(radius), float(sigma)
        self._work = Buffer(1)

    def add(self, sets):
        parts, d = sets_array(sets, self.dim)
        _all_in_range(parts)
        todo = []
        for kk, one in _sets(parts):  # every set's K checked before any is added
            need = ctypes.c_size_t(0)
            check(fn.pcf_work_size(self._acc.addr, kk, ctypes.addressof(need)),
                  "mcs_pcf_work_size(K = %d: the radius reaches past half the torus)" % kk)
            todo.append((kk, one, need.value))
        for kk, one, need in todo:
            if need > self._work.size:
                self._work = Buffer(need)
            _call(fn.pcf_add(self._acc.addr, kk, one.ctypes.data, self._work.addr,
                             self._work.size), one, "mcs_pcf_add")
        return self

    def merge(self, other):
        if not isinstance(other, PairCorrelation):
            raise Error(_lib.ERR_MISMATCH, "merge takes a PairCorrelation")
        check(fn.pcf_merge(self._acc.addr, other._acc.addr), "mcs_pcf_merge")
        return self

    @property
    def count(self):
        c = ctypes.c_uint64(0)
        check(fn.pcf_count(self._acc.addr, ctypes.addressof(c)), "mcs_pcf_count")
        return c.value

    def _column(self, which):
        """One read-out over every bin in one call (mcs_pcf_read_all: 0 the
        radii, 1 the means, 2 their standard errors); NaN where the library
        has none (no set, or one set for the standard error)."""
        col = np.full(self.bins, np.nan)
        ptrs = [None, None, None]
        ptrs[which] = col.ctypes.data
        if fn.pcf_read_all(self._acc.addr, self.bins, *ptrs) != 0:
            col[:] = np.nan
        return col

    @property
    def r(self):
        return self._column(0)

    @property
    def mean(self):
        return self._column(1)

    @property
    def stderr(self):
        return self._column(2)

    def exact(self, pattern=None, k=None):
        """E g per bin (mcs_pcf_exact): pattern None for independent uniform
        points, else a 2D pattern name with k points (its strata the most
        nearly square); NaN where the library has none."""
        pat = None
        if pattern is not None:
            if pattern not in PATTERNS_2D or k is None:
                raise Error(_lib.ERR_KIND, "pattern is a 2D pattern (%s) with its k, not %r"
                            % (", ".join(PATTERNS_2D), pattern))
            pat = struct("pattern2d")
            check(fn.pattern2d_init(pat.addr, PATTERNS_2D[pattern], int(k), 0, 0),
                  "mcs_pattern2d_init")
        col = np.full(self.bins, np.nan)  # one call per bin: the exact value is a quadrature
        for b in range(self.bins):
            st, v = _double(fn.pcf_exact, self._acc.addr, None if pat is None else pat.addr, b)
            if st == 0:
                col[b] = v
        return col

    def __repr__(self):
        return "<mcspec.PairCorrelation %s dim=%d bins=%d radius=%g sets=%d>" % (
            "rdf" if self.rdf else "gaussian", self.dim, self.bins, self.radius, self.count)


def pcf(sets, radius=3.0, bins=60, sigma=0.1, rdf=False, exact=None, k=None):
    """The pair correlation g(r) of 1D or 2D sets (mcs_pcf): per bin its
    centre r (mean spacings), the mean over the sets, its standard error
    (NaN below 2 sets) and the exact E g (NaN where none), as a Pcf of four
    arrays [bins], the columns of `mcspec pcf --csv`. rdf=True: psa's RDF,
    else the Gaussian-kernel PCF of kernel sigma. exact: None, "random"
    (independent uniform points, as --exact random) or a 2D pattern name
    (random, jittered, grid, shifted-grid, n-rooks), whose strata are those
    of k points (default the sets' first K), as `mcspec pcf KIND --k K`
    fills it. A refused call adds nothing and changes nothing."""
    parts, d = sets_array(sets)
    if d not in (1, 2):
        raise Error(_lib.ERR_DOMAIN, "the pair correlation takes 1D or 2D sets, not %dD" % d)
    if exact not in (None, "random") and (exact not in PATTERNS_2D or d != 2):
        raise Error(_lib.ERR_KIND, "exact is None, 'random' or a 2D pattern (%s), not %r"
                    % (", ".join(PATTERNS_2D), exact))
    acc = PairCorrelation(d, radius, bins, sigma, rdf).add(sets)
    if exact is None:
        ex = np.full(acc.bins, np.nan)
    elif exact == "random" and k is None:
        ex = acc.exact()
    else:
        ex = acc.exact(exact, k if k is not None else parts[0].shape[1])
    return Pcf(acc.r, acc.mean, acc.stderr, ex)


# ---- psa's spectral statistics -----------------------------------------------

def _welford(values):
    w = struct("welford")
    check(fn.welford_init(w.addr), "mcs_welford_init")
    for v in values:
        check(fn.welford_add(w.addr, float(v)), "mcs_welford_add")
    out = []
    for f in (fn.welford_mean, fn.welford_stderr):
        st, v = _double(f, w.addr)
        out.append(v if st == 0 else math.nan)
    return out


def effective_nyquist(power, k, dim=2, step=1.0):
    """psa's effective Nyquist frequency of a radial power power[n] (entry i
    at frequency i step; 2D: annulus i), over K^(1/d)."""
    p = np.ascontiguousarray(power, dtype=np.float64)
    st, v = _double(fn.radial_effective_nyquist, int(dim), int(k), p.size, p.ctypes.data,
                    float(step))
    check(st, "mcs_radial_effective_nyquist")
    return v


def oscillations(power, k, dim=2, step=1.0):
    """psa's oscillation metric of a radial power power[n] (as above)."""
    p = np.ascontiguousarray(power, dtype=np.float64)
    st, v = _double(fn.radial_oscillations, int(dim), int(k), p.size, p.ctypes.data, float(step))
    check(st, "mcs_radial_oscillations")
    return v


def spectral_stats(sets, freq=None):
    """The spectral rows of `mcspec stats --csv` for 1D or 2D sets, as a
    dict name -> (mean, stderr): effective_nyquist and oscillations of each
    set's radial power (2D: annulus average, 1D: P(f), f = 0..F), their
    mean and standard error over the sets (a set with no oscillation value
    is left out of it), and effective_nyquist_of_mean and
    oscillations_of_mean of the mean spectrum (NaN for sets of several K;
    stderr NaN). F defaults to the command's, ceil(5 sqrt(K)) in 2D and 5 K
    in 1D for the first set's K. One periodogram call per set."""
    parts, d = sets_array(sets)
    if d not in (1, 2):
        raise Error(_lib.ERR_DOMAIN, "the spectral rows are for 1D or 2D sets, not %dD" % d)
    _all_in_range(parts)
    k0 = parts[0].shape[1]
    if freq is None:
        freq = 5 * k0 if d == 1 else int(math.ceil(5.0 * math.sqrt(k0)))
    freq = int(freq)
    name = "pointset" if d == 1 else "pointset2d"
    size = ctypes.c_size_t(0)
    check(getattr(fn, name + "_size")(freq, 0, ctypes.addressof(size)), "mcs_%s_size" % name)
    hdr, mem = struct(name), Buffer(size.value)
    n = freq + 1
    total = np.zeros(n)
    power = np.empty(n)
    vals = ([], [])
    same_k, nsets = True, 0
    for kk, one in _sets(parts):
        check(getattr(fn, name + "_init")(hdr.addr, freq, 0, mem.addr, mem.size), "init")
        _call(getattr(fn, name + "_add_sets")(hdr.addr, 1, kk, one.ctypes.data), one, "add")
        if d == 1:
            check(fn.pointset_read_all(hdr.addr, n, power.ctypes.data, None), "read_all")
        else:
            check(fn.pointset2d_radial_all(hdr.addr, n, power.ctypes.data, None, None),
                  "radial_all")
        total += power
        same_k = same_k and kk == k0
        nsets += 1
        st, v = _double(fn.radial_effective_nyquist, d, kk, n, power.ctypes.data, 1.0)
        check(st, "mcs_radial_effective_nyquist")
        vals[0].append(v)
        st, v = _double(fn.radial_oscillations, d, kk, n, power.ctypes.data, 1.0)
        if st == 0:
            vals[1].append(v)
    out = {"effective_nyquist": SpectralStats(*_welford(vals[0])),
           "oscillations": SpectralStats(*_welford(vals[1]))}
    mean = total / nsets
    for key, f in (("effective_nyquist", fn.radial_effective_nyquist),
                   ("oscillations", fn.radial_oscillations)):
        st, v = _double(f, d, k0, n, mean.ctypes.data, 1.0) if same_k else (1, 0.0)
        out[key + "_of_mean"] = SpectralStats(v if st == 0 else math.nan, math.nan)
    return out


# ---- integration error -------------------------------------------------------

FAMILIES = ("gaussian", "gaussian_periodic", "heaviside", "disk", "cosine", "blinn_phong",
            "gaussian_mixture")


def _family_names():
    return [_lib.cstr(fn.integrand_family_str(i)) for i in range(len(FAMILIES))]


def integration_error(sets, integrands=16, seed=1, family=None, freq=None, exact=None):
    """The integration error of the sets over each integrand family, as
    `mcspec integrate --csv FILE` computes it: per family (dict key, the
    command's name) a dict of arrays over the sets' K (ascending, key "k"):
    mse, mse_stderr, exact, predicted, predicted_tail, freq, sets. For every
    set, in order, each family draws `integrands` fresh integrands from
    PCG32 (seed, 1000 + family) and adds the set's mean squared error
    (mcs_integrate_add); the prediction (periodic families) is eq. 14 from
    the sets' mean periodogram to F (default 2 ceil(sqrt K) capped at 128 in
    2D, 4 K capped at 65536 in 1D; 0: none). exact: None, "random" or
    "jittered" (the most nearly square grid of K cells in 2D). One library
    call per set and integrand (the draws), per set and family (the add).
    Each family's dict also has the command's slope (least squares of log
    mse on log K over its rows; NaN below two K), rate_random and
    rate_jittered (the reference slopes), repeated per row as the CSV has
    them."""
    parts, d = sets_array(sets)
    if d not in (1, 2):
        raise Error(_lib.ERR_DOMAIN, "the integrands take 1D or 2D points, not %dD" % d)
    if exact not in (None, "random", "jittered"):
        raise Error(_lib.ERR_KIND, "exact is None, 'random' or 'jittered', not %r" % (exact,))
    _all_in_range(parts)
    ref = {None: 0, "random": 1, "jittered": 2}[exact]
    return _integrate(((kk, one, ref) for kk, one in _sets(parts)), d, integrands, seed, family,
                      freq)


def integration_error_of(kind, ks, dim=2, sets=64, integrands=16, seed=1, family=None,
                         freq=None):
    """The integration error of `sets` sets of each K in ks drawn from
    `kind` (any kind sample() draws in dim 1 or 2), as `mcspec integrate KIND
    --k K1,K2,... --dim D --sets T --csv`: the sets of the i-th K from PCG32
    (seed, 1 + i), the exact column for random, jittered (2D) and
    stratified (1D). Returns what integration_error() does."""
    ks = [int(k) for k in (ks if hasattr(ks, "__len__") else [ks])]
    dim = int(dim)
    if dim not in (1, 2):
        raise Error(_lib.ERR_DOMAIN, "the integrands take 1D or 2D points, not %dD" % dim)
    if not ks:
        raise Error(_lib.ERR_K_RANGE, "no K given")
    refs = {"random": 1, "jittered" if dim == 2 else "stratified": 2}

    def items():
        for i, k in enumerate(ks):
            pts = sample(kind, dim, k, sets=sets, seed=seed, stream=1 + i)
            for one in pts:
                yield k, one, refs.get(kind, 0)
    for k in ks:  # every K drawable before anything is done
        sample(kind, dim, k, sets=1, seed=seed)
    return _integrate(items(), dim, integrands, seed, family, freq)


def _integrate(items, d, integrands, seed, family, freq):
    """The accumulation of integration_error over (k, set, reference) items."""
    names = _family_names()
    if family is not None and family not in names:
        raise Error(_lib.ERR_KIND, "unknown family %r (%s)" % (family, ", ".join(names)))
    m = int(integrands)
    if m < 1:
        raise Error(_lib.ERR_K_RANGE, "integrands must be at least 1, not %d" % m)
    if family is not None and not fn.integrand_has_dim(names.index(family), d):
        raise Error(_lib.ERR_DOMAIN, "family %s has no %dD integrands" % (family, d))
    fams = [f for f in range(len(names)) if (family is None or names[f] == family)
            and fn.integrand_has_dim(f, d)]
    isz = _lib.struct_size("integrand")
    rngs = {}
    for f in range(len(names)):
        rngs[f] = struct("rng")
        check(fn.rng_seed(rngs[f].addr, int(seed) & (2**64 - 1), 1000 + f), "mcs_rng_seed")
    periodic = [f for f in fams if fn.integrand_is_periodic(f)]
    exact_of = {0: None, 1: "random", 2: "jittered"}
    groups = {}
    ps_name = "pointset" if d == 1 else "pointset2d"
    for kk, one, ref in items:
        g = groups.get(kk)
        if g is None:
            # one accumulator a family and K, all of a family on its one stream
            g = groups[kk] = {"acc": {f: IntegrationError(names[f], d, m, seed, exact_of[ref])
                                      ._share_stream(rngs[f]) for f in fams},
                              "fs": {f: [] for f in fams}, "sets": 0}
            fq = freq if freq is not None else (min(4 * kk, 65536) if d == 1 else
                                                min(2 * int(math.ceil(math.sqrt(kk))), 128))
            g["freq"] = int(fq)
            g["ps"] = None
            if g["freq"] > 0 and periodic:
                size = ctypes.c_size_t(0)
                check(getattr(fn, ps_name + "_size")(g["freq"], 0, ctypes.addressof(size)),
                      "mcs_%s_size(F = %d)" % (ps_name, g["freq"]))
                g["ps"] = (struct(ps_name), Buffer(size.value))
                check(getattr(fn, ps_name + "_init")(g["ps"][0].addr, g["freq"], 0,
                                                     g["ps"][1].addr, size.value), "init")
        for f in fams:
            acc = g["acc"][f]
            acc.exact_kind = exact_of[ref]
            acc._add(one[np.newaxis], g["fs"][f] if fn.integrand_is_periodic(f) else None)
        if g["ps"] is not None:
            _call(getattr(fn, ps_name + "_add_sets")(g["ps"][0].addr, 1, kk, one.ctypes.data),
                  one, "add")
        g["sets"] += 1
    out = {}
    ks = sorted(groups)
    for f in fams:
        cols = {c: np.full(len(ks), np.nan) for c in
                ("mse", "mse_stderr", "exact", "predicted", "predicted_tail", "freq", "sets")}
        for i, kk in enumerate(ks):
            g = groups[kk]
            acc = g["acc"][f]
            cols["mse"][i], cols["mse_stderr"][i], cols["exact"][i] = (acc.mse, acc.mse_stderr,
                                                                       acc.exact)
            cols["sets"][i] = g["sets"]
            if g["ps"] is not None and g["fs"][f]:
                allfs = Buffer(isz * m * len(g["fs"][f]))
                for j, fs in enumerate(g["fs"][f]):
                    allfs.array[j * isz * m:(j + 1) * isz * m] = fs.array
                pred, tail = ctypes.c_double(), ctypes.c_double()
                call = fn.integrand_predict if d == 2 else fn.integrand_predict_1d
                check(call(allfs.addr, m * len(g["fs"][f]), g["ps"][0].addr, kk,
                           ctypes.addressof(pred), ctypes.addressof(tail)), "mcs_integrand_predict")
                cols["predicted"][i], cols["predicted_tail"][i] = pred.value, tail.value
                cols["freq"][i] = g["freq"]
        cols["k"] = np.array(ks)
        slope = _slope(ks, cols["mse"])
        smooth = names[f] not in ("heaviside", "disk", "gaussian_mixture")
        cols["slope"] = np.full(len(ks), slope)
        cols["rate_random"] = np.full(len(ks), -1.0)
        cols["rate_jittered"] = np.full(len(ks), -(1.0 + (2.0 if smooth else 1.0) / d))
        out[names[f]] = cols
    return out


def _slope(ks, mse):
    """The command's least squares of log mse on log K (its sums, in its
    order; NaN below two positive rows)."""
    n = sx = sy = sxx = sxy = 0.0
    for k, v in zip(ks, mse):
        if v > 0.0:
            x, y = math.log(float(k)), math.log(float(v))
            n += 1.0
            sx += x
            sy += y
            sxx += x * x
            sxy += x * y
    den = n * sxx - sx * sx
    return (n * sxy - sx * sy) / den if n >= 2.0 and den > 0.0 else math.nan


# ---- projections -------------------------------------------------------------

class _Pair(ctypes.Structure):
    # mcs_projections_pair (projections.h); its size is checked against
    # mcs_abi_sizeof(MCS_ABI_PROJECTIONS_PAIR) before use.
    _fields_ = [(n, ctypes.c_double) for n in (
        "radial_low", "radial_low_stderr", "radial_low_ref", "radial_low_z", "anisotropy_db",
        "discrepancy", "discrepancy_stderr", "discrepancy_random", "peak", "peak_stderr",
        "peak_max", "peak_threshold")] + [("flagged", ctypes.c_int)]


PROJECTION_COLUMNS = ("dim_i", "dim_j", "radial_low", "radial_low_stderr", "anisotropy_db",
                      "discrepancy", "peak", "peak_stderr", "flagged", "radial_low_ref",
                      "radial_low_z", "discrepancy_stderr", "discrepancy_random", "peak_max",
                      "peak_threshold")


def projections(sets, freq=8, radius=3, disc_sets=4):
    """For every pair of dimensions (i, j), i < j, of d-dimensional sets
    (d = 2..64), the columns of `mcspec projections --csv` (same defaults) as
    a dict of arrays over the pairs in the command's order: dim_i, dim_j,
    radial_low, ..., flagged (int), ..., peak_threshold. One library call per
    set (mcs_projections_add), one per pair for the read-out."""
    parts, d = sets_array(sets)
    if ctypes.sizeof(_Pair) != _lib.struct_size("projections_pair"):
        raise Error(_lib.ERR_MISMATCH, "mcs_projections_pair is %d bytes in this library, not %d"
                    % (_lib.struct_size("projections_pair"), ctypes.sizeof(_Pair)))
    kmax = max(p.shape[1] for p in parts)
    size = ctypes.c_size_t(0)
    check(fn.projections_size(d, int(freq), kmax, ctypes.addressof(size)),
          "mcs_projections_size(d = %d, F = %d)" % (d, int(freq)))
    acc, mem = struct("projections"), Buffer(size.value)
    check(fn.projections_init(acc.addr, d, int(freq), int(radius), kmax, int(disc_sets), mem.addr,
                              mem.size), "mcs_projections_init")
    _all_in_range(parts)
    for kk, one in _sets(parts):
        _call(fn.projections_add(acc.addr, kk, one.ctypes.data), one, "mcs_projections_add")
    rows = []
    r = _Pair()
    for i in range(d):
        for j in range(i + 1, d):
            check(fn.projections_pair_stats(acc.addr, i, j, ctypes.addressof(r)),
                  "mcs_projections_pair_stats")
            rows.append([i, j] + [getattr(r, c) for c in PROJECTION_COLUMNS[2:]])
    m = np.array(rows, dtype=np.float64).reshape(-1, len(PROJECTION_COLUMNS))
    out = {c: m[:, n].copy() for n, c in enumerate(PROJECTION_COLUMNS)}
    for c in ("dim_i", "dim_j", "flagged"):
        out[c] = out[c].astype(np.int64)
    return out
