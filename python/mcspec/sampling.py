"""Named patterns and samplers as array generators (pattern.h, pattern2d.h,
sampler.h), with the names `mcspec pattern` takes."""
import ctypes

import numpy as np

from . import _lib
from ._lib import Error, check, fn, struct

# mcs_pattern_kind, mcs_pattern2d_kind, mcs_sampler_kind: the command's names.
PATTERNS_1D = {"random": 0, "stratified": 1, "homogenized": 2, "uniform": 3, "jitter": 4}
PATTERNS_2D = {"random": 0, "jittered": 1, "grid": 2, "shifted-grid": 3, "n-rooks": 4,
               "multi-jittered": 5, "cmj": 6}
SAMPLERS = {"van-der-corput": 0, "halton": 1, "hammersley": 2, "sobol-owen": 3, "kronecker": 4}

DEFAULT_BINS = 4096


def kinds(dim):
    """The kinds sample() draws in dimension dim."""
    names = list(PATTERNS_1D if dim == 1 else PATTERNS_2D)
    names += [s for s, v in SAMPLERS.items() if fn.sampler_has_dim(v, dim)]
    return names


def _rng(seed, stream=0):
    rng = struct("rng")
    check(fn.rng_seed(rng.addr, int(seed) & (2**64 - 1), int(stream)), "mcs_rng_seed")
    return rng


def sample(kind, dim, k, sets=1, seed=1, n=None, importance=None, strata=(0, 0)):
    """sets trials of k points of the pattern or sampler `kind` in dim
    dimensions, as a float64 array (sets, k, dim), drawn from PCG32 seeded
    (seed, 0) in order: the trials `mcspec pattern KIND --seed S` draws.

    dim 1: random, stratified, homogenized, uniform, jitter over n bins
    (default 4096; the rounding of a point depends on N; importance: an
    Importance object over the n bins) and the samplers van-der-corput,
    sobol-owen, kronecker. dim 2: random, jittered, grid, shifted-grid,
    n-rooks, multi-jittered, cmj (strata (m, n) with m n = k, (0, 0) the
    most nearly square) and halton, hammersley, sobol-owen, kronecker."""
    k, sets = int(k), int(sets)
    if sets < 1:
        raise Error(_lib.ERR_K_RANGE, "sets must be at least 1, not %d" % sets)
    out = np.empty((sets, k, dim), dtype=np.float64)
    rng = _rng(seed)
    if kind in SAMPLERS and kind not in (PATTERNS_1D if dim == 1 else PATTERNS_2D):
        obj = struct("sampler")
        check(fn.sampler_init(obj.addr, SAMPLERS[kind], dim, k),
              "mcs_sampler_init(%s, dim %d, K = %d)" % (kind, dim, k))
        draw = lambda t: fn.sampler_draw(obj.addr, rng.addr, k, out[t].ctypes.data)
    elif dim == 2 and kind in PATTERNS_2D:
        obj = struct("pattern2d")
        check(fn.pattern2d_init(obj.addr, PATTERNS_2D[kind], k, int(strata[0]), int(strata[1])),
              "mcs_pattern2d_init(%s, K = %d)" % (kind, k))
        draw = lambda t: fn.pattern2d_draw(obj.addr, rng.addr, k, out[t].ctypes.data)
    elif dim == 1 and kind in PATTERNS_1D:
        from .binned import Pattern
        pat = Pattern(kind, DEFAULT_BINS if n is None else n, k, importance)
        bins = np.empty(k, dtype=np.uintp)
        w = np.empty(k)
        draw = lambda t: fn.pattern_draw(pat._obj.addr, rng.addr, k, bins.ctypes.data,
                                         w.ctypes.data, out[t].ctypes.data)
    else:
        raise Error(_lib.ERR_KIND, "unknown %dD kind %r (%s)" % (dim, kind, ", ".join(kinds(dim))))
    # One call per trial: the library draws a trial at a time (no batch entry).
    for t in range(sets):
        check(draw(t), "draw of %s" % kind)
    return out


def base_points(kind, dim, k):
    """The sampler's K points without randomisation (mcs_sampler_base_points)."""
    obj = struct("sampler")
    check(fn.sampler_init(obj.addr, SAMPLERS.get(kind, -1), dim, int(k)), "mcs_sampler_init")
    out = np.empty((int(k), dim))
    check(fn.sampler_base_points(obj.addr, int(k), out.ctypes.data), "mcs_sampler_base_points")
    return out


def exact_power(kind, k, freq, strata=(0, 0)):
    """The exact <P(f)> of a 2D pattern (mcs_pointset2d_exact_power) as an
    array [fy + F, fx + F], and its radial average [r], as (power, radial);
    1D kinds (random, stratified, uniform, jitter) give an array [f]."""
    freq = int(freq)
    if kind in PATTERNS_2D:
        pat = struct("pattern2d")
        check(fn.pattern2d_init(pat.addr, PATTERNS_2D[kind], int(k), *map(int, strata)),
              "mcs_pattern2d_init")
        side = 2 * freq + 1
        power = np.empty((side, side))
        radial = np.empty(freq + 1)
        v = ctypes.c_double()
        # A closed form per wave vector: a loop in Python over (2F+1)^2 calls,
        # for reference values (not a measurement path).
        for iy in range(side):
            for ix in range(side):
                check(fn.pointset2d_exact_power(pat.addr, ix - freq, iy - freq,
                                                ctypes.addressof(v)), "exact_power")
                power[iy, ix] = v.value
        for r in range(freq + 1):
            check(fn.pointset2d_exact_radial(pat.addr, r, ctypes.addressof(v)), "exact_radial")
            radial[r] = v.value
        return power, radial
    if kind in PATTERNS_1D:
        out = np.empty(freq + 1)
        v = ctypes.c_double()
        for f in range(freq + 1):
            check(fn.pointset_exact_power(PATTERNS_1D[kind], int(k), f, ctypes.addressof(v)),
                  "mcs_pointset_exact_power")
            out[f] = v.value
        return out
    raise Error(_lib.ERR_KIND, "no closed form for %r" % (kind,))
