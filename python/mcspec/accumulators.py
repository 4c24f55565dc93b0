"""Accumulators of the measures over sets (discrepancy.h, spacing.h,
integrate.h), the objects behind `mcspec discrepancy`, the distance rows of
`mcspec stats` and `mcspec integrate --family F`, with records (io.h kinds
9 to 11: mcspec.save, load, merge). Each holds its fixed-size C struct in a
64-byte aligned buffer; add(sets) is one library call per set (no loop per
point), done on a copy of the struct that replaces it only when every set
was taken, so a refused add changes nothing."""
import ctypes
import math

import numpy as np

from . import _lib
from ._lib import Buffer, Error, check, fn, struct
from ._points import call_points, each_set, sets_array
from .measures import L2_MEASURES, SPACING, Work, spacing_work, star_work
from .sampling import PATTERNS_2D

DISCREPANCY_MEASURES = L2_MEASURES + ("star",)


class _Welford(ctypes.Structure):
    _fields_ = [("count", ctypes.c_uint64), ("mean", ctypes.c_double), ("m2", ctypes.c_double),
                ("m3", ctypes.c_double), ("m4", ctypes.c_double)]


class _Discrepancy(ctypes.Structure):
    # mcs_discrepancy (discrepancy.h, transparent), size checked against
    # mcs_abi_sizeof(MCS_ABI_DISCREPANCY) before it is read.
    _fields_ = [("dim", ctypes.c_size_t), ("k_min", ctypes.c_size_t), ("k_max", ctypes.c_size_t),
                ("inv_k", _Welford), ("d2", _Welford * len(DISCREPANCY_MEASURES))]


class _Spacing(ctypes.Structure):
    # mcs_spacing (spacing.h)
    _fields_ = [("dim", ctypes.c_size_t), ("k_min", ctypes.c_size_t), ("k_max", ctypes.c_size_t),
                ("stat", _Welford * len(SPACING))]


class _Integrate(ctypes.Structure):
    # mcs_integrate (integrate.h)
    _fields_ = [("family", ctypes.c_int), ("dim", ctypes.c_size_t), ("k_min", ctypes.c_size_t),
                ("k_max", ctypes.c_size_t), ("sq", _Welford), ("exact", _Welford)]


def _view(layout, name, buf):
    if ctypes.sizeof(layout) != _lib.struct_size(name):
        raise Error(_lib.ERR_MISMATCH, "mcs_%s has another layout in this library" % name)
    return layout.from_buffer(buf.array)


def _double(f, *args):
    v = ctypes.c_double()
    st = f(*args, ctypes.addressof(v))
    return v.value if st == 0 else math.nan


class _Accumulator:
    """What the three share: the struct in self._acc, a transactional add,
    merge, copy, count and the K range."""
    _name = None    # abi / io name
    _layout = None  # its ctypes.Structure

    def _fields(self):
        return _view(self._layout, self._name, self._acc)

    def _transaction(self, sets, add_one, dim):
        """add_one(scratch address, k, set, f32) for every set, into a copy
        of the struct; the copy replaces it once all are taken."""
        parts, _ = sets_array(sets, dim)
        scratch = struct(self._name)
        scratch.array[:] = self._acc.array
        for k, one, f32, _ in each_set(parts):
            add_one(scratch.addr, k, one, f32)
        self._acc.array[:] = scratch.array
        return self

    def merge(self, other):
        """self <- self union other (another of the same class, dim and
        family); other unchanged. Error MCS_ERR_MISMATCH otherwise."""
        if type(other) is not type(self):
            raise Error(_lib.ERR_MISMATCH, "merge takes a %s, not a %s"
                        % (type(self).__name__, type(other).__name__))
        check(getattr(fn, self._name + "_merge")(self._acc.addr, other._acc.addr),
              "mcs_%s_merge" % self._name)
        return self

    def copy(self):
        new = type(self).__new__(type(self))
        new.__dict__.update(self.__dict__)
        new._acc = struct(self._name)
        new._acc.array[:] = self._acc.array
        self._copy_extra(new)
        return new

    def _copy_extra(self, new):
        pass

    def reset(self):
        """Empties the sums (the init again, same dim and family); an
        IntegrationError's integrand stream goes on where it was, so sets
        added after a reset get the integrands one add over all would give."""
        f = self._fields()
        args = (f.family, f.dim) if self._name == "integrate" else (f.dim,)
        del f
        check(getattr(fn, self._name + "_init")(self._acc.addr, *args), "mcs_%s_init" % self._name)
        return self

    @property
    def k_range(self):
        """(fewest, most) points in a set added, (0, 0) before any."""
        f = self._fields()
        return f.k_min, f.k_max

    @property
    def dim(self):
        return self._fields().dim


# ---- discrepancy -------------------------------------------------------------

class Discrepancy(_Accumulator):
    """The discrepancy accumulator (mcs_discrepancy), as `mcspec discrepancy`
    fills it: per set the six squared L2 discrepancies and, in 2D with
    star=True (the command's way) for sets of K <= 4096, the square of the
    exact star discrepancy. Read-outs are dicts by the command's row names
    (l2_star ... l2_unanchored, and star when every set has one): mean (over
    the sets of D^2), stderr (NaN below 2 sets), root (sqrt of the mean, as
    the command's root column), exact_random (E[D^2] for independent uniform
    points of the sets' sizes; no star entry)."""
    _name, _layout = "discrepancy", _Discrepancy

    def __init__(self, dim=2, star=True):
        self._acc = struct("discrepancy")
        check(fn.discrepancy_init(self._acc.addr, int(dim)), "mcs_discrepancy_init(dim %d)"
              % int(dim))
        self.star = bool(star)
        self._work = Work()

    def add(self, sets):
        dim = self.dim

        def one(addr, k, pts, f32):
            work, size = None, 0
            if self.star and dim == 2:
                buf = star_work(self._work, min(k, 4096))
                work, size = buf.addr, buf.size
            f = fn.discrepancy_add_f if f32 else fn.discrepancy_add
            call_points(f(addr, k, pts.ctypes.data, work, size), pts, "mcs_discrepancy_add")
        return self._transaction(sets, one, dim)

    def _copy_extra(self, new):
        new._work = Work()

    def count_of(self, measure):
        c = ctypes.c_uint64()
        check(fn.discrepancy_count(self._acc.addr, DISCREPANCY_MEASURES.index(measure),
                                   ctypes.addressof(c)), "mcs_discrepancy_count")
        return c.value

    @property
    def count(self):
        return self.count_of("l2_star")

    def _measures(self):
        n = self.count
        with_star = self.dim == 2 and self.count_of("star") == n
        return L2_MEASURES + (("star",) if with_star else ())

    def _read(self, f, measures=None):
        return {m: _double(f, self._acc.addr, DISCREPANCY_MEASURES.index(m))
                for m in (measures or self._measures())}

    @property
    def mean(self):
        return self._read(fn.discrepancy_mean)

    @property
    def stderr(self):
        return self._read(fn.discrepancy_stderr)

    @property
    def root(self):
        return {m: math.sqrt(max(v, 0.0)) if not math.isnan(v) else math.nan
                for m, v in self.mean.items()}

    @property
    def exact_random(self):
        return self._read(fn.discrepancy_exact_random, L2_MEASURES)

    def __repr__(self):
        return "<mcspec.Discrepancy dim=%d sets=%d>" % (self.dim, self.count)


# ---- spacing -----------------------------------------------------------------

class Spacing(_Accumulator):
    """The spacing accumulator (mcs_spacing), the distance rows of `mcspec
    stats`: per set the minimum and the average minimum toroidal distance
    over the maximal packing distance, in 1D to 8D. Read-outs are dicts by
    statistic (min_distance, avg_min_distance): mean, stderr (NaN below 2
    sets), exact_random (mcs_spacing_exact_random for the sets' one K; NaN
    for mixed K and where theory has none)."""
    _name, _layout = "spacing", _Spacing

    def __init__(self, dim=2):
        self._acc = struct("spacing")
        check(fn.spacing_init(self._acc.addr, int(dim)), "mcs_spacing_init(dim %d)" % int(dim))
        self._work = Work()

    def add(self, sets):
        dim = self.dim

        def one(addr, k, pts, f32):
            buf = spacing_work(self._work, dim, k)
            f = fn.spacing_add_f if f32 else fn.spacing_add
            call_points(f(addr, k, pts.ctypes.data, buf.addr, buf.size), pts, "mcs_spacing_add")
        return self._transaction(sets, one, dim)

    def _copy_extra(self, new):
        new._work = Work()

    @property
    def count(self):
        c = ctypes.c_uint64()
        check(fn.spacing_count(self._acc.addr, ctypes.addressof(c)), "mcs_spacing_count")
        return c.value

    def _read(self, f):
        return {s: _double(f, self._acc.addr, i) for i, s in enumerate(SPACING)}

    @property
    def mean(self):
        return self._read(fn.spacing_mean)

    @property
    def stderr(self):
        return self._read(fn.spacing_stderr)

    @property
    def exact_random(self):
        k0, k1 = self.k_range
        out = {}
        for i, s in enumerate(SPACING):
            out[s] = _double(fn.spacing_exact_random, i, self.dim, k0) if k0 == k1 and k0 else \
                math.nan
        return out

    def __repr__(self):
        return "<mcspec.Spacing dim=%d sets=%d>" % (self.dim, self.count)


# ---- integration error -------------------------------------------------------

def _family_index(family):
    names = [_lib.cstr(fn.integrand_family_str(i)) for i in range(7)]
    if family not in names:
        raise Error(_lib.ERR_KIND, "unknown family %r (%s)" % (family, ", ".join(names)))
    return names.index(family)


class _Pattern2d(ctypes.Structure):
    _fields_ = [("kind", ctypes.c_int), ("k", ctypes.c_size_t),
                ("strata_x", ctypes.c_size_t), ("strata_y", ctypes.c_size_t)]


class IntegrationError(_Accumulator):
    """The integration error accumulator of one family (mcs_integrate), as
    `mcspec integrate --family F` fills it: for every set added, `integrands`
    fresh integrands of the family drawn from the object's PCG32 (seed,
    1000 + family index, the command's streams) and the set's mean squared
    error over them. exact: None, "random" or "jittered" (2D: the most
    nearly square grid of K cells; 1D: the stratified pattern), what the sets
    are, for the exact column; it may be changed between adds. Read-outs:
    mse (= mean), mse_stderr (= stderr, NaN below 2 sets), exact (NaN
    without a reference), count, k_range. A loaded object draws from (seed
    1, 1000 + family) and has exact None until told otherwise."""
    _name, _layout = "integrate", _Integrate

    def __init__(self, family, dim=2, integrands=16, seed=1, exact=None):
        f = _family_index(family)
        self._acc = struct("integrate")
        check(fn.integrate_init(self._acc.addr, f, int(dim)), "mcs_integrate_init(%s, dim %d)"
              % (family, int(dim)))
        self._setup(integrands, seed, exact)

    def _setup(self, integrands, seed, exact):
        m = int(integrands)
        if m < 1:
            raise Error(_lib.ERR_K_RANGE, "integrands must be at least 1, not %d" % m)
        if exact not in (None, "random", "jittered"):
            raise Error(_lib.ERR_KIND, "exact is None, 'random' or 'jittered', not %r" % (exact,))
        self.integrands, self.exact_kind = m, exact
        self._rng = struct("rng")
        check(fn.rng_seed(self._rng.addr, int(seed) & (2**64 - 1), 1000 + self._fields().family),
              "mcs_rng_seed")

    @property
    def family(self):
        return _lib.cstr(fn.integrand_family_str(self._fields().family))

    def _strata(self, k):
        if self.exact_kind != "jittered" or self.dim == 1:
            return k, 1
        grid = struct("pattern2d")
        if ctypes.sizeof(_Pattern2d) != _lib.struct_size("pattern2d"):
            raise Error(_lib.ERR_MISMATCH, "mcs_pattern2d has another layout in this library")
        if fn.pattern2d_init(grid.addr, PATTERNS_2D["jittered"], k, 0, 0) != 0:
            return k, 1  # no grid of k cells: the add refuses it
        p = _Pattern2d.from_buffer(grid.array)
        return p.strata_x, p.strata_y

    def add(self, sets):
        return self._add(sets)

    def _add(self, sets, keep=None):
        """add(sets), and with keep a list, each set's integrands (a Buffer
        of `integrands` mcs_integrand) appended to it, for a prediction."""
        ref = {None: 0, "random": 1, "jittered": 2}[self.exact_kind]
        fam, dim, m = self._fields().family, self.dim, self.integrands
        isz = _lib.struct_size("integrand")
        rng = struct("rng")
        rng.array[:] = self._rng.array

        def one(addr, k, pts, f32):
            pts = np.ascontiguousarray(pts, dtype=np.float64)  # integrate_add takes doubles
            fs = Buffer(isz * m)
            for i in range(m):
                check(fn.integrand_draw(fs.addr + i * isz, fam, dim, rng.addr),
                      "mcs_integrand_draw")
            sx, sy = self._strata(k)
            call_points(fn.integrate_add(addr, m, fs.addr, k, pts.ctypes.data, ref, sx, sy), pts,
                        "mcs_integrate_add")
            drawn.append(fs)
        drawn = []
        self._transaction(sets, one, dim)
        self._rng.array[:] = rng.array
        if keep is not None:
            keep.extend(drawn)
        return self

    def _share_stream(self, rng):
        """Draws from the caller's mcs_rng Buffer rng from now on (each add
        moves it on), so objects of one family over several K see the one
        stream of the command's run over all its sets."""
        self._rng = rng
        return self

    def _copy_extra(self, new):
        new._rng = struct("rng")
        new._rng.array[:] = self._rng.array

    @property
    def count(self):
        c = ctypes.c_uint64()
        check(fn.integrate_count(self._acc.addr, ctypes.addressof(c)), "mcs_integrate_count")
        return c.value

    @property
    def mse(self):
        return _double(fn.integrate_mse, self._acc.addr)

    @property
    def mse_stderr(self):
        return _double(fn.integrate_mse_stderr, self._acc.addr)

    @property
    def exact(self):
        return _double(fn.integrate_exact, self._acc.addr)

    mean, stderr = mse, mse_stderr

    def __repr__(self):
        return "<mcspec.IntegrationError %s dim=%d sets=%d>" % (self.family, self.dim, self.count)


# ---- records -----------------------------------------------------------------

RECORD_CLASSES = {"integrate": IntegrationError, "discrepancy": Discrepancy, "spacing": Spacing}


def load_record(raw):
    """The accumulator in a record of kind 9, 10 or 11 (raw: uint8 array), or
    None for another kind (each loader refuses another kind with
    MCS_ERR_KIND before it writes anything)."""
    for name, cls in RECORD_CLASSES.items():
        acc = struct(name)
        st = getattr(fn, "io_load_" + name)(acc.addr, raw.size, raw.ctypes.data)
        if st == _lib.ERR_KIND:
            continue
        check(st, "mcs_io_load_" + name)
        obj = cls.__new__(cls)
        obj._acc = acc
        if cls is IntegrationError:
            obj._setup(16, 1, None)
        else:
            obj._work = Work()
            if cls is Discrepancy:
                obj.star = True
        return obj
    return None
