"""Point-set periodograms in 1D and 2D (pointset.h, pointset2d.h): the
accumulators over caller memory, and periodogram() and anisotropy() over
a batch of sets. Each batch of T sets with one K is one library call."""
import collections
import ctypes

import numpy as np

from . import _lib
from ._lib import Buffer, Error, addr, check, fn, struct
from ._points import sets_array, where_bad

Estimate = collections.namedtuple("Estimate", "mean stderr")


class PointSet:
    """The periodogram of point sets, without binning, at |f| <= freq (per
    axis in 2D), accumulated over sets (mcs_pointset / mcs_pointset2d over
    their own 64-byte aligned buffers).

    add(sets) takes an array (T, K, d), one set (K, d), or a list of (K, d)
    arrays; T sets of one K go to the library in one call
    (mcs_pointset*_add_sets). Read-outs are whole arrays: power and
    power_stderr indexed [f] in 1D and [fy + F, fx + F] in 2D; radial,
    radial_stderr and anisotropy (dB, NaN where psa's is undefined) indexed
    by radius 0..F in 2D."""

    def __init__(self, freq, dim=2, wrap=False, _header=None, _mem=None):
        if dim not in (1, 2):
            raise Error(_lib.ERR_DOMAIN, "dim must be 1 or 2, not %r" % (dim,))
        self.dim = dim
        self._p = "pointset" if dim == 1 else "pointset2d"
        self._f = getattr(fn, self._p + "_add_sets"), getattr(fn, self._p + "_add_sets_f")
        if _header is not None:
            self._hdr, self._mem = _header, _mem
            self.freq = int(freq)
            return
        freq = int(freq)
        size = ctypes.c_size_t(0)
        check(getattr(fn, self._p + "_size")(freq, 0, ctypes.addressof(size)),
              "mcs_%s_size(F = %d)" % (self._p, freq))
        self._hdr = struct(self._p)
        self._mem = Buffer(size.value)
        check(getattr(fn, self._p + "_init")(self._hdr.addr, freq, 0, self._mem.addr,
                                              self._mem.size), "mcs_%s_init" % self._p)
        self.freq = freq
        self.wrap = bool(wrap)
        if wrap:
            check(getattr(fn, self._p + "_set_wrap")(self._hdr.addr, 1), "set_wrap")

    wrap = False

    def add(self, sets):
        """Adds every set of sets as one trial each; returns self. Nothing is
        added when any point of any set is refused (within one array)."""
        parts, _ = sets_array(sets, self.dim)
        if len(parts) > 1:  # sets of several K: several calls, so every point is checked first
            top = 1.0 if self.wrap else np.nextafter(1.0, 0.0)
            for arr in parts:
                if not ((arr >= 0) & (arr <= top)).all():
                    raise Error(_lib.ERR_POINT_RANGE, where_bad(arr, self.wrap))
        for arr in parts:
            f = self._f[1] if arr.dtype == np.float32 else self._f[0]
            st = f(self._hdr.addr, arr.shape[0], arr.shape[1], arr.ctypes.data)
            if st == _lib.ERR_POINT_RANGE:
                raise Error(st, where_bad(arr, self.wrap))
            check(st, "mcs_%s_add_sets" % self._p)
        return self

    def merge(self, other):
        """self <- self union other (same F and dim); returns self."""
        if not isinstance(other, PointSet) or other.dim != self.dim:
            raise Error(_lib.ERR_MISMATCH, "merge takes a PointSet of the same dim")
        check(getattr(fn, self._p + "_merge")(self._hdr.addr, other._hdr.addr),
              "mcs_%s_merge" % self._p)
        return self

    def copy(self):
        """An independent copy over its own buffer."""
        dup = PointSet(self.freq, self.dim, _header=struct(self._p), _mem=Buffer(self._mem.size))
        check(getattr(fn, self._p + "_copy")(dup._hdr.addr, dup._mem.addr, dup._mem.size,
                                              self._hdr.addr), "mcs_%s_copy" % self._p)
        dup.wrap = self.wrap
        return dup

    @property
    def count(self):
        c = ctypes.c_uint64(0)
        check(getattr(fn, self._p + "_count")(self._hdr.addr, ctypes.addressof(c)), "count")
        return c.value

    def _read(self, stderr):
        if self.dim == 1:
            n = self.freq + 1
            p = np.empty(n)
            s = np.empty(n) if stderr else None
            check(fn.pointset_read_all(self._hdr.addr, n, p.ctypes.data, addr(s)),
                  "mcs_pointset_read_all")
        else:
            side = 2 * self.freq + 1
            p = np.empty((side, side))
            s = np.empty((side, side)) if stderr else None
            check(fn.pointset2d_read_all(self._hdr.addr, side, p.ctypes.data, addr(s)),
                  "mcs_pointset2d_read_all")
        return p, s

    @property
    def power(self):
        """<P(f)>: [f] in 1D, [fy + F, fx + F] in 2D."""
        return self._read(False)[0]

    @property
    def power_stderr(self):
        """The standard error of power (two sets or more)."""
        return self._read(True)[1]

    def estimate(self):
        """(power, power_stderr) from one read-out."""
        return Estimate(*self._read(True))

    def _radial(self, want):
        if self.dim != 2:
            raise Error(_lib.ERR_DOMAIN, "radial read-outs are for dim 2")
        n = self.freq + 1
        arrs = [np.empty(n) if w else None for w in want]
        check(fn.pointset2d_radial_all(self._hdr.addr, n, *[addr(a) for a in arrs]),
              "mcs_pointset2d_radial_all")
        return arrs

    @property
    def radial(self):
        """The radial average per annulus r <= |f| < r + 1, r = 0..F."""
        return self._radial((1, 0, 0))[0]

    @property
    def radial_stderr(self):
        return self._radial((0, 1, 0))[1]

    @property
    def anisotropy(self):
        """psa's anisotropy per annulus in dB (NaN at r = 0 and where undefined)."""
        return self._radial((0, 0, 1))[2]

    def radial_estimate(self):
        """(radial, radial_stderr) from one read-out."""
        r, s, _ = self._radial((1, 1, 0))
        return Estimate(r, s)

    def save(self):
        from .records import save
        return save(self)

    def __repr__(self):
        return "<mcspec.PointSet dim=%d F=%d sets=%d>" % (self.dim, self.freq, self.count)


def periodogram(sets, freq, radial=False, wrap=False):
    """The mean periodogram of sets and its standard error, as an Estimate
    (mean, stderr): 1D arrays [f], f = 0..F; 2D arrays [fy + F, fx + F] for
    |fx|, |fy| <= F, or with radial=True arrays [r] per annulus r = 0..F.
    sets: (T, K, d) float64 or float32 (d = 1 or 2; (T, K) is 1D), or a
    list of (K, d) arrays. The standard error needs T >= 2."""
    parts, d = sets_array(sets)
    acc = PointSet(freq, d, wrap=wrap).add(parts[0] if len(parts) == 1 else
                                           [p[0] for p in parts])
    if radial:
        if d != 2:
            raise Error(_lib.ERR_DOMAIN, "radial=True is for 2D sets")
        return acc.radial_estimate() if acc.count >= 2 else Estimate(acc.radial, None)
    return acc.estimate() if acc.count >= 2 else Estimate(acc.power, None)


def anisotropy(sets, freq, wrap=False):
    """psa's anisotropy of the mean periodogram of 2D sets per annulus
    r = 0..F, in dB (NaN at r = 0 and where it is undefined)."""
    parts, d = sets_array(sets, 2)
    acc = PointSet(freq, 2, wrap=wrap).add(parts[0] if len(parts) == 1 else
                                           [p[0] for p in parts])
    return acc.anisotropy


def wave_vectors(freq):
    """(fx, fy): integer arrays of shape (2F + 1, 2F + 1) giving the wave
    vector of each entry of a 2D power array."""
    f = np.arange(-freq, freq + 1)
    fy, fx = np.meshgrid(f, f, indexing="ij")
    return fx, fy
