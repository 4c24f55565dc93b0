"""Named patterns and samplers as array generators (pattern.h, pattern2d.h,
sampler.h), with the names `mcspec pattern` takes."""
import ctypes

import numpy as np

from . import _lib
from ._lib import Error, check, fn, struct

# mcs_pattern_kind, mcs_pattern2d_kind, mcs_sampler_kind, mcs_bluenoise_kind:
# the names `mcspec sample` takes (cli/cmd_sample.c's kind table).
PATTERNS_1D = {"random": 0, "stratified": 1, "homogenized": 2, "uniform": 3, "jitter": 4}
PATTERNS_2D = {"random": 0, "jittered": 1, "grid": 2, "shifted-grid": 3, "n-rooks": 4,
               "multi-jittered": 5, "cmj": 6}
# sobol-owen is MCS_SAMPLER_SOBOL_ND, the command's: in 1D and 2D the same
# draws as MCS_SAMPLER_SOBOL bit for bit (sampler.h).
SAMPLERS = {"van-der-corput": 0, "halton": 1, "hammersley": 2, "kronecker": 4, "sobol-owen": 5,
            "halton-permuted": 6, "halton-owen": 8, "lattice": 9, "padded": 7}
BLUENOISE = {"dart-throwing": 0, "poisson-disk": 1, "lloyd": 2, "pmj02": 3, "pmj02bn": 4}
MAX_DIM = 64  # MCS_SAMPLER_MAX_DIM
# The 2D kinds a padded sampler's pairs may be (mcs_sampler_init_padded).
PADS = {"halton": 1, "hammersley": 2, "sobol-owen": 3, "kronecker": 4}

DEFAULT_BINS = 4096  # MCS_MAX_N, mcspec sample's default --n


def kinds(dim):
    """The kinds sample() draws in dimension dim, in the command's order."""
    dim = int(dim)
    if dim < 1 or dim > MAX_DIM:
        return []
    names = ["random"] + [p for p in PATTERNS_1D if p != "random" and dim == 1]
    names += [p for p in PATTERNS_2D if p != "random" and dim == 2]
    names += [s for s, v in SAMPLERS.items() if fn.sampler_has_dim(v, dim)]
    names += [b for b, v in BLUENOISE.items() if fn.bluenoise_has_dim(v, dim)]
    return names


def _rng(seed, stream=0):
    rng = struct("rng")
    check(fn.rng_seed(rng.addr, int(seed) & (2**64 - 1), int(stream)), "mcs_rng_seed")
    return rng


def _random_nd(rng, k, dim, sets, out):
    """k dim uniform doubles per set in the generator's order, as the
    command's random kind above 2D (one mcs_rng_double per coordinate):
    the 2D random pattern draws its 2 K' doubles in that same order
    (pattern2d.c, point j * m + i), so K' = floor(k dim / 2) points of it
    and one double more when k dim is odd give them in one call a set."""
    n = k * dim
    half = n // 2
    flat = out.reshape(sets, n)
    pat = None
    if half > 0:
        pat = struct("pattern2d")
        check(fn.pattern2d_init(pat.addr, PATTERNS_2D["random"], half, 0, 0), "mcs_pattern2d_init")
    for t in range(sets):
        if pat is not None:
            check(fn.pattern2d_draw(pat.addr, rng.addr, half, flat[t].ctypes.data),
                  "mcs_pattern2d_draw")
        if n % 2:
            check(fn.rng_double(rng.addr, flat[t].ctypes.data + 8 * (n - 1)), "mcs_rng_double")


class BluenoiseParams(ctypes.Structure):
    """mcs_bluenoise_params (bluenoise.h, transparent); a field at 0 takes
    the kind's default. Its size is checked against mcs_abi_sizeof."""
    _fields_ = [("radius", ctypes.c_double), ("attempts", ctypes.c_uint32),
                ("iterations", ctypes.c_uint32), ("resolution", ctypes.c_uint32),
                ("candidates", ctypes.c_uint32)]


def _bluenoise_params(params):
    if params is None:
        return None
    if ctypes.sizeof(BluenoiseParams) != _lib.struct_size("bluenoise_params"):
        raise Error(_lib.ERR_MISMATCH, "mcs_bluenoise_params has another layout in this library")
    unknown = set(params) - {f[0] for f in BluenoiseParams._fields_}
    if unknown:
        raise Error(_lib.ERR_DOMAIN, "unknown blue-noise parameter(s) %s (radius, attempts, "
                    "iterations, resolution, candidates)" % ", ".join(sorted(unknown)))
    return BluenoiseParams(**params)


def _init_sampler(obj, kind, dim, k, pad, generator):
    if pad is not None:
        if kind != "padded":
            raise Error(_lib.ERR_KIND, "pad is for the padded kind, not %r" % (kind,))
        check(fn.sampler_init_padded(obj.addr, PADS.get(pad, -1), dim, k),
              "mcs_sampler_init_padded(pad %s, dim %d, K = %d)" % (pad, dim, k))
    elif generator is not None:
        if kind != "lattice":
            raise Error(_lib.ERR_KIND, "generator is for the lattice kind, not %r" % (kind,))
        check(fn.sampler_init_lattice(obj.addr, dim, k, int(generator)),
              "mcs_sampler_init_lattice(dim %d, K = %d, g = %d)" % (dim, k, int(generator)))
    else:
        check(fn.sampler_init(obj.addr, SAMPLERS[kind], dim, k),
              "mcs_sampler_init(%s, dim %d, K = %d)" % (kind, dim, k))


def lattice_generator(k, dim):
    """Korobov's generator g that the lattice kind picks for k points in dim
    dimensions (mcs_sampler_lattice_generator; 0 when out of range)."""
    return int(fn.sampler_lattice_generator(int(k), int(dim)))


def sample(kind, dim, k, sets=1, seed=1, n=None, importance=None, strata=(0, 0), pad=None,
           generator=None, params=None, stream=0):
    """sets trials of k points of `kind` in dim dimensions, as a float64
    array (sets, k, dim), drawn from PCG32 seeded (seed, 0) in order: the
    sets `mcspec sample KIND --dim D --k K --sets T --seed S` prints, bit for
    bit (and `mcspec pattern KIND --seed S`'s trials).

    Kinds (kinds(dim) lists those of a dimension): random (1..64; 1D the
    pattern over n bins, 2D the 2D pattern, more every coordinate uniform);
    1D patterns stratified, homogenized, uniform, jitter over n bins (default
    4096; importance: an Importance object over the n bins); 2D patterns
    jittered, grid, shifted-grid, n-rooks, multi-jittered, cmj (strata (m, n)
    with m n = k, (0, 0) the most nearly square); samplers van-der-corput
    (1), halton, hammersley (2), kronecker (1, 2), sobol-owen,
    halton-permuted, halton-owen, lattice (1..64), padded (2..64); blue noise
    dart-throwing, poisson-disk (1..3), lloyd, pmj02, pmj02bn (2), at their
    default parameters, in work memory sized by mcs_bluenoise_work_size.
    Beyond the command: pad (padded: the 2D kind of each pair, halton,
    hammersley, sobol-owen or kronecker; mcs_sampler_init_padded), generator
    (lattice: Korobov's g; mcs_sampler_init_lattice), params (blue noise: a
    dict of radius, attempts, iterations, resolution, candidates; 0 or absent
    the default; mcs_bluenoise_params), stream (PCG32's initseq, 0 as the
    command; mcspec integrate KIND draws its i-th K from stream 1 + i)."""
    k, sets, dim = int(k), int(sets), int(dim)
    if sets < 1:
        raise Error(_lib.ERR_K_RANGE, "sets must be at least 1, not %d" % sets)
    if k < 1:
        raise Error(_lib.ERR_K_RANGE, "k must be at least 1, not %d" % k)
    if kind not in kinds(dim):
        raise Error(_lib.ERR_KIND, "unknown %dD kind %r (%s)" % (dim, kind, ", ".join(kinds(dim))))
    out = np.empty((sets, k, dim), dtype=np.float64)
    rng = _rng(seed, stream)
    if (pad is not None or generator is not None) and kind not in SAMPLERS or \
            params is not None and kind not in BLUENOISE:
        raise Error(_lib.ERR_KIND, "pad, generator and params are for padded, lattice and the "
                    "blue-noise kinds, not %r" % (kind,))
    if kind == "random" and dim > 2:
        _random_nd(rng, k, dim, sets, out)
        return out
    if kind in SAMPLERS:
        obj = struct("sampler")
        _init_sampler(obj, kind, dim, k, pad, generator)
        draw = lambda t: fn.sampler_draw(obj.addr, rng.addr, k, out[t].ctypes.data)
    elif kind in BLUENOISE:
        size = ctypes.c_size_t(0)
        check(fn.bluenoise_work_size(BLUENOISE[kind], dim, k, ctypes.addressof(size)),
              "mcs_bluenoise_work_size(%s, dim %d, K = %d)" % (kind, dim, k))
        work = _lib.Buffer(max(size.value, 1))
        bp = _bluenoise_params(params)
        bpa = None if bp is None else ctypes.addressof(bp)
        draw = lambda t: fn.bluenoise_draw(BLUENOISE[kind], dim, k, bpa, rng.addr, work.addr,
                                           work.size, out[t].ctypes.data)
    elif dim == 2:
        obj = struct("pattern2d")
        check(fn.pattern2d_init(obj.addr, PATTERNS_2D[kind], k, int(strata[0]), int(strata[1])),
              "mcs_pattern2d_init(%s, K = %d)" % (kind, k))
        draw = lambda t: fn.pattern2d_draw(obj.addr, rng.addr, k, out[t].ctypes.data)
    else:
        from .binned import Pattern
        pat = Pattern(kind, DEFAULT_BINS if n is None else n, k, importance)
        bins = np.empty(k, dtype=np.uintp)
        w = np.empty(k)
        draw = lambda t: fn.pattern_draw(pat._obj.addr, rng.addr, k, bins.ctypes.data,
                                         w.ctypes.data, out[t].ctypes.data)
    # One call per trial: the library draws a trial at a time (no batch entry).
    for t in range(sets):
        st = draw(t)
        if st == _lib.ERR_EMPTY:
            raise Error(st, "%s could not place %d points at its default radius (its set "
                        "saturated): ask for fewer points" % (kind, k))
        check(st, "draw of %s" % kind)
    return out


def base_points(kind, dim, k, pad=None, generator=None):
    """The sampler's K points without randomisation (mcs_sampler_base_points)."""
    obj = struct("sampler")
    if kind not in SAMPLERS:
        raise Error(_lib.ERR_KIND, "unknown sampler %r (%s)" % (kind, ", ".join(SAMPLERS)))
    _init_sampler(obj, kind, int(dim), int(k), pad, generator)
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
